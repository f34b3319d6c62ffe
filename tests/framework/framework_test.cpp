// The framework's promises to students and lecturers: bad input gets a clear message and the right
// exit code, never a crash; compiler errors name the original file and line; a broken shader edit
// keeps the last good program.
#include "common/base/settings.hpp"
#include "common/base/variant.hpp"
#include "common/exercise/crash_report.hpp"
#include "common/exercise/exercise_board.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/exercise_source_rules.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/exercise/run_record.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/shader.hpp"
#include "common/platform/texture_io.hpp"
#include "common/scene/scene.hpp"
#include "common/shadows/prefilter.hpp"
#include "common/truth/ground_truth.hpp"

#include <pthread.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  fs::path dir = wb::test::testOutputDir() / name;  // (WB_TEST_OUTPUT_DIR: a second run's own folder)
  fs::create_directories(dir);
  return dir;
}

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// Loads a scene and returns the error message ("" if it loaded).
std::string sceneError(const std::string& json) {
  const fs::path p = scratch("scenes") / "scene.json";
  writeFile(p, json);
  try {
    wb::Scene::load(p);
  } catch (const wb::UsageError& e) {
    return e.what();
  }
  return "";
}

struct LabResult {
  int code;
  std::string output;
};

// Runs the sample lab with `args` and no display; captures its exit code and output.
LabResult runLab(const std::string& args, const std::string& exe = wb::variant::kLabExe) {
  // One log per test: ctest runs the tests of this file in parallel processes.
  const fs::path log =
      scratch("cli") / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".log");
  const std::string cmd = "cd " + scratch("cli").string() + " && env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 " + exe +
                          " " + args + " >" + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::ostringstream s;
  s << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), s.str()};
}

}  // namespace

TEST(Scene, ErrorsNameTheFileTheFieldAndTheReason) {
  EXPECT_NE(sceneError(R"({"objects": [)").find("not valid JSON"), std::string::npos);
  EXPECT_NE(sceneError(R"({"lights": [{}]})").find("objects: missing"), std::string::npos);
  const std::string shape = sceneError(R"({"objects": [{"shape": "cube"}], "lights": [{}]})");
  EXPECT_NE(shape.find("scene.json: objects[0].shape: unknown shape 'cube'"), std::string::npos) << shape;
  const std::string vec = sceneError(R"({"objects": [{"shape": "box", "position": [1, 2]}], "lights": [{}]})");
  EXPECT_NE(vec.find("objects[0].position: must be [x, y, z]"), std::string::npos) << vec;
  const std::string light = sceneError(R"({"objects": [{"shape": "box"}], "lights": [{"type": "area"}]})");
  EXPECT_NE(light.find("lights[0].type: unknown light type 'area'"), std::string::npos) << light;
  const std::string tex = sceneError(R"({"objects": [{"shape": "plane", "texture": "nope.png"}], "lights": [{}]})");
  EXPECT_NE(tex.find("objects[0].texture: file"), std::string::npos) << tex;
  EXPECT_NE(sceneError(R"({"objects": [{"shape": "sphere", "radius": -1}], "lights": [{}]})")
                .find("radius: must be greater than 0"),
            std::string::npos);
  // Lab 07's fields: a light's size (spot lights only, not negative) and the penumbra probe.
  const std::string size = sceneError(R"({"objects": [{"shape": "box"}], "lights": [{"type": "spot", "size": -1}]})");
  EXPECT_NE(size.find("lights[0].size: a light's size"), std::string::npos) << size;
  const std::string sun = sceneError(R"({"objects": [{"shape": "box"}], "lights": [{"size": 0.5}]})");
  EXPECT_NE(sun.find("only spot lights have one"), std::string::npos) << sun;
  const std::string probe =
      sceneError(R"({"objects": [{"shape": "box"}], "lights": [{}], "penumbra_probe": {"x": [1, 0], "z": [0, 1]}})");
  EXPECT_NE(probe.find("penumbra_probe.x: must be [lo, hi]"), std::string::npos) << probe;
  const std::string bins = sceneError(
      R"({"objects": [{"shape": "box"}], "lights": [{}], "penumbra_probe": {"x": [0, 1], "z": [0, 1], "bins": 0}})");
  EXPECT_NE(bins.find("penumbra_probe.bins: must be 1 to 100"), std::string::npos) << bins;
}

TEST(Scene, TheCanonicalSceneLoadsWithBoundsAndBookmarks) {
  const wb::Scene s = wb::Scene::load(fs::path(wb::variant::kSourceDir) / "scenes/depth_map.json");
  EXPECT_GE(s.objects.size(), 8u);  // the tree expands into a trunk and a canopy
  EXPECT_EQ(s.lights.size(), 2u);
  EXPECT_GE(s.cameras.size(), 2u);
  EXPECT_NEAR(s.boundsMin.y, 0, 1e-5);                   // everything stands on the ground plane
  EXPECT_NEAR(s.boundsMax.x - s.boundsMin.x, 16, 1e-4);  // the 16 m ground sets the width
}

