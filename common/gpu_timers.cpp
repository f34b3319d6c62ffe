#include "common/gpu_timers.hpp"

#include <algorithm>

namespace wb {

GpuTimers::~GpuTimers() {
  for (GLuint q : free_) glDeleteQueries(1, &q);
  for (auto& p : pending_) glDeleteQueries(1, &p.second);
}

GpuTimers::Scope::Scope(GpuTimers& timers, const char* name) {
  GLuint q = 0;
  if (timers.free_.empty())
    glGenQueries(1, &q);
  else
    q = timers.free_.back(), timers.free_.pop_back();
  timers.pending_.emplace_back(name, q);
  glBeginQuery(GL_TIME_ELAPSED, q);
}

GpuTimers::Scope::~Scope() { glEndQuery(GL_TIME_ELAPSED); }

PassStats& GpuTimers::stats(const std::string& name) {
  for (auto& [n, s] : passes_)
    if (n == name) return s;
  passes_.emplace_back(name, PassStats{});
  return passes_.back().second;
}

void GpuTimers::collect(bool wait, bool record) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    GLint ready = 0;
    if (!wait) glGetQueryObjectiv(it->second, GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!wait && !ready) {
      ++it;
      continue;
    }
    GLuint64 ns = 0;
    glGetQueryObjectui64v(it->second, GL_QUERY_RESULT, &ns);
    PassStats& s = stats(it->first);
    s.last = double(ns) * 1e-6;
    if (record) {
      s.sum += s.last, ++s.count;
      s.min = std::min(s.min, s.last), s.max = std::max(s.max, s.last);
    }
    free_.push_back(it->second);
    it = pending_.erase(it);
  }
}

void GpuTimers::resetStats() {
  for (auto& [name, s] : passes_) s = PassStats{};
}

}  // namespace wb
