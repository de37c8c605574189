#include "bench/BenchResult.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "output/AtomicFile.h"

namespace aokit {

const std::vector<std::string>& benchCsvColumns() {
  static const std::vector<std::string> cols = {"scene", "method", "setting", "width", "height", "base_ms",
                                                "frame_ms", "ao_ms", "rmse", "mae", "p99", "ssim",
                                                "memory_bytes", "pixels", "ref_samples", "ref_stderr"};
  return cols;
}

namespace {
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
}  // namespace

void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    const auto& cols = benchCsvColumns();
    for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
    out << "\n";
    for (const auto& r : rows) {
      out << csvField(r.scene) << ',' << csvField(r.method) << ',' << csvField(r.setting) << ',' << r.width << ','
          << r.height << ',' << fmt("%.3f", r.baseMs) << ',' << fmt("%.3f", r.frameMs) << ',' << fmt("%.3f", r.aoMs)
          << ',' << fmt("%.5f", r.rmse) << ',' << fmt("%.5f", r.mae) << ',' << fmt("%.5f", r.p99) << ','
          << fmt("%.5f", r.ssim) << ',' << r.memoryBytes << ',' << r.pixels << ',' << r.refSamples << ','
          << fmt("%.5f", r.refStdErr) << "\n";
    }
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

void writeBenchReport(const std::string& path, const std::vector<BenchRow>& rows,
                      const std::vector<ReferenceSummary>& refs, const std::string& chartFile,
                      const std::vector<SequenceRow>& sequence) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "# aokit bench\n\n"
        << "AO is occlusion in [0,1] (1 = fully occluded), compared with the Embree reference on the pixels the "
           "rasterizer covered. Times are medians over repeated frames after warm-up (glFinish), measured in the "
           "same run; `ao ms` = frame - base. llvmpipe on CPU cores: compare ratios, not absolute times.\n\n";
    if (!chartFile.empty()) out << "![error against AO time](" << chartFile << ")\n\n";
    out << "## Reference\n\n| scene | rays/pixel | time s | rays/s | raw rtcOccluded1 rays/s | ratio | SE (RMS) | BVH s | "
           "BVH MiB | triangles |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : refs) {
      out << "| " << r.scene << " | " << r.samples << " | " << fmt("%.1f", r.seconds) << " | "
          << fmt("%.3g", r.raysPerSecond) << " | " << fmt("%.3g", r.rawRaysPerSecond) << " | "
          << (r.rawRaysPerSecond > 0 ? fmt("%.2f", r.raysPerSecond / r.rawRaysPerSecond) : "-") << " | "
          << fmt("%.4f", r.stdErr) << " | " << fmt("%.2f", r.bvhSeconds) << " | "
          << fmt("%.1f", r.bvhBytes / 1048576.0) << " | " << r.triangles << " |\n";
    }
    std::map<std::string, std::vector<const BenchRow*>> byScene;
    std::vector<std::string> order;
    for (const auto& r : rows) {
      if (!byScene.count(r.scene)) order.push_back(r.scene);
      byScene[r.scene].push_back(&r);
    }
    for (const auto& s : order) {
      const auto& first = *byScene[s].front();
      out << "\n## " << s << " (" << first.width << "x" << first.height << ", base frame "
          << fmt("%.1f", first.baseMs) << " ms)\n\n"
          << "| method | setting | frame ms | ao ms | RMSE | MAE | p99 | SSIM | memory MiB |\n"
          << "|---|---|---|---|---|---|---|---|---|\n";
      for (const BenchRow* r : byScene[s])
        out << "| " << r->method << " | " << (r->setting.empty() ? "-" : r->setting) << " | "
            << fmt("%.1f", r->frameMs) << " | " << fmt("%.1f", r->aoMs) << " | " << fmt("%.4f", r->rmse) << " | "
            << fmt("%.4f", r->mae) << " | " << fmt("%.3f", r->p99) << " | " << fmt("%.3f", r->ssim) << " | "
            << fmt("%.2f", r->memoryBytes / 1048576.0) << " |\n";
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
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

}  // namespace aokit