TEST(Settings, AssignChecksNamesTypesAndRanges) {
  wb::Settings s;
  float f = 0.5f;
  int i = 1, c = 0;
  bool b = false;
  s.add("a.float", f, 0, 1, "");
  s.add("a.int", i, 0, 4, "");
  s.add("a.bool", b, "");
  s.addChoice("a.choice", c, {"x", "y"}, "");
  s.assign("a.float=0.25");
  s.assign("a.int=3");
  s.assign("a.bool=on");
  s.assign("a.choice=y");
  EXPECT_EQ(f, 0.25f);
  EXPECT_EQ(i, 3);
  EXPECT_TRUE(b);
  EXPECT_EQ(c, 1);
  EXPECT_THROW(s.assign("a.float=2"), wb::UsageError);
  EXPECT_THROW(s.assign("a.int=1.5"), wb::UsageError);
  EXPECT_THROW(s.assign("a.choice=z"), wb::UsageError);
  EXPECT_THROW(s.assign("nope=1"), wb::UsageError);
  EXPECT_THROW(s.assign("a.int"), wb::UsageError);
}

TEST(Shader, IncludesAreExpandedAndErrorsMapToTheOriginalFileAndLine) {
  const fs::path dir = scratch("include");
  writeFile(dir / "inc.glsl", "// line 1\nfloat helper() { return 1.0; }\n");
  const std::string main = "#version 410 core\n#include \"inc.glsl\"\nvoid main() {}\n";
  const wb::ShaderSource src = wb::preprocessShader(main, dir / "main.comp", "#define X 1\n", {dir});
  ASSERT_EQ(src.files.size(), 2u);
  EXPECT_EQ(src.files[1], dir / "inc.glsl");
  EXPECT_NE(src.text.find("#define X 1"), std::string::npos);
  EXPECT_NE(src.text.find("float helper()"), std::string::npos);
  const std::string mapped = wb::mapShaderLog("1:2(7): error: syntax error\n", src.files);
  EXPECT_NE(mapped.find((dir / "inc.glsl").string() + ":2: error"), std::string::npos) << mapped;
  EXPECT_THROW(wb::preprocessShader("#include \"missing.glsl\"\n", dir / "x", "", {dir}), wb::Error);
}

// Mesa names some errors in an included file by the top file's number, with the right line (seen
// with lab 07's nested includes: "0:26(10): error: `zReceiverr' undeclared" for exercise.glsl:26).
// The name the message quotes shows which file is meant; a message without one on the same line
// follows it, and a name that only the named file holds leaves it alone.
TEST(Shader, AnErrorNamedByTheTopFileIsPutWhereItsNameIs) {
  const fs::path dir = scratch("misnamed");
  writeFile(dir / "scene.frag", "#version 410 core\nuniform float zReceiver;\nvoid main() {}\n");
  writeFile(dir / "exercise.glsl", "// helpers\nfloat f() { return 1.0; }\nfloat g() { return zReceiverr; }\n");
  const std::vector<fs::path> files = {dir / "scene.frag", dir / "exercise.glsl"};
  const std::string mapped = wb::mapShaderLog(
      "0:3(20): error: `zReceiverr' undeclared\n0:3(20): error: operands to arithmetic operators must be numeric\n"
      "0:2(15): error: `zReceiver' redeclared\n",
      files);
  EXPECT_NE(mapped.find((dir / "exercise.glsl").string() + ":3: error: `zReceiverr' undeclared"), std::string::npos)
      << mapped;
  EXPECT_NE(mapped.find((dir / "exercise.glsl").string() + ":3: error: operands"), std::string::npos) << mapped;
  EXPECT_NE(mapped.find((dir / "scene.frag").string() + ":2: error: `zReceiver' redeclared"), std::string::npos)
      << mapped;
}

// A broken edit keeps the last good program and reports file:line; fixing it rebuilds.
using wb::test::GlTest;
TEST_F(GlTest, HotReloadKeepsTheLastGoodProgram) {
  const fs::path dir = scratch("reload");
  const fs::path file = dir / "reload_test.vert";
  const std::string good = "#version 410 core\n// a vertex shader\nvoid main() { gl_Position = vec4(0.0); }\n";
  writeFile(file, good);
  setenv("WB_SHADER_OVERLAY", dir.c_str(), 1);
  wb::Program p = wb::Program::tryLoad({{GL_VERTEX_SHADER, "reload_test.vert"}});
  ASSERT_TRUE(p.ok()) << p.error();
  const GLuint first = p.id();
  writeFile(file, "#version 410 core\n// a vertex shader\nvoid main() { oops }\n");
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  EXPECT_FALSE(p.reloadIfChanged());
  EXPECT_EQ(p.id(), first) << "the last good program must stay in use";
  EXPECT_NE(p.error().find(file.string() + ":3"), std::string::npos) << p.error();
  writeFile(file, good);
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(4));
  EXPECT_TRUE(p.reloadIfChanged());
  EXPECT_TRUE(p.error().empty());
  unsetenv("WB_SHADER_OVERLAY");
}

// An edit that breaks one exercise's chunk keeps that chunk's last good text and the other
// exercises' current ones: a student who improves 99.1 and breaks 99.2 in one save sees the new
// 99.1, and the panel says what is drawn (common/exercise/exercise_chunks.hpp).
namespace {
// Draws `p` (a full-screen triangle whose fragment shader writes (v0, v1, 0, 1)) into one texel,
// and returns v0 and v1.
std::pair<float, float> runTwoValues(const wb::Program& p) {
  const wb::Texture texel = wb::makeTexture2D(GL_RGBA32F, 1, 1);
  const wb::Framebuffer target = wb::makeFramebuffer({texel.id()}, 0);
  const wb::VertexArray triangle = wb::makeEmptyVertexArray();
  wb::BoundFramebuffer into(target.id());
  wb::BoundVertexArray draw(triangle.id());
  glViewport(0, 0, 1, 1);
  glDisable(GL_DEPTH_TEST);
  p.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  float v[4] = {0, 0, 0, 0};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, v);
  return {v[0], v[1]};
}
void touch(const fs::path& file, const std::string& text, int seconds) {
  writeFile(file, text);
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(seconds));
}
}  // namespace

