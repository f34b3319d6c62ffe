#include "tests/harness/harness.hpp"

#include "common/context.hpp"
#include "common/glsl_harness.hpp"
#include "common/run_record.hpp"
#include "common/shader.hpp"
#include "common/variant.hpp"
#include "tests/harness/tape.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace fs = std::filesystem;

namespace wb::test {
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

std::vector<glm::vec4> runExercise(const std::string& id, const std::string& body, int count, int stride,
                                   const std::vector<glm::vec4>& inputs, const std::vector<unsigned>& textures) {
  return observe<std::vector<glm::vec4>>([&] {
    const fs::path file = findShaderFile("exercise.glsl", shaderSearchPath());
    return runGlslKernel(isolatedExerciseSource("exercise.glsl", id), file, body, count, stride, inputs,
                         std::vector<GLuint>(textures.begin(), textures.end()));
  });
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
  std::string cmd = "cd " + quote(out.string()) + " && " + env + "timeout 120 " + quote(exe) + " --headless";
  for (const auto& a : args) cmd += " " + quote(a);
  for (const auto& a : varyArgs()) cmd += " " + quote(a);
  const int status = std::system((cmd + " >" + quote(log.string()) + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128, cmd};
}

// The app a judge trusts: the solution's (this build's in the student edition, which has none).
static std::string trustedExe() { return variant::kSolutionExe[0] ? variant::kSolutionExe : variant::kLabExe; }

// Runs the lab headless for exercise `id` with GLSL isolation (the exercise's own chunk from this
// build, everything else from the solution: a GLSL exercise then runs in the solution's app, so C++
// stubs cannot block it, and a C++ exercise runs in this build's app with the solution's GLSL).
// Returns {"code": exit code, "log": output, "command": the command}.
static nlohmann::json runLabProcess(const std::string& id, const fs::path& out, const std::vector<std::string>& args,
                                    const std::vector<std::string>& extra) {
  fs::create_directories(out);
  std::string env = "WB_STRICT_GL=1 ";
  std::string exe = variant::kLabExe;
  if (*variant::kSolutionDir != '\0' && !updatingGolden()) {
    const std::string mine = readFile(findShaderFile("exercise.glsl", shaderSearchPath()));
    if (mine.find("// EXERCISE " + id) != std::string::npos && variant::kSolutionExe[0]) exe = variant::kSolutionExe;
    std::ofstream(out / "exercise.glsl") << isolatedExerciseSource("exercise.glsl", id);
    env += "WB_SHADER_OVERLAY=" + quote(out.string()) + " ";
  }
  const fs::path log = out / "lab.log";
  std::vector<std::string> all = args;
  all.insert(all.end(), extra.begin(), extra.end());
  const auto [code, cmd] = runApp(out, env, exe, all, log);
  // The log is the student's process's output: only its start and end are kept (and recorded).
  std::string text = readFile(log);
  if (text.size() > 40000) text = text.substr(0, 20000) + "\n[...]\n" + text.substr(text.size() - 20000);
  return {{"code", code}, {"log", text}, {"command", cmd}};
}

// Runs the lab for exercise `id` (see runLabProcess) as an observation: a runner records its exit
// code, output, record (run.json) and visibility (result.pfm, when `args` ask for it); a judge gets
// them back from the tape. Fails with ERROR / NOT IMPLEMENTED when it did not run.
static ::testing::AssertionResult runIsolated(const std::string& id, const fs::path& out,
                                              const std::vector<std::string>& args, std::string& logText,
                                              RunResult* result = nullptr) {
  const fs::path record = out / "run.json";
  fs::create_directories(out);
  fs::remove(record);
  const std::string key = nextObservationKey();
  nlohmann::json run;
  try {
    run = observeJson(key, [&] { return runLabProcess(id, out, args, {"--record", record.string()}); });
    observeFile(key + ".record", record);
    observeFile(key + ".visibility", out / "result.pfm");
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "ERROR: " << e.what();
  }
  const int code = run.value("code", 128);
  logText = run.value("log", std::string());
  if (code != 0) {
    // The first line names the cause (a compile error's file:line when there is one).
    std::string cause, last;
    std::istringstream lines(logText);
    for (std::string l; std::getline(lines, l);) {
      if (!l.empty()) last = l;
      if (cause.empty() && l.find(": error") != std::string::npos) cause = l;
    }
    return ::testing::AssertionFailure() << "ERROR: the lab "
                                         << (code == 124 ? "timed out" : "failed (exit " + std::to_string(code) + ")")
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

// A judge measures the runner's visibility itself: the solution's app (trusted code; this build's
// app in the student edition) renders the same scene for the positions and measures the recorded
// visibility buffer against exact visibility (--measure-visibility), so no number comes from the
// student's process.
static ::testing::AssertionResult judgeMeasurement(const fs::path& out, const std::vector<std::string>& args,
                                                   RunResult& run) {
  const fs::path record = out / "judge.json";
  std::vector<std::string> all = {"--record", record.string(), "--measure-visibility", (out / "result.pfm").string()};
  all.insert(all.end(), args.begin(), args.end());
  const int status = runApp(out, "", trustedExe(), all, out / "judge.log").first;
  try {
    run = readRunRecord(record);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "ERROR: the measurement of the recorded visibility failed: " << e.what();
  }
  if (status != 0 || run.status != "ok")
    return ::testing::AssertionFailure() << "ERROR: the recorded visibility could not be measured: " << run.error;
  return ::testing::AssertionSuccess();
}

std::string runLabOutput(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                         std::string& failure) {
  std::string log;
  const auto ok = runIsolated(id, fs::path(variant::kOutputDir) / ("Ex" + id + "_" + name), args, log);
  failure = ok ? "" : ok.message();
  return log;
}

SceneMetrics measureScene(const std::string& id, const std::string& name, const std::vector<std::string>& args) {
  const fs::path out = fs::path(variant::kOutputDir) / ("Ex" + id + "_" + name);
  std::vector<std::string> scene = {"--size", "480x270", "--metrics"};
  scene.insert(scene.end(), args.begin(), args.end());
  std::vector<std::string> all = {"--dump-visibility", (out / "result.pfm").string()};  // what a judge measures
  all.insert(all.end(), scene.begin(), scene.end());
  std::string log;
  SceneMetrics m;
  RunResult run;
  auto ok = runIsolated(id, out, all, log, &run);
  if (ok && tapeMode() == TapeMode::Replay) ok = judgeMeasurement(out, scene, run);
  if (!ok) {
    m.failure = ok.message();
    return m;
  }
  if (!run.acnePercent || !run.leakPercent) {
    m.failure = "ERROR: the lab's record holds no measurements:\n" + log;
    return m;
  }
  m.acnePercent = *run.acnePercent, m.leakPercent = *run.leakPercent, m.gapTexels = run.gapTexels.value_or(-1);
  return m;
}

void expectSceneMatchesGolden(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                              float tolerance, double maxFailingFraction) {
  const fs::path out = fs::path(variant::kOutputDir) / ("Ex" + id + "_" + name);
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
  if (tapeMode() == TapeMode::Record) return;  // the judge compares
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
  std::printf("[ scene    ] %s: %.3f%% of pixels differ from %s (allowed %.3f%%)\n", name.c_str(), 100 * fraction,
              golden.filename().string().c_str(), 100 * maxFailingFraction);
  if (fraction <= maxFailingFraction) return;
  writePng(out / "reference.png", ref.width, ref.height, toGrey(ref));
  writePng(out / "result.png", got.width, got.height, toGrey(got));
  writePng(out / "diff.png", ref.width, ref.height, diffImage(ref, got, tolerance));
  std::ostringstream msg;
  if (todo) {
    msg << "NOT IMPLEMENTED: " << todo << " pixels of scene '" << name << "' show the not-implemented placeholder";
    for (const auto& [other, state] : run.exerciseStates)
      if (state == "not_implemented") msg << "\n  exercise " << other << " is not implemented yet";
  } else {
    char pct[64];
    std::snprintf(pct, sizeof pct, "%.2f%% of pixels (allowed %.2f%%)", 100 * fraction, 100 * maxFailingFraction);
    msg << "WRONG: visibility in scene '" << name << "' differs from the reference on " << pct;
  }
  msg << "\n  diff: " << (out / "diff.png").string() << " (red: extra shadow, blue: missing shadow)"
      << "\n  reference: " << (out / "reference.png").string() << "\n  result: " << (out / "result.png").string();
  FAIL() << msg.str();
}

}  // namespace wb::test
