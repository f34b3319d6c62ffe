#include "common/judge/isolation.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/judge/reference_calls.hpp"
#include "common/judge/tape.hpp"
#include "common/platform/process.hpp"
#include "common/platform/shader.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace wb::test {

// The seed of grading-time variations (WB_VARY_SEED, set by the grader), or -1: scenes are then
// turned a little (--vary), and compared with the solution's render of the same variation instead
// of the published golden, so a copied golden is worth nothing.
long long varySeed() {
  const char* s = std::getenv("WB_VARY_SEED");
  return s && *s ? std::atoll(s) : -1;
}

bool replaysFailedUse(const std::string& id) {
  const char* failed = std::getenv("WB_REPLAY_USES");
  return varySeed() >= 0 && failed && ("," + std::string(failed) + ",").find("," + id + ",") != std::string::npos;
}

static std::vector<std::string> varyArgs() {
  return varySeed() >= 0 ? std::vector<std::string>{"--vary", std::to_string(varySeed())} : std::vector<std::string>{};
}

// Runs `exe --headless args` (plus the variation, if any) from `out` with a time limit, its output
// in `log`: the exit status and the command. From its output folder, so nothing it writes lands
// where the tests were started. Stopped at the limit with whatever it started (process.hpp).
std::pair<int, std::string> runApp(const fs::path& out, const Env& env, const std::string& exe,
                                   const std::vector<std::string>& args, const fs::path& log) {
  const char* limit = std::getenv("WB_RUN_TIMEOUT");  // seconds for one lab run (check sets it; else 120)
  ProcessSpec spec;
  spec.cwd = out, spec.env = env, spec.log = log;
  spec.timeoutSeconds = limit && std::atoi(limit) > 0 ? std::atoi(limit) : 120;
  spec.graceSeconds = 3;  // (its crash report, from the SIGTERM, names where it was: addr2line takes a moment)
  spec.argv = {exe, "--headless"};
  for (const auto& a : args) spec.argv.push_back(a);
  for (const auto& a : varyArgs()) spec.argv.push_back(a);
  const ProcessResult r = runProcess(spec);
  if (r.end == ProcessResult::End::NotStarted) std::ofstream(log) << "the lab did not start: " << r.detail << "\n";
  return {r.code, shellCommand(spec)};
}

// runApp() as JSON: {"code", "log" (its start and end when long), "command"}.
static nlohmann::json runAppJson(const fs::path& out, const Env& env, const std::string& exe,
                                 const std::vector<std::string>& args) {
  fs::create_directories(out);
  const fs::path log = out / "lab.log";
  const auto [code, cmd] = runApp(out, env, exe, args, log);
  std::string text = readFile(log);
  if (text.size() > 40000) text = text.substr(0, 20000) + "\n[...]\n" + text.substr(text.size() - 20000);
  return {{"code", code}, {"log", text}, {"command", cmd}};
}

static std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The app a judge trusts: the solution's (this build's in the student edition, which has none).
std::string trustedExe() { return variant::kSolutionExe[0] ? variant::kSolutionExe : variant::kLabExe; }

// The environment that makes an app use `id`'s isolated GLSL (the submission's chunk of a GLSL
// exercise and the solution's other chunks; all solution for a C++ exercise), written into `out`.
static Env isolatedGlsl(const std::string& id, const fs::path& out) {
  if (updatingGolden()) return {{"WB_STRICT_GL", "1"}};
  // (Without the solution, isolatedExerciseSource() is the submission's whole file: the files the
  // student edition's app reads anyway, and a submission's when WB_SUBMISSION_DIR names one.)
  for (const std::string& file : glslExerciseFiles())  // exercise.glsl, and a stage file such as a .geom
    std::ofstream(out / file) << isolatedExerciseSource(file, id);
  return {{"WB_STRICT_GL", "1"}, {"WB_SHADER_OVERLAY", out.string()}};
}

// The reference's results for every C++ exercise but `id` in a run with `args` (reference_calls.hpp),
// written to `out`/reference_calls.json for --replay-exercises; empty when there are none, and in a
// varied scene, which the judge's reference draws again instead.
static fs::path referenceOthers(const std::string& id, const fs::path& out, const std::vector<std::string>& args) {
  const fs::path others = out / "reference_calls.json";
  return varySeed() < 0 && referenceCallsOfOthers(referenceCallsFile(args), id, others) ? others : fs::path();
}