TEST_F(GlTest, HotReloadKeepsTheBrokenExercisesLastGoodChunk) {
  const fs::path dir = scratch("chunks");
  writeFile(dir / "chunks_test.frag",
            "#version 410 core\nout vec4 o_value;\n"
            "#include \"chunks.glsl\"\nvoid main() { o_value = vec4(first(), second(), 0.0, 1.0); }\n");
  const fs::path chunks = dir / "chunks.glsl";
  writeFile(chunks,
            "float helper() { return 1.0; }\n// EXERCISE 99.1\nfloat first() { return helper(); }\n"
            "// EXERCISE 99.2\nfloat second() { return -1e30; } // WB_TODO\n");
  setenv("WB_SHADER_OVERLAY", dir.c_str(), 1);
  wb::Program p =
      wb::Program::tryLoad({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "chunks_test.frag"}}, {},
                           &wb::exerciseSourceRules());
  ASSERT_TRUE(p.ok()) << p.error();
  EXPECT_EQ(runTwoValues(p), std::make_pair(1.0f, -1e30f));
  // 99.1 improved, 99.2 broken (line 5), in one save.
  touch(chunks,
        "float helper() { return 1.0; }\n// EXERCISE 99.1\nfloat first() { return 3.0; }\n"
        "// EXERCISE 99.2\nfloat second() { return oops; }\n",
        2);
  EXPECT_TRUE(p.reloadIfChanged()) << "the current 99.1 with the last good 99.2 compiles: " << p.error();
  EXPECT_NE(p.error().find(chunks.string() + ":5"), std::string::npos) << p.error();
  EXPECT_EQ(p.fallback(),
            "drawn with your last 99.2 that compiled (still the stub: stripes) and your current other exercises");
  EXPECT_EQ(runTwoValues(p), std::make_pair(3.0f, -1e30f)) << "the new 99.1, the last good 99.2";
  // 99.2 fixed: everything is current, and nothing is said.
  touch(chunks,
        "float helper() { return 1.0; }\n// EXERCISE 99.1\nfloat first() { return 3.0; }\n"
        "// EXERCISE 99.2\nfloat second() { return 5.0; }\n",
        4);
  EXPECT_TRUE(p.reloadIfChanged()) << p.error();
  EXPECT_TRUE(p.error().empty() && p.fallback().empty());
  EXPECT_EQ(runTwoValues(p), std::make_pair(3.0f, 5.0f));
  // The helpers above the first marker broken: they go back alone, and the line numbers of the
  // chunks below stay the file's (an error further down would still name its own line).
  touch(chunks,
        "float helper() { return 2.0 }\n// EXERCISE 99.1\nfloat first() { return helper(); }\n"
        "// EXERCISE 99.2\nfloat second() { return 5.0; }\n",
        6);
  EXPECT_TRUE(p.reloadIfChanged()) << p.error();
  EXPECT_EQ(p.fallback(),
            "drawn with your last helpers that compiled (above the first exercise) and your current "
            "exercises");
  EXPECT_EQ(runTwoValues(p), std::make_pair(1.0f, 5.0f));
  unsetenv("WB_SHADER_OVERLAY");
}

// A run may replay some exercises (the reference's results) and record the others (check's runner,
// common/judge/reference_calls.hpp): an exercise recorded during the run is never replayed from
// its own first call, and the saved file holds only what was recorded.
TEST(ExerciseTape, ReplaysSomeExercisesAndRecordsTheOthers) {
  const fs::path dir = scratch("tape");
  writeFile(dir / "reference.json",
            R"({"calls": {"10.2": [{"state": "implemented", "message": "", "value": [1, 2]}]}})");
  wb::ExerciseTape tape;
  tape.startReplay(dir / "reference.json");
  tape.startRecording(dir / "recorded.json");
  EXPECT_TRUE(tape.replays("10.2"));
  EXPECT_FALSE(tape.replays("10.1"));
  tape.add("10.1", {wb::ExerciseState::Implemented, "", nullptr});  // a probe's call, then the real one
  EXPECT_FALSE(tape.replays("10.1")) << "10.1 is recorded in this run, not replayed from its own calls";
  tape.add("10.1", {wb::ExerciseState::Implemented, "", nlohmann::json::array({3, 4})});
  EXPECT_EQ(tape.next("10.2").value, nlohmann::json::array({1, 2}));
  tape.save();
  const auto saved = nlohmann::json::parse(wb::readFile(dir / "recorded.json"));
  EXPECT_EQ(saved.at("calls").size(), 1u) << saved.dump();
  EXPECT_EQ(saved.at("calls").at("10.1").size(), 2u) << saved.dump();
}

