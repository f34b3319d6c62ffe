// What check says where the student edition cannot isolate an exercise (common/judge/attribution.hpp),
// and the endless-loop reading of a count of 50000 (diagnosis.cpp). This binary runs as the student
// edition does: its variant has no solution folder.
#include "common/base/variant.hpp"
#include "common/judge/attribution.hpp"
#include "common/judge/diagnosis.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using wb::test::Diagnosis;
using wb::test::ManifestEntry;

namespace {

const std::vector<ManifestEntry> kManifest = {{"07.1", "search region", "shaders/exercise.glsl"},
                                              {"07.2", "blocker search", "shaders/exercise.glsl"},
                                              {"07.4", "PCSS", "shaders/exercise.glsl"}};

// 07.4 calls 07.2's function (and a builtin, and its own helper); 07.1 calls nothing of the others.
const char* kShader =
    "float helper() { return 1.0; }\n"
    "// EXERCISE 07.1\nfloat searchWidth(float a) { if (a > 0.0) { return a; } return helper(); }\n"
    "// EXERCISE 07.2\nvec2 findBlockers(float z) {\n  for (int k = 0; k < 4;) { z += 1.0; }\n  return vec2(z);\n}\n"
    "// EXERCISE 07.4\nfloat pcss(float z) { vec2 b = findBlockers(z); return max(b.x, searchWidth2(z)); }\n"
    "float searchWidth2(float z) { return z; }\n";

const std::set<std::string> kAllHaveOwnTests = {"07.1", "07.2", "07.4"};

Diagnosis failure(const std::string& verdict, const std::string& headline) {
  Diagnosis d;
  d.verdict = verdict, d.headline = headline, d.details = {"a detail"};
  return d;
}

}  // namespace

TEST(CheckAttribution, AGlslExerciseCallsTheExercisesWhoseFunctionsItUses) {
  EXPECT_EQ(wb::test::glslExercisesCalled(kShader, "07.4", kManifest), std::vector<std::string>{"07.2"});
  EXPECT_TRUE(wb::test::glslExercisesCalled(kShader, "07.1", kManifest).empty()) << "helpers and builtins are no one's";
  EXPECT_TRUE(wb::test::glslExercisesCalled(kShader, "07.2", kManifest).empty()) << "'for' is no function";
}

// The student edition (no reference): 07.2 is wrong; 07.4 fails its own tests by calling it, and is
// blocked by it, without a hint; 07.1 passes its own tests, its scene blocked by 07.4's failure: it
// passes its own tests and waits on 07.2, the root, and counts as the grader will count it.
TEST(CheckAttribution, WithoutTheReferenceOneMistakeCostsOneExercise) {
  ASSERT_EQ(*wb::variant::kSolutionDir, '\0') << "this binary must run as the student edition does";
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "attribution";
  fs::create_directories(dir / "shaders");
  std::ofstream(dir / "shaders/exercise.glsl") << kShader;
  setenv("WB_SUBMISSION_DIR", dir.c_str(), 1);
  std::map<std::string, Diagnosis> first = {
      {"07.1", failure("WRONG", "WRONG: 3.2% of pixels differ from the golden scene")},
      {"07.2", failure("WRONG", "WRONG: got 65535, want 30")},
      {"07.4", failure("WRONG", "WRONG: the penumbra of case 2, got 0.4, want 0.1")}};
  const std::set<std::string> ownFailed = {"07.2", "07.4"};
  std::map<std::string, std::string> blockers;
  std::set<std::string> unblocked = {"07.1"};
  wb::test::attribute(kManifest, {first, ownFailed, blockers, unblocked, kAllHaveOwnTests});
  unsetenv("WB_SUBMISSION_DIR");
  EXPECT_EQ(first["07.2"].verdict, "WRONG");
  EXPECT_EQ(first["07.4"].verdict, "ERROR");
  EXPECT_EQ(first["07.4"].headline.rfind("ERROR: blocked by 07.2: 07.4 calls 07.2", 0), 0u) << first["07.4"].headline;
  EXPECT_TRUE(first["07.4"].details.empty()) << "no hint, no case: the failure is 07.2's";
  EXPECT_EQ(first["07.1"].verdict, "WAITS");
  EXPECT_NE(first["07.1"].headline.find("its scene is checked once 07.2 passes"), std::string::npos)
      << first["07.1"].headline;
}

// An exercise with no test but its scenes (a bug hunt, as 07.1 here) whose scene is spoilt by a wrong
// 07.2 passes nothing of its own: it waits on 07.2, neither passed nor failed, with no number.
TEST(CheckAttribution, AnExerciseMeasuredOnlyByItsScenesWaits) {
  std::map<std::string, Diagnosis> first = {
      {"07.1", failure("WRONG",
                       "WRONG: in scene 'x', 100.00% of the pixels the light truly reaches are drawn in "
                       "shadow")},
      {"07.2", failure("WRONG", "WRONG: got 65535, want 30")}};
  std::map<std::string, std::string> blockers;
  std::set<std::string> unblocked = {"07.1"};
  wb::test::attribute(kManifest, {first, {"07.2"}, blockers, unblocked, {"07.2"}});
  EXPECT_EQ(first["07.1"].verdict, "WAITING");
  EXPECT_EQ(first["07.1"].headline.rfind("waiting on 07.2: its scenes are measured once 07.2 passes", 0), 0u)
      << first["07.1"].headline;
  EXPECT_EQ(first["07.1"].headline.find('%'), std::string::npos) << "no number: the stubs' or the blocker's";
}

