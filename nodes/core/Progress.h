#pragma once
// Progress lines for long jobs (bake, reference, bench) and a cooperative Ctrl-C.
#include <chrono>
#include <functional>
#include <string>

namespace aokit {

// Prints "label: 42%" to stderr: in place on a terminal, every 10% otherwise (logs stay short).
class Progress {
 public:
  explicit Progress(std::string label, bool enabled = true);
  void update(double fraction);
  void done();
  // A callback for long jobs: reports the fraction and throws "interrupted" after Ctrl-C.
  std::function<void(double)> reporter();

 private:
  std::string label_;
  bool enabled_, tty_;
  int lastShown_ = -1;
  std::chrono::steady_clock::time_point start_;
};

// SIGINT/SIGTERM set a flag instead of killing the process, so jobs can stop between steps and
// leave no half-written files.
void installInterruptHandler();
bool interruptRequested();
void throwIfInterrupted();  // throws std::runtime_error("interrupted")

}  // namespace aokit
