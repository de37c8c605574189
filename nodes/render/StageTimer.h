#pragma once
// The time of each stage of a frame. A frame is a sequence of marks: begin(), then mark("stage")
// after each stage's commands; a stage's time is the difference between its mark and the previous
// one, so stages of a base pass and of a family's own code can be marked by either.
// StageTiming::Timestamps: GL timestamp queries (glQueryCounter with GL_TIMESTAMP, core since GL
// 3.3), no stall; results are read when asked for, or when the next frame begins (blocking until
// the GPU is done with it). A driver that runs commands later than it dates them (llvmpipe
// rasterizes at flush time) gives stages that do not add up to the frame.
// StageTiming::Finished (profiling): glFinish at every mark and the CPU's steady clock, so each
// stage holds its own work and the stages add up to the frame's time between the first and last
// mark; the stalls cost the overlap between stages.
#include <string>
#include <vector>

#include "core/AOTechnique.h"  // StageTime

namespace aokit {

// "gbuffer=1.20;obscurance=9.80" (the bench's stages column).
std::string formatStageTimes(const StageTimes& stages);

class StageTimer {
 public:
  StageTimer() = default;
  ~StageTimer();
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

  // Off by default: timing costs a little, and plain VTK users do not need it.
  void setMode(StageTiming mode) { mode_ = mode; }
  StageTiming mode() const { return mode_; }
  bool enabled() const { return mode_ != StageTiming::Off; }

  // The context must be current for all of these.
  void begin();
  void mark(const char* stage);
  // The stages of the last frame that was marked (empty when disabled or before any frame).
  const StageTimes& results();
  // Deletes the queries (the context is going away).
  void release();

 private:
  void collect();
  StageTiming mode_ = StageTiming::Off;
  StageTiming pendingMode_ = StageTiming::Off;  // the mode the pending frame was marked in
  std::vector<unsigned> queries_;     // Timestamps: pool, reused frame to frame
  std::vector<double> wallMs_;        // Finished: the steady clock at each mark
  std::vector<std::string> names_;    // names_[i] ends at queries_[i + 1]
  int used_ = 0;                      // queries issued in the pending frame
  bool pending_ = false;
  StageTimes last_;
};

}  // namespace aokit
