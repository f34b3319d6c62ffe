#include "tests/harness/harness.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/exercise/run_record.hpp"
#include "common/platform/context.hpp"
#include "common/platform/shader.hpp"
#include "tests/harness/reference_calls.hpp"
#include "tests/harness/tape.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace wb::test {

// Where this binary's tests write: its own folder, or WB_TEST_OUTPUT_DIR when a shader mutant borrows
// the solution's binary (cmake/Lab.cmake), so that the two never write the same files at once.
static fs::path outputDir() {
  const char* dir = std::getenv("WB_TEST_OUTPUT_DIR");
  return dir && *dir ? fs::absolute(dir) : fs::path(variant::kOutputDir);  // (the app runs elsewhere)
}

namespace {
std::unique_ptr<Context> g_context;
std::string g_renderer;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Reference | result | diff, side by side in one picture is handy, but three files are what the
// report links; the diff is red where the result has extra shadow, blue where it lost shadow,
// magenta where the exercise is still a stub.
std::vector<uint8_t> diffImage(const FloatImage& ref, const FloatImage& got, float tol) {
  std::vector<uint8_t> rgba(ref.pixels.size() * 4, 255);
  for (size_t i = 0; i < ref.pixels.size(); ++i) {
    uint8_t* p = &rgba[4 * i];
    const float r = ref.pixels[i], g = got.pixels[i];
    const auto grey = uint8_t(90 + 80 * std::clamp(r, 0.0f, 1.0f));
    p[0] = p[1] = p[2] = grey;
    if (isTodo(g))
      p[0] = 230, p[1] = 0, p[2] = 200;
    else if (g < r - tol)
      p[0] = 255, p[1] = 40, p[2] = 40;
    else if (g > r + tol)
      p[0] = 40, p[1] = 90, p[2] = 255;
  }
  return rgba;
}
// An RGBA8 image of w x h, each pixel made 2 x 2.
std::vector<uint8_t> doubled(const std::vector<uint8_t>& rgba, int w, int h) {
  std::vector<uint8_t> out(size_t(4 * w * h) * 4);
  for (int y = 0; y < 2 * h; ++y)
    for (int x = 0; x < 2 * w; ++x)
      for (int c = 0; c < 4; ++c) out[(size_t(y) * 2 * w + x) * 4 + c] = rgba[(size_t(y / 2) * w + x / 2) * 4 + c];
  return out;
}
// Where a test's data file lives: `public_dir`/NAME, or for a held-out case ("hidden/NAME") the
// instructor-only tests/hidden/<lab>/`hidden_dir`/NAME.
fs::path dataFile(const std::string& name, const fs::path& publicDir, const char* hiddenDir) {
  const fs::path root(variant::kSourceDir);
  if (name.rfind("hidden/", 0) == 0) return root / "tests/hidden" / variant::kLab / hiddenDir / name.substr(7);
  return root / publicDir / name;
}
}  // namespace

std::vector<std::string> labArgs(const std::vector<std::string>& settings, const std::string& scene) {
  std::vector<std::string> args;
  if (!scene.empty()) args = {"--scene", dataFile(scene, "scenes", "scenes").string()};
  for (const auto& s : settings) args.insert(args.end(), {"--set", s});
  return args;
}

bool g_updateGolden = false;  // set by main() from --update-golden

bool updatingGolden() { return g_updateGolden; }

void GlTest::SetUpTestSuite() {
  if (!g_context) {
    g_context = Context::create({true, 0, 0, "tests", true});
    g_renderer = Context::renderer();
  }
  ::testing::Test::RecordProperty("gl_renderer", g_renderer);
}

void GlTest::TearDown() {
  for (const auto& e : takeGlErrors()) ADD_FAILURE() << "ERROR: OpenGL reported: " << e;
}

std::string renderer() { return g_renderer; }

// The exercise file as handed out, where this edition has it: the student edition's tests/stubs/, or
// the lab's own folder when the submission is elsewhere (WB_SUBMISSION_DIR); "" without one.
static std::string stubText(const std::string& file) {
  const fs::path exported = fs::path(variant::kSourceDir) / "tests/stubs" / variant::kLab / "shaders" / file;
  const char* submission = std::getenv("WB_SUBMISSION_DIR");
  const fs::path own = fs::path(variant::kLabDir) / "shaders" / file;
  try {
    if (fs::exists(exported)) return readFile(exported);
    if (submission && *submission && fs::exists(own)) return readFile(own);
  } catch (const std::exception&) {
  }
  return "";
}

