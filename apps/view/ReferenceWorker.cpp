#include "view/ReferenceWorker.h"

#include <chrono>
#include <stdexcept>

#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/PrimarySamples.h"

namespace aokit::view {

namespace {
struct Cancelled {};
}  // namespace

ReferenceWorker::ReferenceWorker(AOScene& root, int samples)
    : scene_(std::make_unique<EmbreeScene>(root)), samples_(samples), falloff_(root.falloff()) {}

ReferenceWorker::~ReferenceWorker() { cancel(); }

void ReferenceWorker::join() {
  if (thread_.joinable()) thread_.join();
}

void ReferenceWorker::cancel() {
  cancel_ = true;
  join();
  cancel_ = false;
  if (state_ == State::Running) state_ = State::Idle;
}

void ReferenceWorker::start(const Camera& camera, int width, int height, double radius) {
  cancel();
  progress_ = 0.0;
  state_ = State::Running;
  thread_ = std::thread([this, camera, width, height, radius] {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const SurfaceSamples s = castPrimarySamples(*scene_, camera, width, height);
      ReferenceOptions o;
      o.samples = samples_;
      o.radius = radius;
      o.falloff = falloff_;
      o.progress = [this](double f) {
        if (cancel_) throw Cancelled{};
        progress_ = f;
      };
      AOBuffer ao = computeReferenceAO(*scene_, s, o);
      for (std::size_t i = 0; i < ao.ao.size(); ++i)
        if (!ao.covered[i]) ao.ao[i] = -1.0f;
      std::lock_guard<std::mutex> lock(mutex_);
      ao_ = std::move(ao.ao);
      width_ = width;
      height_ = height;
      seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      state_ = State::Done;
    } catch (const Cancelled&) {
      state_ = State::Idle;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = e.what();
      state_ = State::Failed;
    }
  });
}

bool ReferenceWorker::take(std::vector<float>& ao, int& width, int& height, double& seconds) {
  if (state_ != State::Done) return false;
  join();
  std::lock_guard<std::mutex> lock(mutex_);
  ao = std::move(ao_);
  width = width_;
  height = height_;
  seconds = seconds_;
  state_ = State::Idle;
  return true;
}

std::string ReferenceWorker::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

}  // namespace aokit::view
