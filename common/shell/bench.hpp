/// @file bench.hpp
/// Benchmarks that print numbers: --bench (GPU ms per pass and wall ms per frame over a run, as a
/// table and a CSV) and --sweep (every combination of the listed settings, timed and optionally
/// measured, as a Markdown table and a CSV).
#pragma once
#include "common/platform/gpu_timers.hpp"
#include "common/shell/command_line.hpp"
#include "common/truth/measurement.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <string>
#include <vector>

namespace wb {

class Settings;

/// Frame times of a live view (the showcase's Techniques window): the last `capacity` frames, with
/// their median and spread (10th to 90th percentile), the same statistics --sweep prints.
class RollingTimes {
 public:
  /// Keeps the last `capacity` frames.
  explicit RollingTimes(size_t capacity = 60) : capacity_(capacity) {}
  /// Adds one frame's time.
  void add(double ms);
  /// True before the first add().
  bool empty() const { return samples_.empty(); }
  double median() const { return quantile(0.5); }  ///< the median
  double low() const { return quantile(0.1); }     ///< the 10th percentile
  double high() const { return quantile(0.9); }    ///< the 90th percentile
  /// The q-quantile (0..1) of the samples, nearest rank; 0 when empty.
  double quantile(double q) const;

 private:
  size_t capacity_, next_ = 0;
  std::vector<double> samples_;
};

/// Wall-clock time of the recorded frames of a run.
struct WallClock {
  double sumMs = 0;  ///< total
  int frames = 0;    ///< frames recorded
  int warmup = 0;    ///< frames skipped before recording
  /// Mean milliseconds per frame (0 when none).
  double meanMs() const { return frames ? sumMs / frames : 0; }
};

/// Writes the --bench CSV at `path` and prints its table; throws wb::UsageError if it cannot write.
void writeBench(const std::string& path, const std::string& lab, glm::ivec2 size, const GpuTimers& timers,
                const WallClock& wall, bool print);

/// Runs --sweep: options.rounds interleaved rounds over every combination (the last key varies
/// fastest), each one warm-up frame and then options.frames timed frames through `frame`; with
/// options.metrics, `measure` once per combination, outside the timing. Prints a Markdown table of
/// medians over the rounds, with the frame's spread (and writes options.sweepCsv). Returns the exit code.
int runSweep(const Options& options, Settings& settings, GpuTimers& timers, const std::function<void()>& frame,
             const std::function<MeasureResult()>& measure);

}  // namespace wb
