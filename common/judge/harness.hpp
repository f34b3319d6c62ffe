/// @file harness.hpp
/// What every lab's tests use. Failure messages start with one of three words that `check` and the
/// grader classify: "NOT IMPLEMENTED" (a stub), "WRONG" (a bad answer), "ERROR" (it did not run).
#pragma once
#include "common/base/error.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/tape.hpp"
#include "common/platform/image.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace wb::test {

/// Fixture for tests that need GL: one headless EGL context per process; fails on KHR_debug errors.
class GlTest : public ::testing::Test {
 public:
  /// Creates the shared context on first use and records GL_RENDERER as a test property.
  static void SetUpTestSuite();

 protected:
  /// Fails the test if the GL reported errors during it.
  void TearDown() override;
};

/// GL_RENDERER of the shared test context.
std::string renderer();
/// True when the test binary runs with --update-golden (regenerating the golden data).
bool updatingGolden();

/// Runs GLSL exercise `id` (isolated: the other exercises come from the solution when it exists)
/// in a compute kernel; see wb::runGlslKernel for `body`, `stride` and `textures`. Throws
/// wb::Error on a compile error.
std::vector<glm::vec4> runExercise(const std::string& id, const std::string& body, int count, int stride,
                                   const std::vector<glm::vec4>& inputs, const std::vector<unsigned>& textures = {});

/// A GLSL exercise whose kernel runs far longer than the reference's on the same inputs (an endless
/// loop, which the loop guard cuts off after 50000 steps and a GPU would hang on): WRONG.
struct SlowShader : wb::Error {
  using wb::Error::Error;
};
/// How much longer than the reference a kernel may run.
constexpr double kSlowShaderFactor = 20.0;
/// The time (ms) below which a kernel never counts as slow.
constexpr double kSlowShaderFloorMs = 2.0;

/// While it lives, this process's shaders (wb::Program, wb::shaderSearchPath) are exercise `id`'s
/// isolated GLSL: the submission's chunk of `id` and the solution's other chunks, in every GLSL
/// exercise file (exercise.glsl and stage files such as a .geom), written under the test outputs.
/// For tests that build the lab's own programs in the test process. `text(file)` is what was written.
class IsolatedShaders {
 public:
  explicit IsolatedShaders(const std::string& id);  ///< isolates exercise `id` until destroyed
  ~IsolatedShaders();
  IsolatedShaders(const IsolatedShaders&) = delete;
  IsolatedShaders& operator=(const IsolatedShaders&) = delete;
  /// The isolated text of GLSL exercise file `file` (e.g. "exercise_layered.geom").
  std::string text(const std::string& file) const;

 private:
  std::filesystem::path dir_;
  std::string previous_;
  bool hadPrevious_ = false;
};

/// Runs a C++ exercise call; a wb::NotImplemented becomes a "NOT IMPLEMENTED" failure.
#define WB_TRY_EXERCISE(statement)                       \
  try {                                                  \
    statement;                                           \
  } catch (const wb::NotImplemented& e) {                \
    FAIL() << e.what();                                  \
  } catch (const wb::test::RunnerStopped& e) {           \
    FAIL() << "ERROR: " << e.what();                     \
  } catch (const std::exception& e) {                    \
    FAIL() << "ERROR: the exercise threw: " << e.what(); \
  }

/// Runs a GLSL exercise kernel into `results`; a compile error or WB_TODO output ends the test.
#define WB_RUN_GLSL(results, ...)                   \
  try {                                             \
    results = ::wb::test::runExercise(__VA_ARGS__); \
  } catch (const ::wb::test::SlowShader& e) {       \
    FAIL() << e.what();                             \
  } catch (const std::exception& e) {               \
    FAIL() << "ERROR: " << e.what();                \
  }                                                 \
  if (::wb::anyTodo(results)) FAIL() << "NOT IMPLEMENTED: the GLSL function still returns WB_TODO";

/// Lab arguments for a scene test: `--set` for each "key=value", and `--scene scenes/SCENE` when given
/// (a held-out scene, "hidden/NAME.json", is read from the instructor-only tests/hidden/LAB/scenes).
std::vector<std::string> labArgs(const std::vector<std::string>& settings, const std::string& scene = "");

/// A runner's answer to a judge's plan (held-out tests, which are not in the runner): records each
/// request in `requests` (JSON lines: what the judge's planning pass, WB_PLAN=FILE, wrote) on the
/// tape, under the judge's keys: a lab run ({"key", "args"}) or a call of a WB_CALLABLE exercise
/// ({"key", "call", "inputs"}). Returns the exit code for main().
int recordRequestedRuns(const std::filesystem::path& requests);

/// The folder this test binary writes its outputs to (WB_TEST_OUTPUT_DIR when set), for a test that
/// names files of its own (--dump-visibility).
std::filesystem::path testOutputDir();

/// Runs the lab headless for exercise `id` (isolated as in expectSceneMatchesGolden()) with `args`
/// and returns its output; `failure` is set ("ERROR: …" or "NOT IMPLEMENTED: …") if it did not run.
std::string runLabOutput(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                         std::string& failure);

/// Acne, leak and contact gap of one headless run (`--metrics`) of exercise `id`, isolated as in
/// expectSceneMatchesGolden(); `failure` is set ("ERROR: …" or "NOT IMPLEMENTED: …") if it did not run.
struct SceneMetrics {
  double acnePercent = -1;         ///< acne rate, in percent
  double leakPercent = -1;         ///< light leak, in percent
  double gapTexels = -1;           ///< contact gap in texels (-1 when not measured)
  double areaMeanAbsPercent = -1;  ///< against the area light (-1 when the light has no size)
  double areaOffPercent = -1;      ///< the share off by more than 0.1 (-1 when not measured)
  double seamErrorPercent = -1;    ///< a cube map against its own lookups with rays, near face edges (-1: none)
  double restErrorPercent = -1;    ///< the same, away from the face edges
  std::vector<std::array<double, 4>> penumbra;  ///< distance, theory, rendered, reference widths
  std::string failure;                          ///< empty when the run worked
};
/// Runs the lab at 480x270 with `--metrics` and `args`; see SceneMetrics.
SceneMetrics measureScene(const std::string& id, const std::string& name, const std::vector<std::string>& args);

/// How fast the rendered penumbra grows with the receiver-blocker distance, over how fast the
/// theory's does: the ratio of their least-squares slopes over the slabs of `m.penumbra` whose
/// distance was measured (1 is the theory). A slab where the probe's ray found no blocker (distance
/// 0, which a turn of the light by the grader's variation can cause) would pull the slope towards 0.
double penumbraGrowthRatio(const SceneMetrics& m);

/// Layer 2: renders a golden case with the lab itself (`--headless --size 256x256` plus `args`),
/// with exercise `id` isolated, and compares its visibility with tests/golden/LAB/NAME.pfm (a
/// held-out case, `name` = "hidden/NAME", with tests/hidden/LAB/golden/NAME.pfm).
/// A pixel fails when no reference pixel in its 3x3 neighbourhood is within `tolerance`; the test fails when more than
/// `maxFailingFraction` of pixels fail. On failure it writes reference, result and diff PNGs.
void expectSceneMatchesGolden(const std::string& id, const std::string& name, const std::vector<std::string>& args,
                              float tolerance, double maxFailingFraction);

}  // namespace wb::test
