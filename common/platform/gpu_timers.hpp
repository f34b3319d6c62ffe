/// @file gpu_timers.hpp
/// GPU time per named pass: GL_TIME_ELAPSED queries, collected when the GPU has the results, with
/// per-pass statistics for the info panel, --bench and --sweep. On Mesa's software renderers
/// (llvmpipe, softpipe) a pass is timed on the clock between two glFinish() calls instead: there the
/// "GPU" is the CPU's rasterizer threads, and llvmpipe's GL_TIME_ELAPSED holds only the time of the
/// last tile each thread drew when a pass is one scene (lab 08's lighting pass read 0.01 ms of 13).
/// Those fences slow the frame they time (each splits llvmpipe's scene and stores and reloads the
/// frame's attachments), so there the host times passes only when asked (the panel's "GPU ms",
/// --bench on alternate frames, --sweep in frames of their own) and takes frame rates from frames
/// it does not time.
#pragma once
#include "common/platform/gl.hpp"

#include <string>
#include <utility>
#include <vector>

namespace wb {

/// One pass's GPU time in milliseconds.
struct PassStats {
  double last = 0;    ///< the latest sample
  double sum = 0;     ///< total of the recorded samples
  double min = 1e30;  ///< smallest recorded sample
  double max = 0;     ///< largest recorded sample
  int count = 0;      ///< recorded samples
  /// The mean of the recorded samples (0 when none).
  double mean() const { return count ? sum / count : 0; }
};

/// Named GPU pass timers. Passes may not nest (GL allows one GL_TIME_ELAPSED query at a time).
class GpuTimers {
 public:
  GpuTimers() = default;
  ~GpuTimers();
  GpuTimers(const GpuTimers&) = delete;
  GpuTimers& operator=(const GpuTimers&) = delete;

  /// Times the GPU work issued while it lives: `auto t = timers.scope("shadow");`.
  class Scope {
   public:
    /// Begins a GL_TIME_ELAPSED query for the pass `name` (or, on a software renderer, finishes
    /// the work before it and starts the clock).
    Scope(GpuTimers& timers, const char* name);
    /// Ends the query; the result is collected when the GPU has it.
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    GpuTimers& timers_;
    std::string name_;
    double startMs_ = -1;  // the clock at the start, on a software renderer
  };
  /// Starts timing a pass until the returned object is destroyed.
  Scope scope(const char* name) { return Scope(*this, name); }

  /// Turns timing on or off; while off, scope() times nothing (and costs nothing).
  void enable(bool on) { enabled_ = on; }
  /// True when timing slows what it times (a software renderer): see the file's note.
  bool perturbs() { return software(); }
  /// Reads finished queries into the statistics; `wait` blocks until all are done, and only
  /// `record`ed samples count towards mean, min and max (warm-up frames do not).
  void collect(bool wait, bool record);
  /// Forgets the statistics (the pass names stay, in their order).
  void resetStats();
  /// Forgets the passes too (a new lab has its own); collect(true, …) first.
  void clear() { passes_.clear(); }
  /// Every pass seen so far, in first-seen order.
  const std::vector<std::pair<std::string, PassStats>>& passes() const { return passes_; }

 private:
  PassStats& stats(const std::string& name);
  void add(const std::string& name, double ms, bool record);
  bool software();
  int software_ = -1;  // -1 until the renderer has been asked
  bool enabled_ = true;
  std::vector<std::pair<std::string, double>> clocked_;  // software renderers: samples not yet collected
  std::vector<std::pair<std::string, GLuint>> pending_;
  std::vector<GLuint> free_;
  std::vector<std::pair<std::string, PassStats>> passes_;
};

}  // namespace wb
