#pragma once
// One row of results.csv: a method at one setting on one scene, against the reference.
#include <cstddef>
#include <string>
#include <vector>

namespace aokit {

struct BenchRow {
  std::string scene, method, setting;
  int width = 0, height = 0;
  double baseMs = 0, frameMs = 0, aoMs = 0;  // medians; aoMs = frameMs - baseMs
  double rmse = 0, mae = 0, p99 = 0, ssim = 0;
  std::size_t memoryBytes = 0;
  std::size_t pixels = 0;    // covered pixels compared
  int refSamples = 0;        // reference rays per pixel
  double refStdErr = 0;      // RMS of the reference's own per-pixel standard error
};

struct ReferenceSummary {
  std::string scene;
  int samples = 0;
  double seconds = 0, raysPerSecond = 0, rawRaysPerSecond = 0, stdErr = 0, bvhSeconds = 0;
  std::size_t bvhBytes = 0, triangles = 0;
};

// The csv header and the order of columns; the schema test holds us to it.
const std::vector<std::string>& benchCsvColumns();
// Writes rows atomically.
void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows);
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
