#include "core/Progress.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <stdexcept>

namespace aokit {

namespace {
std::atomic<bool> gInterrupted{false};
void onSignal(int) { gInterrupted = true; }
}  // namespace

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void Progress::update(double fraction) {
  if (!enabled_) return;
  const int pct = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100.0);
  const int step = tty_ ? 1 : 10;
  if (pct / step == lastShown_ / step && lastShown_ >= 0) return;
  lastShown_ = pct;
  if (tty_)
    std::fprintf(stderr, "\r%s: %3d%%", label_.c_str(), pct);
  else
    std::fprintf(stderr, "%s: %d%%\n", label_.c_str(), pct);
  std::fflush(stderr);
}

std::function<void(double)> Progress::reporter() {
  return [this](double f) {
    throwIfInterrupted();
    update(f);
  };
}

void Progress::done() {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "%s%s: done in %.1f s\n", tty_ ? "\r" : "", label_.c_str(), s);
}

void installInterruptHandler() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
}

bool interruptRequested() { return gInterrupted; }

void throwIfInterrupted() {
  if (gInterrupted) throw std::runtime_error("interrupted");
}

}  // namespace aokit
