#pragma once
// The reference pane's ground truth, off the GUI thread: CPU primary rays through the pane's pixels
// (castPrimarySamples, shading normals as the rasterizer has them) and the Embree reference on
// them, on a worker thread that the GUI starts when the camera rests and cancels when it moves.
// The GUI polls state() and progress() from a timer and takes the finished AO.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/Camera.h"
#include "core/AOScene.h"

namespace aokit {

class EmbreeScene;

namespace view {

class ReferenceWorker {
 public:
  // Builds the Embree scene of `root` (its casters) once; the falloff is the root's.
  ReferenceWorker(AOScene& root, int samples);
  ~ReferenceWorker();  // cancels and joins
  ReferenceWorker(const ReferenceWorker&) = delete;
  ReferenceWorker& operator=(const ReferenceWorker&) = delete;

  enum class State { Idle, Running, Done, Failed };
  // Cancels a running one and starts on this camera and pane size.
  void start(const Camera& camera, int width, int height, double radius);
  void cancel();
  State state() const { return state_.load(); }
  double progress() const { return progress_.load(); }
  int samples() const { return samples_; }
  // The finished AO, width * height floats bottom row first, -1 where no surface; seconds it took.
  // False unless Done (then the worker is Idle again).
  bool take(std::vector<float>& ao, int& width, int& height, double& seconds);
  std::string error() const;

 private:
  void join();

  std::unique_ptr<EmbreeScene> scene_;
  int samples_;
  Falloff falloff_;
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  std::atomic<State> state_{State::Idle};
  std::atomic<double> progress_{0.0};
  mutable std::mutex mutex_;
  std::vector<float> ao_;
  int width_ = 0, height_ = 0;
  double seconds_ = 0.0;
  std::string error_;
};

}  // namespace view
}  // namespace aokit