// The exercise panel's probes: a chunk that does not compile marks its own exercise failed, and the
// others are probed with its last good text in its place (a syntax error in 09.3 had marked 09.2
// "error" in the window too).
TEST_F(GlTest, ExerciseBoardMarksOnlyTheChunkThatDoesNotCompile) {
  const fs::path dir = scratch("board"), file = dir / "exercise.glsl";
  const std::string good = wb::readFile(fs::path(wb::variant::kLabDir) / "shaders/exercise.glsl");
  writeFile(file, good);
  setenv("WB_SHADER_OVERLAY", dir.c_str(), 1);
  wb::ExerciseBoard board(fs::path(wb::variant::kLabDir) / "exercises.json");
  board.addProbe("01.3", "exercise.glsl", "worldToShadowCoord(mat4(1.0), vec3(0.0)).x");
  board.addProbe("01.4", "exercise.glsl", "hardShadow(wb_tex0, vec3(0.5), 0.0)");
  board.addProbe("01.5", "exercise.glsl", "casterCoverage(wb_tex0, vec2(0.5), 0.5)");
  board.probe();
  for (const char* id : {"01.3", "01.4", "01.5"}) ASSERT_NE(board.stateOf(id), wb::ExerciseState::Failed) << id;
  std::string broken = good;  // a syntax error on the first line of 01.4's function
  const size_t brace = broken.find('{', wb::chunkRange(broken, "01.4").first);
  broken.insert(brace + 1, "\n  float oops = ;");
  touch(file, broken, 2);
  board.probe();
  EXPECT_EQ(board.stateOf("01.4"), wb::ExerciseState::Failed);
  const int line = 1 + int(std::count(broken.begin(), broken.begin() + long(brace), '\n')) + 1;
  for (const auto& e : board.exercises()) {  // its own message: the line of the typo
    if (e.id != "01.4") continue;
    EXPECT_NE(e.message.find("exercise.glsl:" + std::to_string(line) + ": error"), std::string::npos) << e.message;
  }
  EXPECT_NE(board.stateOf("01.3"), wb::ExerciseState::Failed) << "01.3's chunk compiles: it is not 01.4's error";
  EXPECT_NE(board.stateOf("01.5"), wb::ExerciseState::Failed) << "01.5's chunk compiles: it is not 01.4's error";
  unsetenv("WB_SHADER_OVERLAY");
}

// The lab command line: bad input gets one clear line and exit code 2, no display exit code 3.
TEST(CommandLine, BadInputGetsAClearMessageAndExitCode2) {
  struct Case {
    std::string args, expect;
  } cases[] = {
      {"--bogus", "unknown option '--bogus'"},
      {"--headless --scene missing.json", "scene file 'missing.json' not found"},
      {"--headless --set shadow.map_size=16384", "bad value '16384' for shadow.map_size"},
      {"--headless --set nope=1", "unknown setting 'nope'"},
      {"--headless --size 12x", "bad --size '12x'"},
      {"--headless --frames 0", "bad --frames '0'"},
      {"--headless --set light.index=5", "has 2 light(s)"},
      {"--headless --scene " + std::string(wb::variant::kSourceDir) + "/scenes", "is a folder, not a scene file"},
      {"--headless --screenshot shot.gif", "name a .png or .jpg file"},
      {"--headless --set camera.bookmark=8", "camera bookmark(s), 1 to"},
      {"--headless --set camera.bookmark=0", "bad value '0' for camera.bookmark"},
  };
  for (const auto& c : cases) {
    const LabResult r = runLab(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
  }
  const fs::path bad = scratch("cli") / "malformed.json";
  writeFile(bad, R"({"objects": [{"shape": "box", "size": "big"}], "lights": [{}]})");
  const LabResult r = runLab("--headless --scene " + bad.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("objects[0].size: must be [x, y, z]"), std::string::npos) << r.output;
}

// A screenshot is written in the format its name says.
TEST(CommandLine, AJpgScreenshotIsAJpeg) {
  const fs::path shot = scratch("cli") / "shot.jpg";
  const LabResult r = runLab("--headless --frames 1 --screenshot " + shot.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(shot, std::ios::binary);
  unsigned char magic[3] = {};
  in.read(reinterpret_cast<char*>(magic), 3);
  EXPECT_TRUE(magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF) << "not JPEG bytes";
}

// A stub's line says it once: "... is not implemented yet: f is still the stub".
TEST(CommandLine, AStubIsNamedOnce) {
  const LabResult r = runLab("--headless --frames 1 --screenshot " + (scratch("cli") / "stub.png").string());
  EXPECT_EQ(r.output.find("not implemented yet: NOT IMPLEMENTED"), std::string::npos) << r.output;
}

TEST(CommandLine, NoDisplayExplainsAndOffersHeadless) {
  const LabResult r = runLab("");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("--headless"), std::string::npos) << r.output;
}

TEST(CommandLine, HeadlessRunWritesTheRequestedFiles) {
  const fs::path dir = scratch("cli");
  const LabResult r =
      runLab("--headless --size 64x48 --screenshot shot.png --dump-visibility vis.pfm --bench bench.csv --frames 3");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "shot.png"));
  const wb::FloatImage vis = wb::readPfm(dir / "vis.pfm");
  EXPECT_EQ(vis.width, 64);
  EXPECT_EQ(vis.height, 48);
  EXPECT_NE(r.output.find("fps"), std::string::npos) << r.output;
}

