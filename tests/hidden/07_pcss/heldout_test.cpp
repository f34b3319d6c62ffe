// Held-out tests of lab 07 (instructor-only: tests/hidden is never exported). The same exercises on
// a scene students have not seen: a steeper plank leaning the other way, under a larger light that is
// off-centre. Their points and visibility: hidden.json beside this file.
#include "common/judge/harness.hpp"

namespace {
const std::vector<std::string> kHeldOut = wb::test::labArgs({}, "hidden/heldout.json");
}  // namespace

TEST(Hidden07, Ex07_2_SceneHeldOut) {
  wb::test::expectSceneMatchesGolden("07.2", "hidden/heldout", kHeldOut, 0.1f, 0.01);
}

// The solution: 2.0-2.3% off the area light on average, 2.4-3.6% of the shadow's pixels by more than
// 0.1, and a penumbra growing 0.98-1.08 times as fast as the theory, over the grader's variations.
TEST(Hidden07, Ex07_4_MeasuredHeldOutPenumbra) {
  const auto m = wb::test::measureScene("07.4", "hidden_measure", kHeldOut);
  if (!m.failure.empty()) FAIL() << m.failure;
  ASSERT_GE(m.penumbra.size(), 5u) << "ERROR: the held-out scene's probe measured " << m.penumbra.size() << " slabs";
  EXPECT_LT(m.areaMeanAbsPercent, 4) << "WRONG: " << m.areaMeanAbsPercent << "% off the area light on average";
  EXPECT_LT(m.areaOffPercent, 9) << "WRONG: " << m.areaOffPercent << "% of the shadow's pixels off by more than 0.1";
  for (const auto& r : m.penumbra) ASSERT_GT(r[2], 0) << "WRONG: no penumbra found at distance " << r[0];
  EXPECT_NEAR(wb::test::penumbraGrowthRatio(m), 1.0, 0.25)
      << "WRONG: the penumbra does not grow with the receiver-blocker distance as the theory says";
}
