#include "bench/BenchResult.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "output/AtomicFile.h"

namespace aokit {

const std::vector<std::string>& benchCsvColumns() {
  static const std::vector<std::string> cols = {
      "scene",    "method",     "setting",  "quantity", "falloff", "width",        "height",
      "base_ms",  "frame_ms",   "ao_ms",    "ao_ms_q1", "ao_ms_q3", "stages",      "prepare_ms",
      "rmse",     "mae",        "p99",      "ssim",     "memory_bytes", "pixels",  "ref_samples",
      "ref_stderr", "ref_noise", "still_frames", "rmse_f4", "rmse_f16", "bias", "noise"};
  return cols;
}

namespace {
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
// Errors of a row that is not compared (NaN) stay empty.
std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
}  // namespace

std::string benchCsvLine(const BenchRow& r) {
  return csvField(r.scene) + ',' + csvField(r.method) + ',' + csvField(r.setting) + ',' + r.quantity + ',' +
         r.falloff + ',' + std::to_string(r.width) + ',' + std::to_string(r.height) + ',' + fmt("%.3f", r.baseMs) +
         ',' + fmt("%.3f", r.frameMs) + ',' + fmt("%.3f", r.aoMs) + ',' + fmt("%.3f", r.aoQ1Ms) + ',' +
         fmt("%.3f", r.aoQ3Ms) + ',' + csvField(r.stages) + ',' + fmt("%.1f", r.prepareMs) + ',' +
         fmt("%.5f", r.rmse) + ',' + fmt("%.5f", r.mae) + ',' + fmt("%.5f", r.p99) + ',' + fmt("%.5f", r.ssim) + ',' +
         std::to_string(r.memoryBytes) + ',' + std::to_string(r.pixels) + ',' + std::to_string(r.refSamples) + ',' +
         fmt("%.5f", r.refStdErr) + ',' + fmt("%.5f", r.refNoise) + ',' + std::to_string(r.stillFrames) + ',' +
         fmt("%.5f", r.rmseF4) + ',' + fmt("%.5f", r.rmseF16) + ',' + fmt("%.5f", r.stillBias) + ',' +
         fmt("%.5f", r.stillNoise);
}

namespace {
std::string header() {
  std::string h;
  for (const auto& c : benchCsvColumns()) h += (h.empty() ? "" : ",") + c;
  return h;
}
}  // namespace

void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows) {
  writeStreamAtomically(path, [&](std::ostream& out) {
    out << header() << "\n";
    for (const auto& r : rows) out << benchCsvLine(r) << "\n";
  });
}

BenchCsvStream::BenchCsvStream(const std::string& path) : path_(path), out_(path, std::ios::trunc) {
  out_ << header() << "\n" << std::flush;
  if (!out_) throw std::runtime_error(path + ": cannot write");
}

void BenchCsvStream::append(const BenchRow& row) {
  out_ << benchCsvLine(row) + "\n" << std::flush;  // one write per line
  if (!out_) throw std::runtime_error(path_ + ": cannot write");
}

}  // namespace aokit
