// report.md: the bench's rows per scene, the reference summaries and the temporal rows.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "bench/BenchResult.h"
#include "output/AtomicFile.h"

namespace aokit {

namespace {
std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
}  // namespace

void writeBenchReport(const std::string& path, const std::vector<BenchRow>& rows,
                      const std::vector<ReferenceSummary>& refs, const std::string& chartFile,
                      const std::vector<SequenceRow>& sequence) {
  writeStreamAtomically(path, [&](std::ostream& out) {
    out << "# aokit bench\n\n"
        << "Each row is compared with the Embree reference of the quantity it estimates (occlusion, or 1 - W for "
           "ambient transfer, with the falloff it used) on the pixels the rasterizer covered. Times: each row is "
           "timed as interleaved pairs of base and method frames (glFinish after each); `ao ms` is the median of the "
           "paired differences, [q1, q3] its quartiles, never clamped; `stages` (with --profile) are "
           "wall-clock ms per stage, each ended by glFinish, the base frame's own drawing subtracted from the first "
           "(median per stage; their sum in brackets, to set against ao ms). llvmpipe on CPU cores: compare ratios within one run, not absolute times.\n\n";
    if (!chartFile.empty()) out << "![error against AO time](" << chartFile << ")\n\n";
    out << "## Reference\n\n"
        << "Throughput on identical rays with the same Embree calls on both sides (alternating runs, best of three): "
           "the reference against Embree alone. Noise floor: the formula's RMS standard error, and the measured one "
           "(RMS difference of two references with different seeds over every k-th row, divided by sqrt 2).\n\n"
        << "| scene | rays/pixel | time s | rays/s | same rays: reference | Embree alone | ratio | SE (formula) | "
           "noise (measured) | BVH s | BVH MiB | triangles |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : refs) {
      out << "| " << r.scene << " | " << r.samples << " | " << fmt("%.1f", r.seconds) << " | "
          << fmt("%.3g", r.raysPerSecond) << " | " << fmt("%.3g", r.sameRaysReference) << " | "
          << fmt("%.3g", r.sameRaysEmbree) << " | "
          << (r.sameRaysEmbree > 0 ? fmt("%.2f", r.sameRaysReference / r.sameRaysEmbree) : "-") << " | "
          << fmt("%.4f", r.stdErr) << " | " << fmt("%.4f", r.noise) << " (rows 1/" << r.noiseRowStride << ") | "
          << fmt("%.2f", r.bvhSeconds) << " | " << fmt("%.1f", r.bvhBytes / 1048576.0) << " | " << r.triangles
          << " |\n";
    }
    std::map<std::string, std::vector<const BenchRow*>> byScene;
    std::vector<std::string> order;
    for (const auto& r : rows) {
      if (!byScene.count(r.scene)) order.push_back(r.scene);
      byScene[r.scene].push_back(&r);
    }
    for (const auto& s : order) {
      const auto& first = *byScene[s].front();
      out << "\n## " << s << " (" << first.width << "x" << first.height << ")\n\n"
          << "| method | setting | quantity | base ms | frame ms | ao ms [q1, q3] | stages (ms) | prepare ms | RMSE | "
             "MAE | p99 | SSIM | memory MiB |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const BenchRow* r : byScene[s])
        out << "| " << r->method << " | " << (r->setting.empty() ? "-" : r->setting) << " | " << r->quantity
            << (r->falloff.empty() ? "" : " (" + r->falloff + ")") << " | " << fmt("%.1f", r->baseMs) << " | "
            << fmt("%.1f", r->frameMs) << " | " << fmt("%.2f", r->aoMs) << " [" << fmt("%.2f", r->aoQ1Ms) << ", "
            << fmt("%.2f", r->aoQ3Ms) << "] | " << (r->stages.empty() ? "-" : r->stages + " (" + fmt("%.2f", r->stagesMs) + ")") << " | "
            << fmt("%.0f", r->prepareMs) << " | " << fmt("%.4f", r->rmse) << " | " << fmt("%.4f", r->mae) << " | "
            << fmt("%.3f", r->p99) << " | " << fmt("%.3f", r->ssim) << " | "
            << fmt("%.2f", r->memoryBytes / 1048576.0) << " |\n";
    }
    bool still = false;
    for (const auto& r : rows) still = still || r.stillFrames > 0;
    if (still) {
      out << "\n## Still frames\n\nEach row's method again with accumulate=N on the same still view: RMSE "
             "after 1, 4, 16 and N frames, bias (the mean of N frames against the reference) and noise (frame 1 "
             "against that mean, RMS).\n\n| scene | method | setting | N | RMSE 1 | RMSE 4 | RMSE 16 | RMSE N = bias | "
             "noise |\n|---|---|---|---|---|---|---|---|---|\n";
      for (const auto& r : rows)
        if (r.stillFrames > 0)
          out << "| " << r.scene << " | " << r.method << " | " << (r.setting.empty() ? "-" : r.setting) << " | "
              << r.stillFrames << " | " << fmt("%.4f", r.rmse) << " | " << fmt("%.4f", r.rmseF4) << " | "
              << fmt("%.4f", r.rmseF16) << " | " << fmt("%.4f", r.stillBias) << " | " << fmt("%.4f", r.stillNoise)
              << " |\n";
    }
    if (!sequence.empty()) {
      out << "\n## Temporal stability (" << sequence.front().scene << ", " << sequence.front().frames << " frames)\n\n"
          << "Mean frame-to-frame change of AO at surface points seen in both frames (found by reprojecting "
             "the G-buffer), with the camera held and moving along the scene's path; the reference's own change "
             "beside it (same seed every frame: with a held camera it is the true change, with a moving one it "
             "also holds its noise).\n\n| camera | method | setting | change | reference change | mean RMSE | "
             "points/pair |\n|---|---|---|---|---|---|---|\n";
      for (const auto& r : sequence)
        out << "| " << r.camera << " | " << r.method << " | " << (r.setting.empty() ? "-" : r.setting) << " | "
            << fmt("%.4f", r.temporalChange) << " | " << fmt("%.4f", r.refTemporalChange) << " | "
            << fmt("%.4f", r.meanRmse) << " | " << r.matchedPixels << " |\n";
    }
  });
}

}  // namespace aokit