// The machine-readable channel: tests and the grader read the --record JSON, never the text for
// people. With --quiet that text is gone from stdout, and the record still carries every exercise
// state (the stubs of this edition) and every measurement, so rewording the text breaks nothing.
TEST(RunRecord, CarriesEverythingWithoutTheTextForPeople) {
  const fs::path record = scratch("cli") / "stubs.json";
  const LabResult r = runLab("--headless --quiet --size 64x48 --record " + record.string());
  EXPECT_EQ(r.code, 0) << r.output;
  std::istringstream lines(r.output);  // only stderr's notes about unfinished exercises remain
  for (std::string l; std::getline(lines, l);)
    EXPECT_TRUE(l.rfind("Exercise ", 0) == 0 || l.rfind("Next: exercise ", 0) == 0)
        << "--quiet printed text for people: " << l;
  const wb::RunResult run = wb::readRunRecord(record);
  EXPECT_EQ(run.status, "ok");
  EXPECT_GE(run.exerciseStates.size(), 5u);
  for (const auto& [id, state] : run.exerciseStates)
    EXPECT_TRUE(state == "not_implemented" || state == "implemented") << id << ": " << state;
  if (*wb::variant::kSolutionDir) {  // (the repo's labs are the stubs; a student's may be done)
    EXPECT_EQ(run.exerciseStates.at("01.4"), "not_implemented") << "the repo's 01.4 is a stub";
  }
  if (!*wb::variant::kSolutionExe) return;
  const fs::path measured = scratch("cli") / "measured.json";
  const LabResult m =
      runLab("--headless --quiet --metrics --size 160x90 --record " + measured.string(), wb::variant::kSolutionExe);
  EXPECT_EQ(m.code, 0) << m.output;
  EXPECT_EQ(m.output.find("acne"), std::string::npos) << m.output;
  const wb::RunResult sol = wb::readRunRecord(measured);
  ASSERT_TRUE(sol.acnePercent && sol.leakPercent && sol.gapTexels) << "measurements missing from the record";
  EXPECT_GE(*sol.acnePercent, 0);
  EXPECT_LE(*sol.leakPercent, 100);
  for (const auto& [id, state] : sol.exerciseStates) EXPECT_EQ(state, "implemented") << id;
}

// The record names the OpenGL it ran on. Where Mesa is capped at 4.1 core as on a Mac (what
// ./workbook test and CI do), the lab really ran on 4.1: the suite's pass means something there.
TEST(RunRecord, NamesTheOpenGLVersionItRanOn) {
  const fs::path record = scratch("cli") / "version.json";
  const LabResult r = runLab("--headless --quiet --size 64x48 --frames 1 --record " + record.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(record);
  const std::string version = nlohmann::json::parse(in).value("gl_version", std::string());
  EXPECT_EQ(version.rfind("4.", 0), 0u) << "gl_version: '" << version << "'";
  const char* cap = std::getenv("MESA_GL_VERSION_OVERRIDE");
  if (cap && std::string(cap).rfind("4.1", 0) == 0) {  // (4.1, or 4.1FC: forward-compatible, as macOS gives)
    EXPECT_EQ(version.rfind("4.1 ", 0), 0u) << "Mesa was capped at 4.1, and the lab ran on " << version;
  }
}

// A failed run says so in its record too, with the message people see.
TEST(RunRecord, AFailedRunRecordsWhy) {
  const fs::path record = scratch("cli") / "failed.json";
  const LabResult r = runLab("--headless --set nope=1 --record " + record.string());
  EXPECT_EQ(r.code, 2) << r.output;
  const wb::RunResult run = wb::readRunRecord(record);
  EXPECT_EQ(run.status, "usage_error");
  EXPECT_NE(run.error.find("nope"), std::string::npos) << run.error;
  const fs::path early = scratch("cli") / "unknown_option.json";  // the parser itself failed
  EXPECT_EQ(runLab("--record " + early.string() + " --bogus").code, 2);
  EXPECT_NE(wb::readRunRecord(early).error.find("--bogus"), std::string::npos);
}

// Exact visibility against geometry worked out by hand: a unit box [-0.5,0.5] x [0,1] x [-0.5,0.5]
// on the ground, lit by a directional light travelling along (1,-1,0) (45 degrees). A ground point
// (x, 0, z) sends its shadow ray along (-1,1,0); it meets the box iff |z| < 0.5 and -0.5 < x < 1.5
// (the ray climbs one unit per unit of x, and the box is one unit tall). The box's top is lit.
TEST(GroundTruth, ExactVisibilityOfABoxOnTheGround) {
  const fs::path file = scratch("scenes") / "box.json";
  writeFile(file, R"({"objects": [{"shape": "plane", "size": [10, 0, 10]},
                                   {"shape": "box", "size": [1, 1, 1], "position": [0, 0.5, 0]}],
                      "lights": [{"type": "directional", "direction": [1, -1, 0]}]})");
  const wb::Scene scene = wb::Scene::load(file);
  const wb::RayScene rays(scene, 0.5f);
  struct Probe {
    glm::vec3 p;
    float expected;
  } probes[] = {{{1.4f, 0, 0}, 0},    {{1.6f, 0, 0}, 1},       {{-0.6f, 0, 0}, 1}, {{0.9f, 0, 0.4f}, 0},
                {{0.9f, 0, 0.6f}, 1}, {{0.2f, 1.0f, 0.1f}, 1}, {{3, 0, -2}, 1}};
  std::vector<glm::vec4> positions;
  for (const auto& pr : probes) positions.emplace_back(pr.p, 1);
  positions.emplace_back(0, 0, 0, 0);   // background: not measured
  positions.emplace_back(2, 0, 0, -1);  // facing away from the light: shadowed
  const wb::FloatImage exact = wb::exactVisibility(rays, scene.lights[0], int(positions.size()), 1, positions);
  for (size_t i = 0; i < std::size(probes); ++i)
    EXPECT_EQ(exact.pixels[i], probes[i].expected)
        << "point (" << probes[i].p.x << ", " << probes[i].p.y << ", " << probes[i].p.z << ")";
  EXPECT_TRUE(std::isnan(exact.pixels[std::size(probes)]));
  EXPECT_EQ(exact.pixels[std::size(probes) + 1], 0);
}

