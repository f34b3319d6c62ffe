/// @file tape.hpp
/// Runner and judge. In grading, student code runs only in a *runner*: the student's test binary
/// with --runner DIR, which records every value an exercise produced (a C++ result, a GLSL kernel's
/// outputs, a scene's visibility) on a tape in DIR, and decides nothing. A *judge* (the same test
/// sources built with the solution, run with --judge DIR) replays the tape: each observation returns
/// the recorded value instead of running anything, and the tests' own comparisons give the verdict.
/// Nothing a runner prints, exits with or writes besides the tape's values can claim a pass. Without
/// either option a test binary observes directly (the ordinary tests and CI).
#pragma once
#include "common/base/error.hpp"
#include "common/base/value_codec.hpp"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace wb::test {

/// The runner of an exercise stopped before this call (check ran it alone with a time limit): its
/// crash or time-out, in the student's words.
struct RunnerStopped : Error {
  using Error::Error;
};

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
/// Replaying: why a run of an exercise was stopped, by its tag ("Ex09_4" -> reason), from the tape's
/// stopped.txt (./workbook check writes it for runners, and for a judge's test it had to stop).
const std::map<std::string, std::string>& stoppedRuns();
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

/// True in a judge that judges held-out tests (WB_HELD_OUT=1, set by the grader): nothing the
/// runner recorded as text (an exception's message, a log) is quoted, since it could carry the
/// held-out inputs to a student.
bool heldOutJudging();

/// True in a judge's planning pass (WB_PLAN=FILE): the held-out tests, which no runner holds, list
/// what a runner must record for them.
bool planning();
/// Appends one request to the plan: {"key", "args"} (a lab run) or {"key", "call", "inputs"} (a C++
/// exercise called by name, see WB_CALL_HELD_OUT).
void planRequest(const nlohmann::json& request);

/// An exercise argument or result as JSON (an enum as its int).
template <class T>
nlohmann::json encodeValue(const T& v) {
  if constexpr (std::is_enum_v<T>)
    return encode(int(v));
  else
    return encode(v);
}
/// The inverse of encodeValue(); throws wb::Error on malformed data.
template <class T>
T decodeValue(const nlohmann::json& j) {
  if constexpr (std::is_enum_v<T>)
    return T(decode<int>(j));
  else
    return decode<T>(j);
}

/// A C++ exercise a runner can call by name, on inputs from a request (JSON array, one per argument).
using Callable = std::function<nlohmann::json(const nlohmann::json& inputs)>;
/// Registers `call` under `name`; WB_CALLABLE does it for an exercise function.
bool registerCallable(const std::string& name, Callable call);
/// Calls the exercise registered as `name` (throws wb::Error naming it when there is none).
nlohmann::json callRegistered(const std::string& name, const nlohmann::json& inputs);

/// The number of arguments of an exercise function.
template <class R, class... A>
constexpr size_t arity(R (*)(A...)) {
  return sizeof...(A);
}

/// Calls `fn` with `inputs` (a JSON array, one value per parameter) decoded, and encodes its result.
template <class R, class... A, size_t... I>
nlohmann::json callWithInputs(R (*fn)(A...), const nlohmann::json& inputs, std::index_sequence<I...>) {
  if (!inputs.is_array() || inputs.size() != sizeof...(A)) throw Error("malformed inputs of a requested call");
  return encodeValue(fn(decodeValue<std::decay_t<A>>(inputs[I])...));
}

/// Observes a call of exercise function `fn` (registered as `name`) on `args`. In a judge's planning
/// pass it also asks the runner for that call (the solution's result keeps the test going), so a
/// held-out test can call an exercise on inputs no runner binary holds; otherwise like WB_CALL.
template <class R, class... A, class... B>
R observeCall(const char* name, R (*fn)(A...), const B&... args) {
  static_assert(sizeof...(A) == sizeof...(B), "one value per argument");
  const std::string key = nextObservationKey();
  if (tapeMode() == TapeMode::Direct) return fn(args...);
  if (planning()) {
    planRequest({{"key", key}, {"call", name}, {"inputs", {encodeValue<std::decay_t<A>>(args)...}}});
    return fn(args...);
  }
  return decodeValue<R>(observeJson(key, [&] { return encodeValue(fn(args...)); }));
}

}  // namespace wb::test

/// Observes the value of a C++ exercise call: `m = WB_CALL(lab01::f(x))`. The judge never calls it.
#define WB_CALL(expr) ::wb::test::observe<std::decay_t<decltype(expr)>>([&] { return (expr); })

/// Makes exercise function `fn` callable by name in a runner (put it in the lab's public tests):
/// `WB_CALLABLE(lab10::fitCascade);`. Held-out tests call it with WB_CALL_HELD_OUT.
#define WB_CALLABLE(fn)                                                                                 \
  static const bool WB_CALLABLE_CAT(wbCallable, __LINE__) =                                             \
      ::wb::test::registerCallable(#fn, [](const nlohmann::json& in) {                                  \
        return ::wb::test::callWithInputs(&fn, in, std::make_index_sequence<::wb::test::arity(&fn)>{}); \
      })
/// Pastes two tokens (a unique name for each registration).
#define WB_CALLABLE_CAT2(a, b) a##b
/// Pastes two tokens after expanding them (`__LINE__`).
#define WB_CALLABLE_CAT(a, b) WB_CALLABLE_CAT2(a, b)

/// A held-out test's call of a WB_CALLABLE exercise: `m = WB_CALL_HELD_OUT(lab10::fitCascade, v, c, r)`.
/// The runner, which does not hold the test, makes the call from the judge's plan.
#define WB_CALL_HELD_OUT(fn, ...) ::wb::test::observeCall(#fn, &fn, __VA_ARGS__)
