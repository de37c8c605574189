#pragma once
// GPU time of each stage of a frame, from GL timestamp queries (glQueryCounter with GL_TIMESTAMP,
// core since GL 3.3; llvmpipe exposes 64-bit timestamps). A frame is a sequence of marks: begin(),
// then mark("stage") after each stage's commands; a stage's time is the difference between its
// mark and the previous one. Timestamps (unlike GL_TIME_ELAPSED queries) need no nesting rules,
// so stages of a base pass and of a family's own code can be marked by either.
// Results of a frame are read when asked for, or when the next frame begins (blocking until the
// GPU is done with it: call after glFinish when timing, as the bench does).
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

  // Off by default: queries cost a little, and plain VTK users do not need them.
  void setEnabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }

  // The context must be current for all of these.
  void begin();
  void mark(const char* stage);
  // The stages of the last frame that was marked (empty when disabled or before any frame).
  const StageTimes& results();
  // Deletes the queries (the context is going away).
  void release();

 private:
  void collect();
  bool enabled_ = false;
  std::vector<unsigned> queries_;     // pool, reused frame to frame
  std::vector<std::string> names_;    // names_[i] ends at queries_[i + 1]
  int used_ = 0;                      // queries issued in the pending frame
  bool pending_ = false;
  StageTimes last_;
};

}  // namespace aokit
