#include "bench/PairedTiming.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace aokit {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) throw std::invalid_argument("quantile of an empty list");
  std::sort(v.begin(), v.end());
  const double h = (v.size() - 1) * std::clamp(q, 0.0, 1.0);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - lo) * (v[hi] - v[lo]);
}

namespace {
template <class F>
double timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

PairedTiming timePairs(const std::function<StageTimes()>& baseFrame, const std::function<StageTimes()>& methodFrame,
                       int warmup, int pairs) {
  if (pairs < 1 || warmup < 0) throw std::invalid_argument("timePairs: need at least one timed pair");
  // At least `warmup` pairs, then more until both frames have settled (each within 15 % of its
  // previous one), at most kMaxExtraWarmup more: the first frames of a heavy scene (buffer uploads,
  // shader variants, caches) would otherwise read as the first row's AO time.
  constexpr int kMaxExtraWarmup = 8;
  double lastBase = -1.0, lastMethod = -1.0;
  auto settled = [](double now, double before) { return before > 0.0 && std::abs(now - before) <= 0.15 * before; };
  int warmed = 0;
  for (; warmup > 0 && warmed < warmup + kMaxExtraWarmup; ++warmed) {
    const double b = timed([&] { baseFrame(); });
    const double m = timed([&] { methodFrame(); });
    const bool steady = settled(b, lastBase) && settled(m, lastMethod);
    lastBase = b;
    lastMethod = m;
    if (warmed + 1 >= warmup && steady) {
      ++warmed;
      break;
    }
  }
  std::vector<double> base, method, diff;
  std::vector<std::pair<std::string, std::vector<double>>> stages;
  for (int i = 0; i < pairs; ++i) {
    StageTimes bs, st;
    const double b = timed([&] { bs = baseFrame(); });
    const double m = timed([&] { st = methodFrame(); });
    base.push_back(b);
    method.push_back(m);
    diff.push_back(m - b);
    double baseGpu = 0.0;
    for (const auto& s : bs) baseGpu += s.ms;
    if (!st.empty() && !bs.empty()) st.front().ms -= baseGpu;
    for (const auto& s : st) {
      auto it = std::find_if(stages.begin(), stages.end(), [&](const auto& e) { return e.first == s.name; });
      if (it == stages.end()) it = stages.insert(stages.end(), {s.name, {}});
      it->second.push_back(s.ms);
    }
  }
  PairedTiming t;
  t.pairs = pairs;
  t.warmupPairs = warmed;
  t.baseMs = quantile(base, 0.5);
  t.frameMs = quantile(method, 0.5);
  t.aoMs = quantile(diff, 0.5);
  t.aoQ1Ms = quantile(diff, 0.25);
  t.aoQ3Ms = quantile(diff, 0.75);
  for (const auto& [name, ms] : stages) t.stages.push_back({name, quantile(ms, 0.5)});
  return t;
}

}  // namespace aokit