// Direct (ctest, check): this build's lab draws exercise `id` in isolation. Every other C++
// exercise's result is the reference's (reference_calls.hpp), so a mistake there cannot block this
// one; a GLSL exercise runs in the solution's app where there is one, a C++ exercise in this
// build's app, both with the solution's GLSL for the other exercises. Updating the golden data
// records the reference's calls instead.
static nlohmann::json runDirect(const std::string& id, const fs::path& out, const std::vector<std::string>& args) {
  fs::create_directories(out);
  const bool glsl = !glslExerciseFile(id).empty();
  const std::string exe = glsl && !updatingGolden() ? trustedExe() : variant::kLabExe;
  const fs::path reference = referenceCallsFile(args);
  std::vector<std::string> all = args;
  if (updatingGolden()) {
    fs::create_directories(reference.parent_path());
    all = joined(args, {"--record-exercises", reference.string()});
  } else if (const fs::path others = referenceOthers(id, out, args); !others.empty()) {
    all = joined(args, {"--replay-exercises", others.string()});
  }
  auto run = runAppJson(out, isolatedGlsl(id, out), exe, all);
  if (updatingGolden() && keepReferenceCalls(reference)) std::printf("updated %s\n", reference.string().c_str());
  return run;
}

// What a runner's app needs of the scene's arguments: not the measurements or images, only a run.
static std::vector<std::string> runnerArgs(const std::vector<std::string>& args) {
  std::vector<std::string> kept;
  for (size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--metrics") continue;
    if (args[k] == "--dump-visibility" || args[k] == "--screenshot" || args[k] == "--heatmap" ||
        args[k] == "--record") {
      ++k;
      continue;
    }
    kept.push_back(args[k]);
  }
  return kept;
}

// The environment of a runner's lab run, which only records what the C++ exercises return: with
// the stub shaders when the grader gives them (WB_RECORD_SHADERS), so that the student's GLSL, which
// the judge grades on its own, cannot stop the C++ exercises' runs.
static Env recordEnv() {
  const char* stubs = std::getenv("WB_RECORD_SHADERS");
  // (WB_GLSL_STUBBED: framework steps whose results a C++ exercise takes, such as SDSM's depth
  // bounds, then run their own CPU equivalent of the stubbed GLSL exercise, depth_bounds.cpp)
  if (stubs && *stubs) return {{"WB_STRICT_GL", "1"}, {"WB_SHADER_OVERLAY", stubs}, {"WB_GLSL_STUBBED", "1"}};
  return {{"WB_STRICT_GL", "1"}};
}

// A runner's lab run under tape key `key`: this build's app records what its C++ exercises return
// (--record-exercises), and the run ({"code", "log", "command"}) and that file go on the tape. A
// judge gets both back. Returns the run; the file is `out`/exercises.json. For exercise `id` in a
// scene compared with the golden (check), the other C++ exercises replay the reference's results
// (reference_calls.hpp, found by the scene's arguments `scene`): 10.2's corners are then computed
// from the reference's splits, and a wrong 10.1 is marked in 10.1 alone.
static nlohmann::json recordRun(const std::string& key, const fs::path& out, const std::vector<std::string>& args,
                                const std::string& id = "", const std::vector<std::string>& scene = {}) {
  const fs::path calls = out / "exercises.json";
  fs::create_directories(out);
  fs::remove(calls);
  std::vector<std::string> all = joined(args, {"--record-exercises", calls.string()});
  if (const fs::path others = id.empty() ? fs::path() : referenceOthers(id, out, scene); !others.empty())
    all = joined(all, {"--replay-exercises", others.string()});
  const auto run = observeJson(key, [&] { return runAppJson(out, recordEnv(), variant::kLabExe, all); });
  observeFile(key + ".exercises", calls);
  return run;
}

// The exercises whose results exercise `id` takes as its inputs in the lab ("uses" in the trusted
// manifest, labs/NN/exercises.json): 10.3 fits the slices that 10.1 and 10.2 computed. Only in a
// varied scene, which the judge's reference draws again on the same inputs (the grader's). The
// grader names in WB_REPLAY_USES the used exercises that failed their own tests; only those are
// replayed (one that passed gets the solution's code, so a student cannot feed the graded exercise
// made-up inputs in one test alone). Without WB_REPLAY_USES every used exercise is.
static std::vector<std::string> exerciseUses(const std::string& id) {
  // Compared with the golden (check, ctest), which was drawn with the reference's inputs: the used
  // exercises are the reference's too, so a mistake upstream is marked upstream alone.
  if (varySeed() < 0) return {};
  std::vector<std::string> uses;
  try {
    const auto manifest = nlohmann::json::parse(readFile(fs::path(variant::kLabDir) / "exercises.json"));
    for (const auto& e : manifest.at("exercises"))
      if (e.at("id") == id) uses = e.value("uses", std::vector<std::string>{});
  } catch (const std::exception&) {
  }
  if (const char* failed = std::getenv("WB_REPLAY_USES")) {
    const std::string list = "," + std::string(failed) + ",";
    uses.erase(std::remove_if(uses.begin(), uses.end(),
                              [&](const std::string& u) { return list.find("," + u + ",") == std::string::npos; }),
               uses.end());
  }
  return uses;
}

