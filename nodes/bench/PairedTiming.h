#pragma once
// Time of a method as it adds to the base frame, measured as interleaved pairs: base frame, method
// frame, base, method, ... each ended by glFinish, so both see the same state of a busy machine.
// The AO time is the median of the paired differences (method - base), with its quartiles: never
// clamped, so a difference inside the spread reads as such. GPU stage times (when the method
// reports them) are the medians over the timed method frames, per stage; the method's first stage,
// which draws the scene (a G-buffer, or the whole of a pass that is timed as one stage), is taken
// minus the base frame's own GPU time in the same pair, so that the stages add up to the AO time.
#include <functional>

#include "core/AOTechnique.h"

namespace aokit {

struct PairedTiming {
  double baseMs = 0.0, frameMs = 0.0;            // medians of the base and the method frames
  double aoMs = 0.0, aoQ1Ms = 0.0, aoQ3Ms = 0.0;  // median and quartiles of method - base
  StageTimes stages;                             // median per stage, in first-seen order
  int pairs = 0;
  int warmupPairs = 0;  // untimed pairs run first (see timePairs)
};

// Runs at least `warmup` untimed pairs, more (up to 8) until the base and the method frame have
// each settled within 15 % of their previous frame, then `pairs` timed ones. Each callback must
// render one frame and finish it, and returns that frame's GPU stage times (empty if it has none;
// the base frame's are summed into its GPU time).
PairedTiming timePairs(const std::function<StageTimes()>& baseFrame, const std::function<StageTimes()>& methodFrame,
                       int warmup, int pairs);

// The q-quantile (0..1) of the values by linear interpolation between order statistics (the
// "type 7" definition of R and numpy). Throws std::invalid_argument on an empty list.
double quantile(std::vector<double> values, double q);

}  // namespace aokit
