// The loop guard (common/platform/loop_guard.hpp): every loop condition of an exercise's GLSL is
// bounded, line for line, and a loop that never ends stops after kLoopGuardSteps steps on the GL
// implementation at hand (Mesa 25's llvmpipe and a GPU would hang on it without).
#include "common/platform/loop_guard.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"

#include <algorithm>
#include <string>

namespace {
using wb::test::GlTest;

size_t lines(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

TEST(LoopGuard, WrapsEveryLoopConditionLineForLine) {
  const std::string text =
      "float f(int n) {\n"
      "  float s = 0.0;\n"
      "  for (int k = 0; k < n; ++k) s += 1.0;\n"
      "  for (;;) { break; }\n"
      "  int j = 0;\n"
      "  while (j < n &&\n"
      "         s > 0.0) ++j;\n"
      "  do { ++j; } while (j < 3);\n"
      "  // for (int k = 0; k < n; ++k) in a comment\n"
      "  /* while (true) */ forward(j); awhile(j);\n"
      "#define LOOP for (int q = 0; q < 2; ++q)\n"
      "  for (int a = 0; a < min(n, 2); a += (1)) s += 2.0;\n"
      "  return s;\n"
      "}\n";
  const std::string got = wb::guardLoops(text);
  EXPECT_EQ(lines(got), lines(text)) << got;
  EXPECT_NE(got.find("for (int k = 0;wb_loop( k < n); ++k)"), std::string::npos) << got;
  EXPECT_NE(got.find("for (;wb_loop(true);)"), std::string::npos) << got;
  EXPECT_NE(got.find("while (wb_loop(j < n &&\n         s > 0.0))"), std::string::npos) << got;
  EXPECT_NE(got.find("while (wb_loop(j < 3));"), std::string::npos) << got;
  EXPECT_NE(got.find("// for (int k = 0; k < n; ++k) in a comment"), std::string::npos) << got;
  EXPECT_NE(got.find("/* while (true) */ forward(j); awhile(j);"), std::string::npos) << got;
  EXPECT_NE(got.find("#define LOOP for (int q = 0; q < 2; ++q)"), std::string::npos) << got;
  EXPECT_NE(got.find("for (int a = 0;wb_loop( a < min(n, 2)); a += (1))"), std::string::npos) << got;
}

// An endless loop in an exercise's file ends after kLoopGuardSteps steps, on any implementation. Loops that end compute
// what they did (a shader invocation whose loop never ended has used up its steps: its other loops stop too, and it is
// wrong anyway).
TEST_F(GlTest, AnEndlessLoopOfAnExerciseEndsAtTheGuard) {
  const std::string functions =
      "float endless() { float n = 0.0; for (int k = 0; k < 4;) n += 1.0; return n; }\n"
      "float ends(int m) { float n = 0.0; int k = 0; while (k < m) { n += 1.0; ++k; } return n; }\n";
  const std::vector<glm::vec4> in = {glm::vec4(7.0f), glm::vec4(300.0f)};
  const auto endless = wb::runGlslKernel(functions, "exercise.glsl", "result = vec4(endless());", 2, 1, in);
  const auto ends = wb::runGlslKernel(functions, "exercise.glsl", "result = vec4(ends(int(IN(0).x)));", 2, 1, in);
  ASSERT_EQ(endless.size(), 2u);
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_EQ(endless[0].x, float(wb::kLoopGuardSteps));
  EXPECT_EQ(ends[0].x, 7.0f);
  EXPECT_EQ(ends[1].x, 300.0f);
}

// The guard, not the implementation, stops the loops of an exercise (llvmpipe's own cap, 65535 steps
// of an invocation, is higher; Mesa 25's llvmpipe and GPUs have none): two loops of 30000 steps stop
// at kLoopGuardSteps in an exercise's file, and run in full in any other (the framework's shaders
// are not guarded).
TEST_F(GlTest, TheGuardBoundsAnExercisesStepsAltogether) {
  const std::string functions =
      "float steps() { float n = 0.0; for (int i = 0; i < 30000; ++i) n += 1.0; "
      "for (int j = 0; j < 30000; ++j) n += 1.0; return n; }\n";
  const auto guarded = wb::runGlslKernel(functions, "exercise.glsl", "result = vec4(steps());", 1, 1, {});
  const auto free = wb::runGlslKernel(functions, "framework.glsl", "result = vec4(steps());", 1, 1, {});
  ASSERT_EQ(guarded.size(), 1u);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(guarded[0].x, float(wb::kLoopGuardSteps));
  EXPECT_EQ(free[0].x, 60000.0f);
}

}  // namespace