// Keeps only exercise `id`'s calls, and those of the exercises it uses (exerciseUses()), in a
// recorded --record-exercises file: the judge's app replays them and runs its own code for the
// others. The used exercises' calls alone go to `upstream` (removed when there are none), for the
// reference render: so a mistake in 10.2 is judged in 10.2, and 10.3 on the corners it was given.
// False when the file holds no call of `id` (an empty list included: replaying nothing would let
// the trusted app run its own code).
static bool keepOnlyCalls(const fs::path& file, const std::string& id, const fs::path& upstream) {
  fs::remove(upstream);
  try {
    const auto all = parseShallowJson(readFile(file));
    const auto& recorded = all.at("calls");
    if (!recorded.contains(id) || !recorded.at(id).is_array() || recorded.at(id).empty()) return false;
    nlohmann::json calls = {{id, recorded.at(id)}}, used = nlohmann::json::object();
    for (const std::string& u : exerciseUses(id))
      if (recorded.contains(u)) calls[u] = used[u] = recorded.at(u);
    const auto dump = [](const nlohmann::json& j) {
      return nlohmann::json{{"calls", j}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    };
    std::ofstream(file) << dump(calls);
    if (!used.empty()) std::ofstream(upstream) << dump(used);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// The arguments of a judge's run of exercise `id`, replaying `calls` (the student's results for it,
// or none). The student edition has no solution app: the judge's app is the student's, so every
// other C++ exercise's result is the reference's recorded one (reference_calls.hpp), as in a
// direct run; the solution's app computes them itself.
static std::vector<std::string> withOthers(const std::string& id, const fs::path& out,
                                           const std::vector<std::string>& args, const fs::path& calls = {}) {
  nlohmann::json replay = nlohmann::json::object();
  if (const fs::path others = variant::kSolutionExe[0] ? fs::path() : referenceOthers(id, out, args); !others.empty())
    replay = parseShallowJson(readFile(others)).at("calls");
  if (!calls.empty()) {
    const auto mine = parseShallowJson(readFile(calls));  // (kept alive: items() refers into it)
    for (const auto& [exercise, list] : mine.at("calls").items()) replay[exercise] = list;
  }
  if (replay.empty()) return args;
  const fs::path file = out / "judged_calls.json";
  std::ofstream(file) << nlohmann::json{{"calls", replay}}.dump(-1, ' ', false,
                                                                nlohmann::json::error_handler_t::replace);
  return joined(args, {"--replay-exercises", file.string()});
}

// Where the pixels of exercise `id` come from, by mode: direct (ctest), runDirect(); a runner only
// records what a C++ exercise returned in its own app (--record-exercises, kept on the tape) and
// has nothing to do for a GLSL exercise; a judge has the trusted app draw the scene, with the
// runner's recorded results for a C++ exercise and the submission's chunk for a GLSL one. Returns
// the app run {"code", "log", "command"}, or throws wb::Error with what went wrong.
static nlohmann::json drawExercise(const std::string& id, const fs::path& out, const std::vector<std::string>& args) {
  const std::string key = nextObservationKey();
  fs::remove(out / "upstream.json");
  if (tapeMode() == TapeMode::Direct) return runDirect(id, out, args);
  const bool glsl = !glslExerciseFile(id).empty();
  if (planning()) {
    // A judge's planning pass (held-out tests, which no runner has): the runs a runner must record.
    if (!glsl) planRequest({{"key", key}, {"args", runnerArgs(args)}});
    throw Error("planned");
  }
  if (glsl && tapeMode() == TapeMode::Record) throw Error("recorded for the judge");
  if (glsl) return runAppJson(out, isolatedGlsl(id, out), trustedExe(), withOthers(id, out, args));
  const auto mine = recordRun(key, out, runnerArgs(args), id, args);
  const fs::path calls = out / "exercises.json";
  if (tapeMode() == TapeMode::Record) throw Error("recorded for the judge");
  if (mine.value("code", 128) != 0) return mine;  // the student's app failed: that is the result
  if (!fs::exists(calls) || !keepOnlyCalls(calls, id, out / "upstream.json"))
    throw Error("your lab never ran exercise " + id + " in this scene (its run left no result):\n" +
                (heldOutJudging() ? std::string("(held-out run)") : mine.value("log", std::string())));
  return runAppJson(out, isolatedGlsl(id, out), trustedExe(), withOthers(id, out, args, calls));
}

// Draws exercise `id` (drawExercise) with a record, and reads it. Fails with ERROR / NOT
// IMPLEMENTED when it did not run, and always in a runner (which decides nothing).
::testing::AssertionResult runIsolated(const std::string& id, const fs::path& out, const std::vector<std::string>& args,
                                       std::string& logText, RunResult* result) {
  const fs::path record = out / "run.json";
  fs::create_directories(out);
  fs::remove(record);
  nlohmann::json run;
  try {
    run = drawExercise(id, out, joined(args, {"--record", record.string()}));
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "ERROR: " << e.what();
  }
  const int code = run.value("code", 128);
  logText = run.value("log", std::string());
  if (heldOutJudging()) logText = "(the log of a held-out run is not shown)";
  // A shader error names the isolated copy the app read; the student's own file is what to open.
  for (const std::string& file : glslExerciseFiles()) {
    const std::string copy = (out / file).string(), mine = submittedShaderFile(file).string();
    for (size_t at; (at = logText.find(copy)) != std::string::npos;) logText.replace(at, copy.size(), mine);
  }
  if (code != 0) {
    // The first line names the cause (a compile error's file:line when there is one).
    std::string cause, last;
    std::istringstream lines(logText);
    for (std::string l; std::getline(lines, l);) {
      if (!l.empty()) last = l;
      if (cause.empty() &&
          (l.find(": error") != std::string::npos || l.rfind("crashed (", 0) == 0 || l.rfind("timed out (", 0) == 0))
        cause = l;
    }
    // A crash in another exercise's code (common/exercise/crash_report.cpp names it) blocks this one: it could
    // not be drawn, and says nothing about this exercise.
    const auto other = cause.find(" in exercise ");
    if ((code > 128 || code == 124) && other != std::string::npos &&
        cause.compare(other + 13, id.size() + 1, id + ",") != 0) {
      const std::string by = cause.substr(other + 13, cause.find(',', other) - other - 13);
      return ::testing::AssertionFailure()
             << "ERROR: blocked by " << by << ": the lab " << (code == 124 ? "ran out of time" : "crashed")
             << " in exercise " << by << " before it could draw this one; fix " << by << " first. " << cause;
    }
    // A compile error in another exercise's chunk of a shared shader file blocks this one too: the
    // app names the chunks that do not compile alone (exercise_chunks.hpp), found by compiling.
    if (const auto culprits = culpritsIn(logText); !culprits.empty() && !culprits.count(id)) {
      const std::string by = *culprits.begin();
      return ::testing::AssertionFailure() << "ERROR: blocked by " << by << ": the GLSL of exercise " << by
                                           << " does not compile, so the lab could not draw this one; fix " << by
                                           << " first (" << by << " shows the error).";
    }
    return ::testing::AssertionFailure() << "ERROR: the lab "
                                         << (code == 124  ? "timed out"
                                             : code > 128 ? "crashed"
                                                          : "failed (exit " + std::to_string(code) + ")")
                                         << ": " << (cause.empty() ? last : cause) << "\n"
                                         << logText << "command: " << run.value("command", std::string());
  }
  RunResult recorded;
  try {
    recorded = readRunRecord(record);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "ERROR: the lab wrote no usable record: " << e.what() << "\n" << logText;
  }
  // The app probes every exercise; a stub whose effect cannot be seen in pixels (an alpha test
  // that keeps everything) is still reported as not implemented.
  if (recorded.exerciseStates[id] == "not_implemented")
    return ::testing::AssertionFailure() << "NOT IMPLEMENTED: exercise " << id << ": " << recorded.exerciseMessages[id];
  if (result) *result = recorded;
  return ::testing::AssertionSuccess();
}

int recordRequestedRuns(const fs::path& requests) {
  std::ifstream in(requests);
  if (!in) {
    std::fprintf(stderr, "cannot read --requests file %s\n", requests.string().c_str());
    return 2;
  }
  int k = 0;
  for (std::string line; std::getline(in, line); ++k) {
    const auto request = nlohmann::json::parse(line, nullptr, false);
    if (request.is_discarded() || !request.contains("key") || !request["key"].is_string()) continue;
    if (request.contains("call") && request["call"].is_string()) {  // a C++ exercise on held-out inputs
      try {
        observeJson(request["key"].get<std::string>(), [&] {
          return callRegistered(request["call"].get<std::string>(), request.value("inputs", nlohmann::json()));
        });
      } catch (const std::exception&) {  // recorded on the tape: the judge reports it
      }
      continue;
    }
    if (!request.contains("args")) continue;
    // In the tape's folder: the runner's own, while other exercises' runners may be running too.
    try {  // one failed request (malformed, a run that could not be recorded) must not end the others
      recordRun(request["key"].get<std::string>(), tapeDir() / ("request-" + std::to_string(k)),
                request["args"].get<std::vector<std::string>>());
    } catch (const std::exception&) {
    }
  }
  return 0;
}

}  // namespace wb::test
