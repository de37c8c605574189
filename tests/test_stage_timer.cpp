// StageTimer: stages are the spans between marks, named by the mark that ends them; profiling
// (StageTiming::Finished) measures each span on the steady clock after glFinish, so a span that
// held 30 ms of work reads at least 30 ms and the spans add up to the frame; off, nothing is kept.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "headless/OffscreenWindow.h"
#include "render/StageTimer.h"

using namespace aokit;

namespace {

// One frame: a 30 ms span "slow", then an empty span "fast"; the frame's wall time.
double markFrame(StageTimer& timer) {
  const auto t0 = std::chrono::steady_clock::now();
  timer.begin();
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  timer.mark("slow");
  timer.mark("fast");
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST(StageTimer, ProfilingSpansAreWallClockAndAddUpToTheFrame) {
  OffscreenWindow window(32, 32);
  window.render();  // VTK loads the GL entry points with its first frame
  window.makeCurrent();
  StageTimer timer;
  timer.setMode(StageTiming::Finished);
  const double frameMs = markFrame(timer);
  const StageTimes& t = timer.results();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "slow");
  EXPECT_EQ(t[1].name, "fast");
  EXPECT_GE(t[0].ms, 30.0);
  EXPECT_GE(t[1].ms, 0.0);
  EXPECT_LE(t[0].ms + t[1].ms, frameMs);
  timer.release();
}

TEST(StageTimer, TimestampsNameTheSameStagesAndOffKeepsNone) {
  OffscreenWindow window(32, 32);
  window.render();  // VTK loads the GL entry points with its first frame
  window.makeCurrent();
  StageTimer timer;
  timer.setMode(StageTiming::Timestamps);
  markFrame(timer);
  window.finish();
  const StageTimes t = timer.results();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "slow");
  EXPECT_GE(t[0].ms, 0.0);
  timer.setMode(StageTiming::Off);
  markFrame(timer);
  EXPECT_EQ(timer.results().size(), 2u) << "off keeps the last timed frame's results";
  StageTimer never;
  markFrame(never);
  EXPECT_TRUE(never.results().empty());
  timer.release();
}