// Acne counts lit pixels drawn shadowed; leaks count shadowed pixels drawn lit.
TEST(GroundTruth, MetricsCountAcneAndLeaks) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const wb::FloatImage exact{6, 1, {1, 1, 1, 0, 0, nan}}, rendered{6, 1, {1, 0, 1, 0, 1, 0}};
  const std::vector<glm::vec4> pos(6, glm::vec4(0, 0, 0, 1));
  const wb::VisibilityMetrics m = wb::compareVisibility(rendered, exact, pos);
  EXPECT_EQ(m.litPixels, 3);
  EXPECT_EQ(m.acnePixels, 1);
  EXPECT_EQ(m.shadowedPixels, 2);
  EXPECT_EQ(m.leakPixels, 1);
  EXPECT_NEAR(m.acneRate(), 1.0 / 3, 1e-12);
  EXPECT_NEAR(m.leakRate(), 0.5, 1e-12);
}

// The area ratio counts the drawn shadow against the exact one; acne and leaks within kRimPixels of
// an exact edge are on the rim, and only those beyond it count as wrong outside the rim.
TEST(GroundTruth, AreaRatioAndTheRim) {
  // 12 x 1: lit, then a shadow from x = 6 on (one edge, between x = 5 and 6).
  wb::FloatImage exact{12, 1, std::vector<float>(12, 1.0f)};
  for (int x = 6; x < 12; ++x) exact.pixels[size_t(x)] = 0;
  wb::FloatImage rendered = exact;
  rendered.pixels[0] = 0;   // acne 5 px from the edge: beyond the rim (edge pixels 5, 6; 2 px more: 3..8)
  rendered.pixels[6] = 1;   // a leak on the edge: on the rim
  rendered.pixels[11] = 1;  // a leak 5 px from the edge: beyond the rim
  const std::vector<glm::vec4> pos(12, glm::vec4(0, 0, 0, 1));
  const wb::VisibilityMetrics m = wb::compareVisibility(rendered, exact, pos);
  EXPECT_EQ(m.rimPixels, 6);
  EXPECT_EQ(m.wrongOutsideRim, 2);
  EXPECT_NEAR(m.wrongOutsideRimRate(), 2.0 / 6, 1e-12);
  EXPECT_NEAR(m.areaRatio(), (1.0 + 6 - 2) / 6, 1e-12);  // acne adds a pixel, the leaks take two
  EXPECT_EQ(wb::compareVisibility(exact, exact, pos).areaRatio(), 1.0);
}

// The measurement sees the trade-off the handouts teach: no bias, heavy acne; the default bias,
// almost none; a large bias, more light leaking (peter-panning) than the default.
TEST(GroundTruth, TheSolutionsAcneAndLeaksFollowTheBias) {
  if (!*wb::variant::kSolutionExe) GTEST_SKIP() << "no solution build in this edition";
  auto rates = [](const std::string& bias) {
    const fs::path record = scratch("cli") / ("bias_" + bias + ".json");
    const LabResult r =
        runLab("--headless --size 320x180 --metrics --record " + record.string() + " --set shadow.bias=" + bias,
               wb::variant::kSolutionExe);
    EXPECT_EQ(r.code, 0) << r.output;
    const wb::RunResult run = wb::readRunRecord(record);
    return std::make_pair(run.acnePercent.value_or(-1), run.leakPercent.value_or(-1));
  };
  const auto none = rates("0"), normal = rates("0.004"), large = rates("0.03");
  EXPECT_GT(none.first, 20.0) << "no bias should give heavy acne";
  EXPECT_LT(normal.first, 1.0) << "the default bias should remove nearly all acne";
  EXPECT_GT(large.second, normal.second) << "a large bias should leak more light";
}

