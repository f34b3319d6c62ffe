#include "common/platform/gpu_timers.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace wb {

GpuTimers::~GpuTimers() {
  for (GLuint q : free_) glDeleteQueries(1, &q);
  for (auto& p : pending_) glDeleteQueries(1, &p.second);
}

namespace {
double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

bool GpuTimers::software() {
  if (software_ < 0) {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    software_ = r && (std::strstr(r, "llvmpipe") || std::strstr(r, "softpipe")) ? 1 : 0;
  }
  return software_ == 1;
}

GpuTimers::Scope::Scope(GpuTimers& timers, const char* name) : timers_(timers), name_(name) {
  if (!timers.enabled_) {
    startMs_ = -2;  // times nothing
    return;
  }
  if (timers.software()) {
    glFinish();  // the passes before this one are not this one's
    startMs_ = nowMs();
    return;
  }
  GLuint q = 0;
  if (timers.free_.empty())
    glGenQueries(1, &q);
  else
    q = timers.free_.back(), timers.free_.pop_back();
  timers.pending_.emplace_back(name, q);
  glBeginQuery(GL_TIME_ELAPSED, q);
}

GpuTimers::Scope::~Scope() {
  if (startMs_ == -2) return;
  if (startMs_ < 0) {
    glEndQuery(GL_TIME_ELAPSED);
    return;
  }
  glFinish();
  timers_.clocked_.emplace_back(name_, nowMs() - startMs_);
}

PassStats& GpuTimers::stats(const std::string& name) {
  for (auto& [n, s] : passes_)
    if (n == name) return s;
  passes_.emplace_back(name, PassStats{});
  return passes_.back().second;
}

void GpuTimers::add(const std::string& name, double ms, bool record) {
  PassStats& s = stats(name);
  s.last = ms;
  if (record) {
    s.sum += s.last, ++s.count;
    s.min = std::min(s.min, s.last), s.max = std::max(s.max, s.last);
  }
}

void GpuTimers::collect(bool wait, bool record) {
  for (const auto& [name, ms] : clocked_) add(name, ms, record);
  clocked_.clear();
  for (auto it = pending_.begin(); it != pending_.end();) {
    GLint ready = 0;
    if (!wait) glGetQueryObjectiv(it->second, GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!wait && !ready) {
      ++it;
      continue;
    }
    GLuint64 ns = 0;
    glGetQueryObjectui64v(it->second, GL_QUERY_RESULT, &ns);
    add(it->first, double(ns) * 1e-6, record);
    free_.push_back(it->second);
    it = pending_.erase(it);
  }
}

void GpuTimers::resetStats() {
  for (auto& [name, s] : passes_) s = PassStats{};
}

}  // namespace wb
