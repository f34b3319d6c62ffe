/// @file tape.hpp
/// Runner and judge. In grading, student code runs only in a *runner*: the student's test binary
/// with --runner DIR, which records every value an exercise produced (a C++ result, a GLSL kernel's
/// outputs, a scene's visibility) on a tape in DIR, and decides nothing. A *judge* (the same test
/// sources built with the solution, run with --judge DIR) replays the tape: each observation returns
/// the recorded value instead of running anything, and the tests' own comparisons give the verdict.
/// Nothing a runner prints, exits with or writes besides the tape's values can claim a pass. Without
/// either option a test binary observes directly (the ordinary tests and CI).
#pragma once
#include "common/error.hpp"
#include "common/value_codec.hpp"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace wb::test {

/// How observations behave in this process.
enum class TapeMode {
  Direct,  ///< run the code (ordinary tests)
  Record,  ///< run the code and record what it produced (--runner DIR)
  Replay   ///< return what the runner recorded, never running the code (--judge DIR)
};

/// This process's mode.
TapeMode tapeMode();
/// The tape's folder ("" when direct).
const std::filesystem::path& tapeDir();
/// Sets the mode (main() does, from --runner / --judge); Replay loads DIR/tape.jsonl.
void openTape(TapeMode mode, const std::filesystem::path& dir);

/// The key of the next observation of the running test ("Suite.Test#k"); deterministic as long as
/// the test's control flow depends only on observed values.
std::string nextObservationKey();

/// Records `value` (or the exception) under `key`, or in replay returns what was recorded: a value,
/// or an exception rethrown as wb::NotImplemented or wb::Error. A missing key is an error saying
/// the student's build produced nothing there.
nlohmann::json observeJson(const std::string& key, const std::function<nlohmann::json()>& produce);

/// Observes what `produce` returns: runs it (direct, record) or replays it (judge).
template <class T>
T observe(const std::function<T()>& produce) {
  const std::string key = nextObservationKey();
  if (tapeMode() == TapeMode::Direct) return produce();
  return decode<T>(observeJson(key, [&] { return encode(produce()); }));
}

/// Observes a file the runner wrote (a scene's visibility, its record): in record mode it is kept
/// on the tape under `name`; in replay mode the recorded copy is put back at `path`. Returns false
/// if there is none.
bool observeFile(const std::string& name, const std::filesystem::path& path);

}  // namespace wb::test

/// Observes the value of a C++ exercise call: `m = WB_CALL(lab01::f(x))`. The judge never calls it.
#define WB_CALL(expr) ::wb::test::observe<std::decay_t<decltype(expr)>>([&] { return (expr); })
