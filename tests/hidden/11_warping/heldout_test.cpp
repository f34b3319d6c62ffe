// Held-out tests of lab 11 (instructor-only: tests/hidden is never exported). Other numbers than the
// public tests, a light view that is turned, and a vineyard students have not seen (five rows of posts
// 200 m deep, a shed, a sun from the right and in front). The C++ calls go through WB_CALL_HELD_OUT:
// the runner, which does not hold these tests, makes them from the judge's plan. Points and
// visibility: hidden.json beside this file.
#include "common/judge/harness.hpp"
#include "exercise.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace {
std::vector<std::string> vineyard(std::vector<std::string> settings) {
  return wb::test::labArgs(settings, "hidden/heldout.json");
}
}  // namespace

// z0 0.5, d 80, sin 0.7, strength 0.8, fadeSin 0.3 (no fade): z1 = 0.5 + 56 = 56.5, sqrt(28.25) =
// 5.315073, n_opt = 5.815073 / 0.7 = 8.307247, over 0.8: 10.384059. z0 2, d 40, sin 0.1, fadeSin 0.3:
// the fade (0.1 - 0.02) / (0.3 - 0.02) = 0.285714; z1 = 6, sqrt(12) = 3.464102, n_opt = 54.64102, over
// 0.285714: 191.24357.
TEST(Hidden11, Ex11_3_NearHeldOut) {
  float got = 0;
  WB_TRY_EXERCISE(got = WB_CALL_HELD_OUT(lab11::warpNear, 0.5f, 80.0f, 0.7f, 0.8f, 0.3f));
  EXPECT_NEAR(got, 10.384059f, 1e-3f) << "WRONG: a held-out case";
  WB_TRY_EXERCISE(got = WB_CALL_HELD_OUT(lab11::warpNear, 2.0f, 40.0f, 0.1f, 1.0f, 0.3f));
  EXPECT_NEAR(got, 191.24357f, 2e-2f) << "WRONG: a held-out case";
}

// A turned light and a long thin body: the corners touch the map's four edges, and each corner's map y
// follows from its light-space y alone (the formula of the public test, on other numbers).
TEST(Hidden11, Ex11_4_WarpUnderATurnedLight) {
  const glm::vec3 dir = glm::normalize(glm::vec3(0.6f, -0.5f, -0.62f));
  const glm::mat4 lightView =
      glm::lookAt(glm::vec3(-4, 6, 1), glm::vec3(-4, 6, 1) + dir, glm::vec3(-0.2f, 0.3f, -0.9f));
  std::vector<glm::vec3> body;
  for (int k = 0; k < 8; ++k) body.push_back({k & 1 ? 5.0f : -3.0f, k & 2 ? 2.0f : -1.0f, k & 4 ? -1.5f : -70.0f});
  glm::mat4 m(1);
  WB_TRY_EXERCISE(m = WB_CALL_HELD_OUT(lab11::warpMatrix, lightView, body, 7.0f, 3.0f));
  double lo = 1e30, hi = -1e30;
  for (const glm::vec3& b : body) {
    const double y = (lightView * glm::vec4(b, 1)).y;
    lo = std::min(lo, y), hi = std::max(hi, y);
  }
  const double n = 7, f = n + (hi - lo), a = (f + n) / (f - n), bb = -2 * f * n / (f - n);
  glm::vec2 least(1e30f), most(-1e30f);
  for (const glm::vec3& b : body) {
    const glm::vec4 c = m * glm::vec4(b, 1);
    const glm::vec3 p = glm::vec3(c) / c.w;
    const double t = (lightView * glm::vec4(b, 1)).y - lo + n;
    EXPECT_NEAR(p.y, (a * t + bb) / t, 1e-3) << "WRONG: a held-out case";
    EXPECT_LE(std::abs(p.z), 1 + 1e-4) << "WRONG: a held-out case";
    least = glm::min(least, glm::vec2(p)), most = glm::max(most, glm::vec2(p));
  }
  EXPECT_NEAR(least.x, -1, 1e-4) << "WRONG: a held-out case";
  EXPECT_NEAR(most.x, 1, 1e-4) << "WRONG: a held-out case";
  EXPECT_NEAR(least.y, -1, 1e-4) << "WRONG: a held-out case";
  EXPECT_NEAR(most.y, 1, 1e-4) << "WRONG: a held-out case";
}

// Bounds 2.5 .. 90 on near 0.5, far 150, three cascades, lambda 0.6: logarithmic 2.5 * 36^(i/3) =
// 8.254818, 27.256810; uniform 31.666667, 60.833333; practical 17.619558, 40.687419.
TEST(Hidden11, Ex11_6_SplitsHeldOut) {
  std::vector<float> got;
  WB_TRY_EXERCISE(got = WB_CALL_HELD_OUT(lab11::fittedSplits, glm::vec2(2.5f, 90), 0.5f, 150.0f, 3, 0.6f));
  const std::vector<float> want = {2.5f, 17.619558f, 40.687419f, 90};
  ASSERT_EQ(got.size(), want.size()) << "WRONG: a held-out case";
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-4 * want[i]) << "WRONG: a held-out case";
}

TEST(Hidden11, Ex11_H1_SwitchHeldOut) {
  std::vector<float> got;
  WB_TRY_EXERCISE(got = WB_CALL_HELD_OUT(lab11::switchDistances, std::vector<float>{3, 9, 25, 70, 150}, 0.5f, 150.0f));
  const std::vector<float> want = {9, 25, 70};
  ASSERT_EQ(got.size(), want.size()) << "WRONG: a held-out case";
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-4 * want[i]) << "WRONG: a held-out case";
}

TEST(Hidden11, Ex11_3_SceneVineyard) {
  wb::test::expectSceneMatchesGolden("11.3", "hidden/heldout", vineyard({"warp.sdsm=on"}), 0.1f, 0.01);
}
TEST(Hidden11, Ex11_4_SceneVineyardCascadesWarped) {
  wb::test::expectSceneMatchesGolden("11.4", "hidden/heldout_csm_lispsm",
                                     vineyard({"warp.scheme=csm_lispsm", "camera.bookmark=2"}), 0.1f, 0.01);
}
TEST(Hidden11, Ex11_5_SceneVineyard) {
  wb::test::expectSceneMatchesGolden("11.5", "hidden/heldout", vineyard({"warp.sdsm=on"}), 0.1f, 0.01);
}
TEST(Hidden11, Ex11_6_SceneVineyardCascades) {
  wb::test::expectSceneMatchesGolden("11.6", "hidden/heldout_csm", vineyard({"warp.scheme=csm", "csm.lambda=0.5"}),
                                     0.1f, 0.01);
}
