#pragma once
// One row of results.csv: a method at one setting on one scene, against the reference of the
// quantity it estimates; and the per-scene reference summary.
#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace aokit {

struct BenchRow {
  std::string scene, method, setting;
  std::string quantity = "occlusion";  // "occlusion" or "transfer": what the row estimates
  std::string falloff;                 // the falloff the method used (and its reference)
  int width = 0, height = 0;
  double baseMs = 0, frameMs = 0;            // medians of the interleaved base and method frames
  double aoMs = 0, aoQ1Ms = 0, aoQ3Ms = 0;   // median and quartiles of the paired differences
  std::string stages;                        // "name=ms;..." stage medians, profiled runs only (empty: none)
  double stagesMs = 0.0;                     // their sum
  double prepareMs = 0;                      // one-time work before the first frame (bakes)
  double rmse = 0, mae = 0, p99 = 0, ssim = 0;
  std::size_t memoryBytes = 0;
  std::size_t pixels = 0;    // covered pixels compared
  int refSamples = 0;        // reference rays per pixel
  double refStdErr = 0;      // RMS of the reference's own per-pixel standard error (formula)
  double refNoise = 0;       // measured: RMS difference of two references with different seeds / sqrt 2
  // Still frames (bench --still N; bench/StillFrames.h): NaN when not measured.
  int stillFrames = 0;
  double rmseF4 = std::numeric_limits<double>::quiet_NaN(), rmseF16 = std::numeric_limits<double>::quiet_NaN();
  double stillBias = std::numeric_limits<double>::quiet_NaN(), stillNoise = std::numeric_limits<double>::quiet_NaN();
};

struct ReferenceSummary {
  std::string scene;
  int samples = 0;
  double seconds = 0, raysPerSecond = 0, bvhSeconds = 0;
  std::size_t bvhBytes = 0, triangles = 0;
  // Throughput on identical rays, the same Embree calls on both sides, alternating, best of three.
  double sameRaysReference = 0, sameRaysEmbree = 0;
  double stdErr = 0;  // the formula's noise floor (RMS standard error)
  double noise = 0;   // the measured one (two seeds, every noiseRowStride-th row)
  int noiseRowStride = 0;
};

// The csv header and the order of columns; the schema test holds us to it.
const std::vector<std::string>& benchCsvColumns();
// One csv line (no newline) for a row.
std::string benchCsvLine(const BenchRow& row);
// Writes rows atomically.
void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows);

// results.csv written as the bench goes: the header on open, each row appended and flushed as it
// finishes, so an interrupted bench keeps every row it completed (and no half row).
class BenchCsvStream {
 public:
  explicit BenchCsvStream(const std::string& path);  // throws when it cannot write
  void append(const BenchRow& row);

 private:
  std::string path_;
  std::ofstream out_;
};

// One method over an animated sequence (see SequenceBench.h).
struct SequenceRow {
  std::string scene, method, setting;
  std::string camera;            // "held" or "moving"
  int frames = 0;
  double temporalChange = 0;     // mean |AO_t - AO_t-1| over surface points seen in both frames
  double refTemporalChange = 0;  // the reference's, same points
  double meanRmse = 0;           // RMSE against the reference, averaged over frames
  std::size_t matchedPixels = 0;  // surface points compared per frame pair (mean)
};

// Markdown: the rows as tables per scene, the reference summaries, the temporal rows (optional),
// and how to read them.
void writeBenchReport(const std::string& path, const std::vector<BenchRow>& rows,
                      const std::vector<ReferenceSummary>& refs, const std::string& chartFile,
                      const std::vector<SequenceRow>& sequence = {});

}  // namespace aokit
