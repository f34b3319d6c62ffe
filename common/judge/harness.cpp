#include "common/judge/harness.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/exercise/run_record.hpp"
#include "common/judge/isolation.hpp"
#include "common/judge/picture.hpp"
#include "common/judge/reference_calls.hpp"
#include "common/judge/tape.hpp"
#include "common/platform/context.hpp"
#include "common/platform/process.hpp"
#include "common/platform/shader.hpp"

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

// The difference of a failing scene (the third of its panels): red where the result has extra shadow, blue where it
// lost shadow, magenta where the exercise is still a stub.
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

// Exercise `id`'s kernel. Without the reference (the student edition), a compile error in another
// exercise's chunk would stop this one's tests: the chunks that do not compile alone (found by
// compiling, never from the log) are then swapped for the stub's, and the kernel tried again; if the
// exercise needs what was swapped (its results are the stub's WB_TODO), it is blocked by that one.
static std::vector<glm::vec4> runIsolatedKernel(const std::string& id, const std::string& body, int count, int stride,
                                                const std::vector<glm::vec4>& inputs, const std::vector<GLuint>& ids) {
  const std::string file = "exercise.glsl";
  const fs::path origin = submittedShaderFile(file);
  const std::string text = isolatedExerciseSource(file, id);
  std::set<std::string> broken;
  std::string stub;
  try {
    return runGlslKernel(text, origin, body, count, stride, inputs, ids);
  } catch (const SlowShader&) {
    throw;
  } catch (const Error&) {
    // (With the reference's other chunks the error is this one's; without a stub nothing can be swapped.)
    if (*variant::kSolutionDir || !fs::exists(handedOutShaderFile(file))) throw;
    stub = readFile(handedOutShaderFile(file));
    broken = chunksThatDoNotCompile(
        text, stub, [&](const std::string& t) { return glslKernelError(t, origin, body, stride, ids).empty(); });
    if (broken.empty() || broken.count(id)) throw;
  }
  auto got = runGlslKernel(withChunksFrom(text, stub, broken), origin, body, count, stride, inputs, ids);
  if (anyTodo(got) && !chunkIsStub(text, id))  // (a stub's own WB_TODO is its own: not implemented)
    throw Error("blocked by " + *broken.begin() + ": its chunk does not compile, and " + id +
                " needs it (fix the compile error first; the grader tests " + id + " with the reference)");
  return got;
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

IsolatedShaders::IsolatedShaders(const std::string& id) : dir_(outputDir() / ("isolated_" + id)) {
  fs::create_directories(dir_);
  for (const std::string& file : glslExerciseFiles()) std::ofstream(dir_ / file) << isolatedExerciseSource(file, id);
  if (const char* old = std::getenv("WB_SHADER_OVERLAY")) previous_ = old, hadPrevious_ = true;
  setEnv("WB_SHADER_OVERLAY", dir_.string().c_str());
}

IsolatedShaders::~IsolatedShaders() {
  if (hadPrevious_)
    setEnv("WB_SHADER_OVERLAY", previous_.c_str());
  else
    setEnv("WB_SHADER_OVERLAY", nullptr);
}

std::string IsolatedShaders::text(const std::string& file) const { return readFile(dir_ / file); }

fs::path testOutputDir() { return outputDir(); }

std::string runLabOutput(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                         std::string& failure) {
  std::string log;
  const auto ok = runIsolated(id, outputDir() / ("Ex" + id + "_" + name), args, log);
  failure = ok ? "" : ok.message();
  return log;
}

// The verdict on scene `name` of exercise `id` when its frame shows a stub's placeholder: blocked by
// the other exercises that are stubs in `run` (the grader draws them with the reference), or not
// implemented when there are none. No number: it would count the stubs' stripes.
static std::string placeholderVerdict(const std::string& id, const std::string& name, const RunResult& run,
                                      const std::string& done) {
  std::string stubs;  // (runIsolated() already failed an exercise that is a stub itself)
  for (const auto& [other, state] : run.exerciseStates)
    if (state == "not_implemented" && other != id) stubs += (stubs.empty() ? "" : ", ") + other;
  if (stubs.empty()) return "NOT IMPLEMENTED: scene '" + name + "' shows the not-implemented placeholder";
  return "ERROR: blocked by " + stubs + ": scene '" + name + "' shows their not-implemented placeholder (stripes), " +
         "so it cannot be " + done + " yet: implement " + stubs + " first (the grader draws it with the reference)";
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
  if (run.todoPixels > 0) {  // a stub's pattern counts as shadow: the numbers would be the stubs'
    m.failure = placeholderVerdict(id, name, run, "measured");
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

namespace {

// The lab's visibility of a scene test (with `args`) at `pfm`: the image, or why there is none.
std::string renderScene(const std::string& id, const fs::path& out, const fs::path& pfm,
                        const std::vector<std::string>& args, FloatImage& got, RunResult& run) {
  std::vector<std::string> all = {"--size", "256x256", "--dump-visibility", pfm.string()};
  all.insert(all.end(), args.begin(), args.end());
  fs::create_directories(out);
  fs::remove(pfm);
  std::string logText;
  if (const auto ok = runIsolated(id, out, all, logText, &run); !ok) return ok.message();
  try {
    got = readPfm(pfm);
  } catch (const std::exception& e) {
    return std::string("ERROR: the lab's visibility could not be read: ") + e.what();
  }
  return "";
}

// ./workbook golden: the render becomes the golden data, with the renderer that made it beside it.
void updateGolden(const fs::path& pfm, const fs::path& golden) {
  fs::create_directories(golden.parent_path());
  fs::copy_file(pfm, golden, fs::copy_options::overwrite_existing);
  GlTest::SetUpTestSuite();  // for the renderer string stored beside the golden data
  std::ofstream(golden.parent_path() / "renderer.txt") << renderer() << "\n";
  std::printf("updated %s\n", golden.string().c_str());
}

// What the render is held against: with WB_VARY_SEED, the trusted app's render of the same varied
// scene (with the inputs the graded exercise had); else the published golden. "" or why there is none.
std::string referenceFor(const fs::path& out, const fs::path& golden, const std::vector<std::string>& args,
                         const std::string& id, FloatImage& ref) {
  if (varySeed() < 0) {
    if (!fs::exists(golden))
      return "ERROR: no golden data " + golden.string() + "; run ./workbook golden " + id.substr(0, 2);
    ref = readPfm(golden);
    return "";
  }
  const fs::path refPfm = out / "reference_varied.pfm";
  std::vector<std::string> all = {"--size", "256x256", "--dump-visibility", refPfm.string()};
  all.insert(all.end(), args.begin(), args.end());
  if (fs::exists(out / "upstream.json"))  // the inputs the graded exercise had (keepOnlyCalls)
    all.insert(all.end(), {"--replay-exercises", (out / "upstream.json").string()});
  fs::remove(refPfm);
  if (runApp(out, {}, trustedExe(), all, out / "reference.log").first != 0 || !fs::exists(refPfm))
    return "ERROR: the reference render of the varied scene failed (a fault of the grader):\n" +
           readFile(out / "reference.log");
  ref = readPfm(refPfm);
  return "";
}

// Pixels of `got` with no pixel of `ref` in its 3x3 neighbourhood within `tolerance` (a shadow edge
// that moves by one pixel, by rasterisation or a texel of a rotated map, is no error), and pixels
// that show a stub's placeholder.
struct SceneDifference {
  size_t failing = 0, todo = 0;
};
SceneDifference differenceNear(const FloatImage& ref, const FloatImage& got, float tolerance) {
  SceneDifference d;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const float g = got.at(x, y);
      if (isTodo(g)) {
        ++d.todo;
        continue;
      }
      bool near = false;
      for (int dy = -1; dy <= 1 && !near; ++dy)
        for (int dx = -1; dx <= 1 && !near; ++dx) {
          const int sx = std::clamp(x + dx, 0, ref.width - 1), sy = std::clamp(y + dy, 0, ref.height - 1);
          near = std::abs(g - ref.at(sx, sy)) <= tolerance;
        }
      d.failing += !near;
    }
  return d;
}

}  // namespace

void expectSceneMatchesGolden(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                              float tolerance, double maxFailingFraction) {
  const fs::path out = outputDir() / ("Ex" + id + "_" + name);
  const fs::path golden = dataFile(name + ".pfm", fs::path("tests/golden") / variant::kLab, "golden");
  const fs::path pfm = out / "result.pfm";
  FloatImage got, ref;
  RunResult run;
  if (const std::string why = renderScene(id, out, pfm, args, got, run); !why.empty()) FAIL() << why;
  if (updatingGolden()) return updateGolden(pfm, golden);
  if (const std::string why = referenceFor(out, golden, args, id, ref); !why.empty()) FAIL() << why;
  if (ref.width != got.width || ref.height != got.height) FAIL() << "ERROR: golden " << golden << " has another size";
  const SceneDifference d = differenceNear(ref, got, tolerance);
  const double fraction = double(d.failing + d.todo) / double(ref.pixels.size());
  if (d.todo && fraction > maxFailingFraction) {  // a stub's stripes: no number, which would be the stubs'
    std::printf("[ scene    ] %s %s: not compared: %zu pixels show the not-implemented placeholder\n", id.c_str(),
                name.c_str(), d.todo);
    FAIL() << placeholderVerdict(id, name, run, "compared");
  }
  std::printf("[ scene    ] %s %s: %.3f%% of pixels differ from %s (allowed %.3f%%)\n", id.c_str(), name.c_str(),
              100 * fraction, golden.filename().string().c_str(), 100 * maxFailingFraction);
  if (fraction <= maxFailingFraction) return;
  const std::string legend = "red: shadowed where the reference is lit; blue: lit where it is shadowed";
  writeScenePanels(out / "panels.png", ref.width, ref.height, toGrey(ref), toGrey(got), diffImage(ref, got, tolerance),
                   "difference: " + legend);
  char pct[64];
  std::snprintf(pct, sizeof pct, "%.2f%% of pixels (allowed %.2f%%)", 100 * fraction, 100 * maxFailingFraction);
  FAIL() << "WRONG: visibility in scene '" << name << "' differs from the reference on " << pct
         << "\n  picture: " << (out / "panels.png").string() << " (reference, yours, difference: " << legend << ")";
}

}  // namespace wb::test