// The PCF reference of the filtered labs on a step: occluders (depth 0.3) over the left half of a
// 64² map, nothing over the right, a receiver plane at depth 0.5 seen by 256 pixels across. Far from
// the edge it is 0 or 1; it rises monotonically; it is symmetric about the edge; and it rises over
// the footprint's width, between K and K + 1 texels (K box taps, each a bilinear blend).
TEST_F(GlTest, PcfReferenceFiltersAStepOverTheFootprint) {
  constexpr int kMap = 64, kPixels = 256;
  wb::Texture depth = wb::makeTexture2D(GL_DEPTH_COMPONENT32F, kMap, kMap);
  std::vector<float> texels(kMap * kMap);
  for (int k = 0; k < kMap * kMap; ++k) texels[size_t(k)] = k % kMap < kMap / 2 ? 0.3f : 1.0f;
  wb::uploadTexture2D(depth.id(), 0, 0, kMap, kMap, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  std::vector<glm::vec4> world;  // world = light clip space: x across the map, depth 0.5
  for (int p = 0; p < kPixels; ++p) world.emplace_back(-1.0f + 2.0f * (float(p) + 0.5f) / kPixels, 0.0f, 0.0f, 1.0f);
  world.back().w = -1;  // facing away: not compared
  wb::Texture positions = wb::makeTexture2D(GL_RGBA32F, kPixels, 1);
  wb::uploadTexture2D(positions.id(), 0, 0, kPixels, 1, GL_RGBA, GL_FLOAT, world.data());
  wb::PcfReference reference;
  for (int kernel : {1, 3, 5, 7}) {
    const std::vector<float> v =
        reference.render(positions.id(), kPixels, 1, depth.id(), kMap, glm::mat4(1), kernel, false);
    EXPECT_EQ(v.back(), -1.0f);
    EXPECT_EQ(v[0], 0.0f) << "kernel " << kernel;
    EXPECT_NEAR(v[kPixels - 2], 1.0f, 1e-5f) << "kernel " << kernel;
    int ramp = 0;
    for (int p = 1; p < kPixels - 1; ++p) {
      EXPECT_GE(v[size_t(p)], v[size_t(p) - 1] - 1e-6f) << "kernel " << kernel << ", pixel " << p;
      ramp += v[size_t(p)] > 0.01f && v[size_t(p)] < 0.99f;
    }
    for (int d = 0; d < 40; ++d)  // pixels 127 - d and 128 + d lie as far left and right of the edge
      EXPECT_NEAR(v[size_t(127 - d)] + v[size_t(128 + d)], 1.0f, 1e-4f) << "kernel " << kernel << ", offset " << d;
    const float texels = float(ramp) * kMap / kPixels;
    EXPECT_GE(texels, float(kernel)) << "kernel " << kernel;
    EXPECT_LE(texels, float(kernel + 1)) << "kernel " << kernel;
  }
}

// A heatmap's one-pixel mark becomes a 2x2 block over the grey, never over another mark, and never
// wraps to the next row.
TEST(GroundTruth, HeatmapMarksAreTwoPixelsWide) {
  const int w = 4, h = 3;
  std::vector<uint8_t> rgba(size_t(w * h) * 4, 150);
  auto set = [&](int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    uint8_t* p = &rgba[size_t(4 * (y * w + x))];
    p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
  };
  set(0, 0, 255, 40, 40);   // acne at (0, 0)
  set(1, 1, 40, 110, 255);  // a leak where the acne's block would reach
  set(3, 1, 255, 40, 40);   // acne in the last column
  const std::vector<uint8_t> out = wb::widenMarks(rgba, w);
  auto red = [&](int x, int y) { return out[size_t(4 * (y * w + x))] == 255; };
  auto blue = [&](int x, int y) { return out[size_t(4 * (y * w + x)) + 2] == 255; };
  EXPECT_TRUE(red(0, 0) && red(1, 0) && red(0, 1)) << "the acne pixel's 2x2 block";
  EXPECT_TRUE(blue(1, 1) && !red(1, 1)) << "another mark is never painted over";
  EXPECT_TRUE(blue(2, 1) && blue(1, 2) && blue(2, 2)) << "the leak's block";
  EXPECT_TRUE(red(3, 2)) << "the last column's mark grows down";
  EXPECT_FALSE(red(0, 2)) << "and does not wrap to column 0 of the next row";
}

// Against a reference: light-facing pixels only, lighter or darker by more than 0.1, in a column range.
TEST(GroundTruth, ReferenceDifferenceCountsLighterAndDarker) {
  const wb::FloatImage rendered{5, 1, {0.5f, 0.9f, 0.2f, 1.0f, 0.0f}};
  const std::vector<float> reference{0.5f, 0.5f, 0.5f, -1.0f, 0.05f};
  const wb::ReferenceDifference d = wb::compareWithReference(rendered, reference, 0, 5);
  EXPECT_EQ(d.pixels, 4);
  EXPECT_EQ(d.lighter, 1);
  EXPECT_EQ(d.darker, 1);
  EXPECT_NEAR(d.meanAbs(), (0 + 0.4 + 0.3 + 0.05) / 4, 1e-6);
  EXPECT_EQ(wb::compareWithReference(rendered, reference, 1, 2).lighter, 1);
  EXPECT_EQ(wb::compareWithReference(rendered, reference, 2, 5).lighter, 0);
}

// The blur (two fragment passes) against the same separable filter on the CPU: weights worked out
// here (a box, or a Gaussian of sigma = kernel / 4, normalised), edges clamped, for every format,
// width and weighting. (It replaced a compute-shader blur in the OpenGL 4.1 port: see issue 28.)
namespace {
std::vector<double> blurOnTheCpu(const std::vector<float>& in, int size, int kernel, bool gaussian) {
  const int r = kernel / 2;
  std::vector<double> w;
  double total = 0;
  for (int i = -r; i <= r; ++i)
    total += w.emplace_back(gaussian ? std::exp(-i * i / (2.0 * kernel * kernel / 16.0)) : 1.0);
  std::vector<double> pass(in.begin(), in.end()), out(in.size());
  for (int axis = 0; axis < 2; ++axis) {
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        for (int c = 0; c < 4; ++c) {
          double sum = 0;
          for (int i = -r; i <= r; ++i) {
            const int sx = axis == 0 ? std::clamp(x + i, 0, size - 1) : x;
            const int sy = axis == 1 ? std::clamp(y + i, 0, size - 1) : y;
            sum += w[size_t(i + r)] / total * pass[size_t(4 * (sy * size + sx) + c)];
          }
          out[size_t(4 * (y * size + x) + c)] = sum;
        }
    pass = out;
  }
  return out;
}
}  // namespace

TEST_F(GlTest, PrefilterBlurMatchesTheSameFilterOnTheCpu) {
  wb::Program blur({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/blur.frag"}});
  constexpr int kSize = 32;
  std::vector<float> input(kSize * kSize * 4);
  for (size_t k = 0; k < input.size(); ++k) input[k] = float((k * 2654435761u) % 1000u) / 1000.0f;
  for (GLenum format : {GL_RGBA32F, GL_RG32F, GL_RGBA16F})
    for (int kernel : {3, 7})
      for (bool gaussian : {false, true}) {
        const char* name = format == GL_RGBA32F ? "rgba32f" : format == GL_RG32F ? "rg32f" : "rgba16f";
        wb::FilteredShadowMap map;
        map.resize(kSize, {format, kernel, gaussian, false});
        std::vector<float> stored(input.size());  // what the texture holds before the blur
        wb::uploadTexture2D(map.texture(), 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, input.data());
        wb::readTexture(map.texture(), 0, GL_RGBA, GL_FLOAT, stored.data());
        map.prefilter(blur);
        std::vector<float> got(input.size());
        wb::readTexture(map.texture(), 0, GL_RGBA, GL_FLOAT, got.data());
        const std::vector<double> want = blurOnTheCpu(stored, kSize, kernel, gaussian);
        const double tolerance = format == GL_RGBA16F ? 2e-3 : 1e-5;  // fp16 rounds each pass to 11 bits
        const int channels = format == GL_RG32F ? 2 : 4;
        double worst = 0, change = 0;
        for (size_t k = 0; k < input.size(); ++k)
          if (int(k % 4) < channels)
            worst = std::max(worst, std::abs(got[k] - want[k])),
            change = std::max(change, std::abs(want[k] - stored[k]));
        EXPECT_LE(worst, tolerance) << name << ", kernel " << kernel << (gaussian ? " Gaussian" : " box");
        EXPECT_GT(change, 0.1) << "the test's input is too smooth to tell: " << name << ", kernel " << kernel;
      }
}

// The grader re-grades a C++ exercise alone when a failure came from a test that runs the lab's app
// (tools/grading/grade.py, runs_app): it finds those tests by name, so every test that runs the app must
// have Scene or Measured in its name; and check tells an exercise's own tests from its scenes the same
// way (a hunt measured by scenes alone waits on the others), so the words come only as the first word
// after the exercise ("Ex09_4_...InFrontOfTheScene", a kernel test, was taken for a scene).
TEST(Grading, TestsThatRunTheAppSaySceneOrMeasured) {
  const std::regex test(R"(^TEST(_F)?\(\s*\w+\s*,\s*(\w+)\s*\))");
  std::vector<fs::path> files;
  for (const char* dir : {"tests", "tests/hidden"})
    if (fs::exists(fs::path(wb::variant::kSourceDir) / dir))
      for (const auto& lab : fs::directory_iterator(fs::path(wb::variant::kSourceDir) / dir))
        if (lab.is_directory() && std::isdigit(static_cast<unsigned char>(lab.path().filename().string()[0])))
          for (const auto& f : fs::directory_iterator(lab.path()))
            if (f.path().extension() == ".cpp") files.push_back(f.path());
  ASSERT_FALSE(files.empty());
  int checked = 0;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string name;
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (std::regex_search(line, m, test)) {
        name = m[2];
        const std::string rest = std::regex_replace(name, std::regex(R"(^Ex\d\d_(\d+|x|H\d+)_)"), "");
        const bool says = name.find("Scene") != std::string::npos || name.find("Measured") != std::string::npos;
        EXPECT_TRUE(!says || rest.rfind("Scene", 0) == 0 || rest.rfind("Measured", 0) == 0)
            << f << ": test " << name << ": Scene or Measured only as the first word after the exercise";
      }
      for (const char* call : {"expectSceneMatchesGolden", "measureScene", "runLabOutput"})
        if (line.find(call) != std::string::npos && !name.empty()) {
          ++checked;
          EXPECT_TRUE(name.find("Scene") != std::string::npos || name.find("Measured") != std::string::npos)
              << f << ": test " << name << " calls " << call << " but its name has neither Scene nor Measured";
        }
    }
  }
  EXPECT_GT(checked, 10);
}

// A crash names its signal and its file:line (what check and the grader show a student).
static void crashHere() {
  wb::installCrashReport();
  volatile int* nowhere = nullptr;
  *nowhere = 1;
}

TEST(CrashReport, NamesTheSignalAndTheLine) {
  EXPECT_DEATH(crashHere(), "crashed \\(SIGSEGV: a bad memory access.*framework_test.cpp:[0-9]+");
}

// A stop from outside (the time limit's SIGTERM) that lands on another thread (Mesa's llvmpipe has
// several) still names the line where the main thread was, not "no source line found".
static std::atomic<bool> g_looping{false};
[[gnu::noinline]] static void loopHere() {
  g_looping = true;
  for (volatile int spin = 0;; spin = spin + 1) {
  }
}
static void stoppedOnAnotherThread() {
  wb::installCrashReport();
  std::thread other([] {
    while (!g_looping) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    pthread_kill(pthread_self(), SIGTERM);  // as if the kernel chose this thread
  });
  other.detach();
  loopHere();
}

TEST(CrashReport, AStopOnAnotherThreadNamesTheMainThreadsLine) {
  EXPECT_EXIT(stoppedOnAnotherThread(), ::testing::KilledBySignal(SIGTERM),
              "timed out \\(stopped at its time limit.*framework_test.cpp:[0-9]+ \\(loopHere");
}
