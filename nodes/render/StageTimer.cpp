#include "render/StageTimer.h"

#include <chrono>
#include <cstdio>

#include <vtk_glew.h>

namespace aokit {

std::string formatStageTimes(const StageTimes& stages) {
  std::string out;
  char buf[64];
  for (const auto& s : stages) {
    std::snprintf(buf, sizeof buf, "%s=%.3f", s.name.c_str(), s.ms);
    out += (out.empty() ? "" : ";") + std::string(buf);
  }
  return out;
}

StageTimer::~StageTimer() = default;  // GL objects need a context: release() is the owner's call

void StageTimer::begin() {
  if (pending_) collect();
  pendingMode_ = mode_;
  if (!enabled()) return;
  used_ = 0;
  names_.clear();
  wallMs_.clear();
  mark(nullptr);
}

void StageTimer::mark(const char* stage) {
  if (!enabled() || mode_ != pendingMode_) return;  // a mode set mid-frame waits for the next
  if (mode_ == StageTiming::Finished) {
    glFinish();
    wallMs_.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count());
    ++used_;
  } else {
    if (used_ == static_cast<int>(queries_.size())) {
      GLuint q = 0;
      glGenQueries(1, &q);
      queries_.push_back(q);
    }
    glQueryCounter(queries_[used_++], GL_TIMESTAMP);
  }
  if (stage) names_.emplace_back(stage);
  pending_ = used_ > 1;
}

void StageTimer::collect() {
  pending_ = false;
  last_.clear();
  if (pendingMode_ == StageTiming::Finished) {
    for (int i = 1; i < used_; ++i) last_.push_back({names_[i - 1], wallMs_[i] - wallMs_[i - 1]});
  } else {
    GLuint64 previous = 0;
    for (int i = 0; i < used_; ++i) {
      GLuint64 t = 0;
      glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &t);
      if (i > 0) last_.push_back({names_[i - 1], static_cast<double>(t - previous) * 1e-6});
      previous = t;
    }
  }
  // Stages marked twice in one frame (a stage run per occluder, say) are summed into one entry.
  StageTimes merged;
  for (const auto& s : last_) {
    bool found = false;
    for (auto& m : merged)
      if (m.name == s.name) {
        m.ms += s.ms;
        found = true;
      }
    if (!found) merged.push_back(s);
  }
  last_ = std::move(merged);
}

const StageTimes& StageTimer::results() {
  if (pending_) collect();
  return last_;
}

void StageTimer::release() {
  if (!queries_.empty()) glDeleteQueries(static_cast<GLsizei>(queries_.size()), queries_.data());
  queries_.clear();
  names_.clear();
  wallMs_.clear();
  used_ = 0;
  pending_ = false;
}

}  // namespace aokit