// Exercise `id`'s kernel. Without the reference (the student edition), a compile error in another
// exercise's chunk would stop this one's tests: that chunk is then swapped for the stub's, and the
// kernel tried again; if the exercise needs what it swapped (its results are the stub's WB_TODO), it
// is blocked by that exercise.
static std::vector<glm::vec4> runIsolatedKernel(const std::string& id, const std::string& body, int count, int stride,
                                                const std::vector<glm::vec4>& inputs, const std::vector<GLuint>& ids) {
  std::string text = isolatedExerciseSource("exercise.glsl", id);
  const std::string stub = *variant::kSolutionDir ? "" : stubText("exercise.glsl");
  std::set<std::string> swapped;
  for (;;) {
    try {
      auto got = runGlslKernel(text, submittedShaderFile("exercise.glsl"), body, count, stride, inputs, ids);
      if (anyTodo(got) && !swapped.empty())
        throw Error("blocked by " + *swapped.begin() + ": its chunk does not compile, and " + id +
                    " needs it (fix the compile error first; the grader tests " + id + " with the reference)");
      return got;
    } catch (const SlowShader&) {
      throw;
    } catch (const Error& e) {
      const std::string owner = glslErrorOwner(e.what());
      if (stub.empty() || owner.empty() || owner == id || swapped.count(owner)) throw;
      swapped.insert(owner);
      text = withChunksFrom(text, stub, {owner});
    }
  }
}

std::vector<glm::vec4> runExercise(const std::string& id, const std::string& body, int count, int stride,
                                   const std::vector<glm::vec4>& inputs, const std::vector<unsigned>& textures) {
  nextObservationKey();  // (keeps the keys of the test's later observations the same in every mode)
  // GLSL is evaluated by whoever decides: a runner has nothing to record (it never sees the
  // solution's chunks), and a judge runs the submission's chunk itself, in the GPU driver.
  if (tapeMode() == TapeMode::Record) return std::vector<glm::vec4>(size_t(count) * size_t(stride));
  const std::vector<GLuint> ids(textures.begin(), textures.end());
  auto got = runIsolatedKernel(id, body, count, stride, inputs, ids);
  const fs::path reference = fs::path(variant::kSolutionDir) / "shaders/exercise.glsl";
  if (*variant::kSolutionDir && fs::exists(reference)) {
    // Timed against the reference on the same inputs, repeated to 16384 invocations so that the
    // dispatch's own cost does not hide a slow shader.
    const int reps = std::max(1, 16384 / std::max(count, 1));
    const size_t one = size_t(std::max(count, 1)) * size_t(stride);
    std::vector<glm::vec4> many(one * size_t(reps));
    for (size_t j = 0; j < many.size(); ++j) many[j] = j % one < inputs.size() ? inputs[j % one] : glm::vec4(0.0f);
    const std::string mineText = isolatedExerciseSource("exercise.glsl", id), refText = readFile(reference);
    const fs::path mineOrigin = submittedShaderFile("exercise.glsl");
    auto timed = [&](const std::string& text, const fs::path& origin) {
      runGlslKernel(text, origin, body, count * reps, stride, many, ids);
      return std::max(lastKernelMilliseconds(), 0.01);
    };
    timed(mineText, mineOrigin);  // (a first run may include the driver's compile)
    timed(refText, reference);
    double mine = timed(mineText, mineOrigin), ref = timed(refText, reference);
    // Slow once: three more rounds, interleaved, and the fastest of each, so that a process
    // descheduled on a loaded machine is not taken for an endless loop.
    for (int round = 0; round < 3 && mine > kSlowShaderFloorMs && mine > kSlowShaderFactor * ref; ++round) {
      mine = std::min(mine, timed(mineText, mineOrigin));
      ref = std::min(ref, timed(refText, reference));
    }
    if (mine > kSlowShaderFloorMs && mine > kSlowShaderFactor * ref)
      throw SlowShader("WRONG: your shader runs " + std::to_string(int(mine / ref)) + "x longer than the reference (" +
                       std::to_string(int(mine)) + " ms against " + std::to_string(ref).substr(0, 5) + " ms on " +
                       std::to_string(count * reps) + " inputs): an endless loop? (a GPU would hang on it)");
  }
  return got;
}

