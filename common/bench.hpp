/// @file bench.hpp
/// Benchmarks that print numbers: --bench (GPU ms per pass and wall ms per frame over a run, as a
/// table and a CSV) and --sweep (every combination of the listed settings, timed and optionally
/// measured, as a Markdown table and a CSV).
#pragma once
#include "common/command_line.hpp"
#include "common/gpu_timers.hpp"
#include "common/measurement.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <string>

namespace wb {

class Settings;

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

/// Runs --sweep: for every combination (the last key varies fastest), one warm-up frame and then
/// options.frames timed frames through `frame`; with options.metrics, `measure` the last one.
/// Prints a Markdown table (and writes options.sweepCsv). Returns the exit code.
int runSweep(const Options& options, Settings& settings, GpuTimers& timers, const std::function<void()>& frame,
             const std::function<MeasureResult()>& measure);

}  // namespace wb