// A scene that is wrong while the only other unfinished exercise is a stub shows its own mistake: a
// stub draws its pattern, which the scene's test names as "blocked by" itself, so the stub did not
// spoil this picture (02.H1 with its bug, beside the stubs of 02.2, 02.5 and 02.6).
TEST(CheckAttribution, AStubDoesNotExcuseAWrongScene) {
  std::map<std::string, Diagnosis> first = {
      {"07.1", failure("WRONG", "WRONG: visibility in scene 'x' differs from the reference on 6.28% of pixels")},
      {"07.2", failure("NOT IMPLEMENTED", "NOT IMPLEMENTED: the GLSL function still returns WB_TODO")}};
  std::map<std::string, std::string> blockers;
  std::set<std::string> unblocked = {"07.1"};
  wb::test::attribute(kManifest, {first, {"07.2"}, blockers, unblocked, {"07.2"}});
  EXPECT_EQ(first["07.1"].verdict, "WRONG") << first["07.1"].headline;
}

// 07.2 loops for ever: 07.4, which calls it, times out in its scene. That time-out is 07.2's too, so
// 07.4 is blocked by 07.2 and counted as not known yet; a compile error of 07.4's own stays its own.
TEST(CheckAttribution, ATimeOutInACallerOfAnEndlessLoopIsTheLoops) {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "attribution_timeout";
  fs::create_directories(dir / "shaders");
  std::ofstream(dir / "shaders/exercise.glsl") << kShader;
  setenv("WB_SUBMISSION_DIR", dir.c_str(), 1);
  for (const char* own :
       {"ERROR: the lab timed out: timed out (stopped at its time limit: an endless loop?)", "ERROR: compile error:"}) {
    std::map<std::string, Diagnosis> first = {{"07.2", failure("WRONG", "WRONG: got 65535, want 30")},
                                              {"07.4", failure("ERROR", own)}};
    std::map<std::string, std::string> blockers;
    std::set<std::string> unblocked;
    wb::test::attribute(kManifest, {first, {"07.2", "07.4"}, blockers, unblocked, kAllHaveOwnTests});
    const bool compile = std::string(own).find("compile") != std::string::npos;
    EXPECT_EQ(first["07.4"].headline.rfind(compile ? "ERROR: compile error" : "ERROR: blocked by 07.2", 0), 0u)
        << first["07.4"].headline;
  }
  unsetenv("WB_SUBMISSION_DIR");
}

// A stub is not implemented, whatever it calls.
TEST(CheckAttribution, AStubStaysNotImplemented) {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "attribution_stub";
  fs::create_directories(dir / "shaders");
  std::string text = kShader;
  text.replace(text.find("return max(b.x"), 14, "return WB_TODO");
  std::ofstream(dir / "shaders/exercise.glsl") << text;
  setenv("WB_SUBMISSION_DIR", dir.c_str(), 1);
  std::map<std::string, Diagnosis> first = {
      {"07.2", failure("WRONG", "WRONG: got 65535, want 30")},
      {"07.4", failure("NOT IMPLEMENTED", "NOT IMPLEMENTED: the GLSL function still returns WB_TODO")}};
  std::map<std::string, std::string> blockers;
  std::set<std::string> unblocked;
  wb::test::attribute(kManifest, {first, {"07.2", "07.4"}, blockers, unblocked, kAllHaveOwnTests});
  unsetenv("WB_SUBMISSION_DIR");
  EXPECT_EQ(first["07.4"].verdict, "NOT IMPLEMENTED");
}

// The loop guard stops an exercise's loops after 50000 steps (loop_guard.hpp): a count of exactly
// that is named as an endless loop; a count near it is not.
// (gtest's message for ASSERT_NEAR(got, 30, 0.001), then ours)
std::string nearFailure(const std::string& got) {
  return "The difference between got and 30 is 1, which exceeds 0.001, where\ngot evaluates to " + got +
         ",\n30 evaluates to 30, and\n0.001 evaluates to 0.001.\nWRONG: the number of blockers among 32 taps";
}

TEST(CheckDiagnosis, ACountOfTheLoopGuardsStepsIsAnEndlessLoop) {
  const auto looped = wb::test::diagnose("Lab07.Ex07_2_X", nearFailure("50000"));
  bool named = false;
  for (const auto& l : looped.details) named |= l.find("looks like an endless loop") != std::string::npos;
  EXPECT_TRUE(named);
  const auto other = wb::test::diagnose("Lab07.Ex07_2_X", nearFailure("49999"));
  for (const auto& l : other.details) EXPECT_EQ(l.find("endless loop"), std::string::npos) << l;
}
