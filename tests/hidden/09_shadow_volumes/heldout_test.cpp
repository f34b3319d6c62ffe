// Held-out tests of lab 09 (instructor-only: tests/hidden is never exported). The same exercises in a
// courtyard students have not seen: a directional light, an arch, a flat ring, an open sheet (open
// edges), and a bookmark inside the arch's shadow. Points and visibility: hidden.json beside this file.
#include "common/judge/harness.hpp"
#include "exercise.hpp"

#include <array>
#include <iterator>

namespace {
const std::vector<std::string> kOverview = wb::test::labArgs({}, "hidden/heldout.json");
const std::vector<std::string> kInside = wb::test::labArgs({"camera.bookmark=2"}, "hidden/heldout.json");
}  // namespace

TEST(Hidden09, Ex09_1_SceneHeldOut) {
  wb::test::expectSceneMatchesGolden("09.1", "hidden/heldout", kOverview, 0.1f, 0.005);
}

TEST(Hidden09, Ex09_5_SceneHeldOutInsideZFail) {
  wb::test::expectSceneMatchesGolden(
      "09.5", "hidden/heldout_inside",
      wb::test::labArgs({"camera.bookmark=2", "volume.method=zfail"}, "hidden/heldout.json"), 0.1f, 0.005);
}

TEST(Hidden09, Ex09_6_SceneHeldOutInsideAuto) {
  wb::test::expectSceneMatchesGolden("09.6", "hidden/heldout_inside", kInside, 0.1f, 0.005);
}

// 09.6 on the public test's boxes, moved by affine maps that keep boxes axis-aligned (a permutation
// of the axes, mirrorings, a scale per axis, a shift). Such a map keeps "the box reaches into the
// region between the quad and the light", so every answer stays; an answer learnt for the public
// numbers, or a constant, does not.

TEST(Hidden09, Ex09_6_NearPlaneTestUnderAffineMaps) {
  struct Case {
    glm::vec4 light;
    glm::vec3 lo, hi;
    bool want;
  };
  const Case cases[] = {
      {{0, 0, 10, 1}, {-0.2f, -0.2f, 4}, {0.2f, 0.2f, 5}, true},
      {{0, 0, 10, 1}, {-5, -5, 2}, {5, 5, 3}, true},
      {{0, 0, 10, 1}, {0.9f, 0.9f, -0.5f}, {1.5f, 1.5f, 0.5f}, true},
      {{0, 0, 10, 1}, {3, -0.5f, 1}, {4, 0.5f, 2}, false},
      {{0, 0, 10, 1}, {-0.5f, -0.5f, -3}, {0.5f, 0.5f, -2}, false},
      {{0, 0, 10, 1}, {-0.2f, -0.2f, 13}, {0.2f, 0.2f, 14}, false},
      {{0, 0, 1, 0}, {3, 3, 50}, {4, 4, 60}, false},
      {{0, 0, 1, 0}, {-0.5f, -0.5f, 50}, {0.5f, 0.5f, 60}, true},
      {{0, 0, 1, 0}, {-0.5f, -0.5f, -60}, {0.5f, 0.5f, -50}, false},
      {{6, 0, 5, 1}, {3, -0.3f, 2}, {3.4f, 0.3f, 3}, true},
      {{6, 0, 5, 1}, {-0.5f, -0.5f, 4}, {0.5f, 0.5f, 5}, false},
  };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int m = 0; m < 8; ++m) {
    const int* perm = perms[(m * 5 + 1) % 6];
    const glm::vec3 sign(m & 1 ? -1 : 1, m & 2 ? -1 : 1, m & 4 ? -1 : 1);
    const glm::vec3 scale(0.5f + 0.37f * float(m), 2.0f - 0.21f * float(m), 1.0f + 0.5f * float(m % 3));
    const glm::vec3 shift(3.0f * float(m) - 7, 11 - 2.0f * float(m), 0.25f * float(m * m) - 4);
    auto linear = [&](glm::vec3 v) {
      glm::vec3 r;
      for (int a = 0; a < 3; ++a) r[a] = sign[a] * scale[a] * v[perm[a]];
      return r;
    };
    auto point = [&](glm::vec3 v) { return linear(v) + shift; };
    const std::array<glm::vec3, 4> quad = {point({-1, -1, 0}), point({1, -1, 0}), point({1, 1, 0}), point({-1, 1, 0})};
    for (size_t k = 0; k < std::size(cases); ++k) {
      const Case& c = cases[k];
      const glm::vec4 light = c.light.w != 0 ? glm::vec4(point(glm::vec3(c.light)), 1)
                                             : glm::vec4(glm::normalize(linear(glm::vec3(c.light))), 0);
      const glm::vec3 a = point(c.lo), b = point(c.hi);
      bool got = false;
      WB_TRY_EXERCISE(got =
                          WB_CALL_HELD_OUT(lab09::nearPlaneMayBeShadowed, quad, light, glm::min(a, b), glm::max(a, b)));
      ASSERT_EQ(got, c.want) << "WRONG: a held-out case (map " << m << ", box " << k << ")";
    }
  }
}