// The seed of grading-time variations (WB_VARY_SEED, set by the grader), or -1: scenes are then
// turned a little (--vary), and compared with the solution's render of the same variation instead
// of the published golden, so a copied golden is worth nothing.
static long long varySeed() {
  const char* s = std::getenv("WB_VARY_SEED");
  return s && *s ? std::atoll(s) : -1;
}

static std::vector<std::string> varyArgs() {
  return varySeed() >= 0 ? std::vector<std::string>{"--vary", std::to_string(varySeed())} : std::vector<std::string>{};
}

// Runs `exe --headless args` (plus the variation, if any) from `out` with a time limit, its output
// in `log`: the exit status and the command. From its output folder, so nothing it writes lands
// where the tests were started.
static std::pair<int, std::string> runApp(const fs::path& out, const std::string& env, const std::string& exe,
                                          const std::vector<std::string>& args, const fs::path& log) {
  const char* limit = std::getenv("WB_RUN_TIMEOUT");  // seconds for one lab run (check sets it; else 120)
  const int seconds = limit && std::atoi(limit) > 0 ? std::atoi(limit) : 120;
  std::string cmd = "cd " + quote(out.string()) + " && " + env + "timeout " + std::to_string(seconds) + " " +
                    quote(exe) + " --headless";
  for (const auto& a : args) cmd += " " + quote(a);
  for (const auto& a : varyArgs()) cmd += " " + quote(a);
  const int status = std::system((cmd + " >" + quote(log.string()) + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128, cmd};
}

// runApp() as JSON: {"code", "log" (its start and end when long), "command"}.
static nlohmann::json runAppJson(const fs::path& out, const std::string& env, const std::string& exe,
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
static std::string trustedExe() { return variant::kSolutionExe[0] ? variant::kSolutionExe : variant::kLabExe; }

IsolatedShaders::IsolatedShaders(const std::string& id) : dir_(outputDir() / ("isolated_" + id)) {
  fs::create_directories(dir_);
  for (const std::string& file : glslExerciseFiles()) std::ofstream(dir_ / file) << isolatedExerciseSource(file, id);
  if (const char* old = std::getenv("WB_SHADER_OVERLAY")) previous_ = old, hadPrevious_ = true;
  setenv("WB_SHADER_OVERLAY", dir_.c_str(), 1);
}

IsolatedShaders::~IsolatedShaders() {
  if (hadPrevious_)
    setenv("WB_SHADER_OVERLAY", previous_.c_str(), 1);
  else
    unsetenv("WB_SHADER_OVERLAY");
}

std::string IsolatedShaders::text(const std::string& file) const { return readFile(dir_ / file); }

// The environment that makes an app use `id`'s isolated GLSL (the submission's chunk of a GLSL
// exercise and the solution's other chunks; all solution for a C++ exercise), written into `out`.
static std::string isolatedGlsl(const std::string& id, const fs::path& out) {
  if (updatingGolden()) return "";
  // (Without the solution, isolatedExerciseSource() is the submission's whole file: the files the
  // student edition's app reads anyway, and a submission's when WB_SUBMISSION_DIR names one.)
  for (const std::string& file : glslExerciseFiles())  // exercise.glsl, and a stage file such as a .geom
    std::ofstream(out / file) << isolatedExerciseSource(file, id);
  return "WB_SHADER_OVERLAY=" + quote(out.string()) + " ";
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
  auto run = runAppJson(out, "WB_STRICT_GL=1 " + isolatedGlsl(id, out), exe, all);
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
static std::string recordEnv() {
  const char* stubs = std::getenv("WB_RECORD_SHADERS");
  return std::string("WB_STRICT_GL=1 ") + (stubs && *stubs ? "WB_SHADER_OVERLAY=" + quote(stubs) + " " : "");
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
  if (glsl) return runAppJson(out, "WB_STRICT_GL=1 " + isolatedGlsl(id, out), trustedExe(), withOthers(id, out, args));
  const auto mine = recordRun(key, out, runnerArgs(args), id, args);
  const fs::path calls = out / "exercises.json";
  if (tapeMode() == TapeMode::Record) throw Error("recorded for the judge");
  if (mine.value("code", 128) != 0) return mine;  // the student's app failed: that is the result
  if (!fs::exists(calls) || !keepOnlyCalls(calls, id, out / "upstream.json"))
    throw Error("your lab never ran exercise " + id + " in this scene (its run left no result):\n" +
                (heldOutJudging() ? std::string("(held-out run)") : mine.value("log", std::string())));
  return runAppJson(out, "WB_STRICT_GL=1 " + isolatedGlsl(id, out), trustedExe(), withOthers(id, out, args, calls));
}

// Draws exercise `id` (drawExercise) with a record, and reads it. Fails with ERROR / NOT
// IMPLEMENTED when it did not run, and always in a runner (which decides nothing).
static ::testing::AssertionResult runIsolated(const std::string& id, const fs::path& out,
                                              const std::vector<std::string>& args, std::string& logText,
                                              RunResult* result = nullptr) {
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
    // A compile error in another exercise's chunk of a shared shader file blocks this one too.
    if (const std::string by = glslErrorOwner(cause); !by.empty() && by != id)
      return ::testing::AssertionFailure() << "ERROR: blocked by " << by << ": the GLSL of exercise " << by
                                           << " does not compile, so the lab could not draw this one; fix " << by
                                           << " first (" << by << " shows the error).";
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

fs::path testOutputDir() { return outputDir(); }

std::string runLabOutput(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                         std::string& failure) {
  std::string log;
  const auto ok = runIsolated(id, outputDir() / ("Ex" + id + "_" + name), args, log);
  failure = ok ? "" : ok.message();
  return log;
}

SceneMetrics measureScene(const std::string& id, const std::string& name, const std::vector<std::string>& args) {
  const fs::path out = outputDir() / ("Ex" + id + "_" + name);
  std::vector<std::string> scene = {"--size", "480x270", "--metrics"};
  scene.insert(scene.end(), args.begin(), args.end());
  std::string log;
  SceneMetrics m;
  RunResult run;
  const auto ok = runIsolated(id, out, scene, log, &run);
  if (!ok) {
    m.failure = ok.message();
    return m;
  }
  if (!run.acnePercent || !run.leakPercent) {
    m.failure = "ERROR: the lab's record holds no measurements:\n" + log;
    return m;
  }
  m.acnePercent = *run.acnePercent, m.leakPercent = *run.leakPercent, m.gapTexels = run.gapTexels.value_or(-1);
  m.areaMeanAbsPercent = run.areaMeanAbsPercent.value_or(-1), m.areaOffPercent = run.areaOffPercent.value_or(-1);
  m.seamErrorPercent = run.seamErrorPercent.value_or(-1), m.restErrorPercent = run.restErrorPercent.value_or(-1);
  m.penumbra = run.penumbra;
  return m;
}

double penumbraGrowthRatio(const SceneMetrics& m) {
  auto slope = [&](int y) {  // of column y against the distance (column 0)
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (const auto& r : m.penumbra)
      if (r[0] > 0) sx += r[0], sy += r[size_t(y)], sxx += r[0] * r[0], sxy += r[0] * r[size_t(y)], ++n;
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  };
  return slope(2) / slope(1);
}

void expectSceneMatchesGolden(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                              float tolerance, double maxFailingFraction) {
  const fs::path out = outputDir() / ("Ex" + id + "_" + name);
  const fs::path golden = dataFile(name + ".pfm", fs::path("tests/golden") / variant::kLab, "golden");
  const fs::path pfm = out / "result.pfm";
  std::vector<std::string> all = {"--size", "256x256", "--dump-visibility", pfm.string()};
  all.insert(all.end(), args.begin(), args.end());
  fs::create_directories(out);
  fs::remove(pfm);
  std::string logText;
  RunResult run;
  const auto ok = runIsolated(id, out, all, logText, &run);
  if (!ok) FAIL() << ok.message();
  FloatImage got;
  try {
    got = readPfm(pfm);
  } catch (const std::exception& e) {
    FAIL() << "ERROR: the lab's visibility could not be read: " << e.what();
  }
  if (updatingGolden()) {
    fs::create_directories(golden.parent_path());
    fs::copy_file(pfm, golden, fs::copy_options::overwrite_existing);
    GlTest::SetUpTestSuite();  // for the renderer string stored beside the golden data
    std::ofstream(golden.parent_path() / "renderer.txt") << renderer() << "\n";
    std::printf("updated %s\n", golden.string().c_str());
    return;
  }
  FloatImage ref;
  if (varySeed() >= 0) {  // the trusted app's render of the same variation
    const fs::path refPfm = out / "reference_varied.pfm";
    std::vector<std::string> all = {"--size", "256x256", "--dump-visibility", refPfm.string()};
    all.insert(all.end(), args.begin(), args.end());
    if (fs::exists(out / "upstream.json"))  // the inputs the graded exercise had (keepOnlyCalls)
      all.insert(all.end(), {"--replay-exercises", (out / "upstream.json").string()});
    fs::remove(refPfm);
    if (runApp(out, "", trustedExe(), all, out / "reference.log").first != 0 || !fs::exists(refPfm))
      FAIL() << "ERROR: the reference render of the varied scene failed (a fault of the grader):\n"
             << readFile(out / "reference.log");
    ref = readPfm(refPfm);
  } else {
    if (!fs::exists(golden))
      FAIL() << "ERROR: no golden data " << golden << "; run ./workbook golden " << id.substr(0, 2);
    ref = readPfm(golden);
  }
  if (ref.width != got.width || ref.height != got.height) FAIL() << "ERROR: golden " << golden << " has another size";
  // A pixel fails when no reference pixel in its 3x3 neighbourhood is within `tolerance`: a shadow
  // edge that moves by one pixel (rasterisation, a texel of a rotated map) is not an error.
  size_t failing = 0, todo = 0;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const float g = got.at(x, y);
      if (isTodo(g)) {
        ++todo;
        continue;
      }
      bool near = false;
      for (int dy = -1; dy <= 1 && !near; ++dy)
        for (int dx = -1; dx <= 1 && !near; ++dx) {
          const int sx = std::clamp(x + dx, 0, ref.width - 1), sy = std::clamp(y + dy, 0, ref.height - 1);
          near = std::abs(g - ref.at(sx, sy)) <= tolerance;
        }
      failing += !near;
    }
  const double fraction = double(failing + todo) / double(ref.pixels.size());
  std::printf("[ scene    ] %s %s: %.3f%% of pixels differ from %s (allowed %.3f%%)\n", id.c_str(), name.c_str(),
              100 * fraction, golden.filename().string().c_str(), 100 * maxFailingFraction);
  if (fraction <= maxFailingFraction) return;
  // Twice the size, pixel for pixel, so that a one-pixel edge can be seen in an image viewer.
  writePng(out / "reference.png", 2 * ref.width, 2 * ref.height, doubled(toGrey(ref), ref.width, ref.height));
  writePng(out / "result.png", 2 * got.width, 2 * got.height, doubled(toGrey(got), got.width, got.height));
  writePng(out / "diff.png", 2 * ref.width, 2 * ref.height,
           doubled(diffImage(ref, got, tolerance), ref.width, ref.height));
  std::ostringstream msg;
  std::string stubs;  // the other exercises that are not implemented in this run
  for (const auto& [other, state] : run.exerciseStates)
    if (state == "not_implemented" && other != id) stubs += (stubs.empty() ? "" : ", ") + other;
  if (todo && !stubs.empty()) {  // (runIsolated() already failed an exercise that is a stub itself)
    msg << "ERROR: blocked by " << stubs << ": " << todo << " pixels of scene '" << name << "' show the "
        << "not-implemented placeholder (stripes) of " << stubs << ", which this scene draws with yours: "
        << "implement " << stubs << " first (the grader draws it with the reference)";
  } else if (todo) {
    msg << "NOT IMPLEMENTED: " << todo << " pixels of scene '" << name << "' show the not-implemented placeholder";
  } else {
    char pct[64];
    std::snprintf(pct, sizeof pct, "%.2f%% of pixels (allowed %.2f%%)", 100 * fraction, 100 * maxFailingFraction);
    msg << "WRONG: visibility in scene '" << name << "' differs from the reference on " << pct;
  }
  msg << "\n  diff: " << (out / "diff.png").string()
      << " (red: shadowed where the reference is lit; blue: lit where it is shadowed)"
      << "\n  reference: " << (out / "reference.png").string() << "\n  result: " << (out / "result.png").string();
  FAIL() << msg.str();
}

}  // namespace wb::test
