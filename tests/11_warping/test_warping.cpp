// Lab 11 tests. Layer 1: texels per pixel and its two parts on derivatives and angles worked out by
// hand, LiSPSM's n against the formula at chosen angles, the warped matrix on a box whose images are
// derived below, the reduction step with empty texels, and the fitted splits on clamped and empty
// bounds. Layer 2: the field under each scheme against goldens, and the measure's numbers.
#include "common/judge/harness.hpp"
#include "common/judge/isolation.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/image.hpp"
#include "common/scene/scene.hpp"
#include "exercise.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

using wb::test::GlTest;

// The held-out tests (instructor-only) call these on inputs of their own, through the grader's plan.
WB_CALLABLE(lab11::warpNear);
WB_CALLABLE(lab11::warpMatrix);
WB_CALLABLE(lab11::fittedSplits);
WB_CALLABLE(lab11::switchDistances);

// --- 11.1: texels per pixel ----------------------------------------------------------------------------
// A step of one pixel moves the map coordinate by uvDx (screen x) and uvDy (screen y); times the map's
// texels along u and v, that is a step in texels, and its length is the texels one pixel spans.
// (0.001, 0) on a 1024 x 512 map: 1.024; (0, 0.002): 1.024. (3e-4, 4e-4) on 1000 x 1000: 0.3, 0.4: 0.5;
// (-6e-4, 8e-4): 1.0. (1e-3, 1e-3) on 2048 x 512: (2.048, 0.512): sqrt(4.194304 + 0.262144) = 2.111031;
// (1e-3, -1e-3) the same.
TEST_F(GlTest, Ex11_1_TexelsPerPixelByHand) {
  const std::vector<glm::vec4> in = {
      {0.001f, 0, 0, 0.002f}, {3e-4f, 4e-4f, -6e-4f, 8e-4f}, {1e-3f, 1e-3f, 1e-3f, -1e-3f}};
  const std::vector<glm::vec4> maps = {{1024, 512, 0, 0}, {1000, 1000, 0, 0}, {2048, 512, 0, 0}};
  std::vector<glm::vec4> inputs;
  for (size_t k = 0; k < in.size(); ++k) inputs.insert(inputs.end(), {in[k], maps[k]});
  const glm::vec2 want[] = {{1.024f, 1.024f}, {0.5f, 1.0f}, {2.111031f, 2.111031f}};
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "11.1", "result.xy = texelsPerPixel(IN(0).xy, IN(0).zw, IN(1).xy);", int(in.size()), 2, inputs);
  for (size_t k = 0; k < in.size(); ++k)
    for (int a = 0; a < 2; ++a)
      EXPECT_NEAR(got[k][a], want[k][a], 1e-4 * want[k][a])
          << "WRONG: " << (a ? "along screen y" : "along screen x") << ", uvDx (" << in[k].x << ", " << in[k].y
          << "), uvDy (" << in[k].z << ", " << in[k].w << "), a " << maps[k].x << " x " << maps[k].y << " map";
}

// --- 11.2: the two parts ------------------------------------------------------------------------------
// The eye 5 away at (0, 3, 4) from the point, normal up: cos to the eye 3/5. A pixel of 0.001 rad
// spans 5 * 0.001 = 0.005 across the view; texels 0.01 wide: perspective 0.5. Light from (0, 1, 1):
// cos 1/sqrt(2): projective 0.707107 / 0.6 = 1.178511. The normal twice as long changes nothing. A
// light from below: projective 0. An eye along the surface (10, 0, 0): its cosine is held at 1e-4, the
// light straight above: projective 1 / 1e-4 = 10000; perspective 10 * 0.002 / 0.004 = 5.
TEST_F(GlTest, Ex11_2_PartsByHand) {
  struct Case {
    glm::vec4 toEye, normal, toLight, sizes;  // sizes: pixel angle, texel width
    glm::vec2 want;
    const char* what;
  };
  const Case cases[] = {
      {{0, 3, 4, 0}, {0, 1, 0, 0}, {0, 1, 1, 0}, {0.001f, 0.01f, 0, 0}, {0.5f, 1.178511f}, "the eye at (0, 3, 4)"},
      {{0, 3, 4, 0}, {0, 2, 0, 0}, {0, 1, 1, 0}, {0.001f, 0.01f, 0, 0}, {0.5f, 1.178511f}, "a normal of length 2"},
      {{0, 3, 4, 0}, {0, 1, 0, 0}, {0, -1, 1, 0}, {0.001f, 0.01f, 0, 0}, {0.5f, 0}, "a light from below"},
      {{10, 0, 0, 0}, {0, 1, 0, 0}, {0, 1, 0, 0}, {0.002f, 0.004f, 0, 0}, {5, 10000}, "an eye along the surface"},
  };
  std::vector<glm::vec4> inputs;
  for (const Case& c : cases) inputs.insert(inputs.end(), {c.toEye, c.normal, c.toLight, c.sizes});
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "11.2", "result.xy = aliasingParts(IN(0).xyz, IN(1).xyz, IN(2).xyz, IN(3).x, IN(3).y);",
              int(std::size(cases)), 4, inputs);
  for (size_t k = 0; k < std::size(cases); ++k) {
    const Case& c = cases[k];
    EXPECT_NEAR(got[k].x, c.want.x, 1e-4 * c.want.x)
        << "WRONG: the perspective part, " << c.what << ": distance " << glm::length(glm::vec3(c.toEye))
        << " times the pixel's angle " << c.sizes.x << " over the texel's width " << c.sizes.y;
    EXPECT_NEAR(got[k].y, c.want.y, 1e-4 * c.want.y + 1e-6)
        << "WRONG: the projective part, " << c.what << ": cos(to the light) / cos(to the eye), toEye (" << c.toEye.x
        << ", " << c.toEye.y << ", " << c.toEye.z << "), normal (" << c.normal.x << ", " << c.normal.y << ", "
        << c.normal.z << "), toLight (" << c.toLight.x << ", " << c.toLight.y << ", " << c.toLight.z << ")";
  }
}

// --- 11.3: LiSPSM's n --------------------------------------------------------------------------------
// n_opt = (z0 + sqrt(z0 z1)) / sin g, z1 = z0 + d sin g. z0 1, d 100, sin 1: z1 101, 1 + sqrt(101) =
// 11.049876. sin 0.5 (the fade's edge, fade 1): z1 51, (1 + 7.141428) / 0.5 = 16.282856. Strength 0.5
// at sin 1: 22.099751. z0 2, d 30, sin 0.8: z1 26, (2 + 7.211103) / 0.8 = 11.513878. Fading: sin 0.26
// with fadeSin 0.5 is halfway, (0.26 - 0.02) / (0.5 - 0.02) = 0.5: z1 = 27, (1 + 5.196152) / 0.26 =
// 23.831355, over 0.5: 47.662710. fadeSin 0 never fades: sin 0.1, z1 11, (1 + 3.316625) / 0.1 = 43.16625.
// No warp (infinity): strength 0, or sin g at or below 0.02.
TEST(Lab11, Ex11_3_OptimalNearByHand) {
  struct Case {
    float z0, d, sinGamma, strength, fadeSin, want;
    const char* what;
  };
  const float inf = std::numeric_limits<float>::infinity();
  const Case cases[] = {
      {1, 100, 1, 1, 0.5f, 11.049876f, "view across the light"},
      {1, 100, 0.5f, 1, 0.5f, 16.282856f, "sin g 0.5, at the fade's edge"},
      {1, 100, 1, 0.5f, 0.5f, 22.099751f, "strength 0.5"},
      {2, 30, 0.8f, 1, 0.5f, 11.513878f, "z0 2, d 30, sin g 0.8"},
      {1, 100, 0.26f, 1, 0.5f, 47.662710f, "sin g 0.26: halfway through the fade"},
      {1, 100, 0.1f, 1, 0, 43.16625f, "fadeSin 0: no fade"},
      {1, 100, 1, 0, 0.5f, inf, "strength 0: no warp"},
      {1, 100, 0.015f, 1, 0.5f, inf, "sin g 0.015: looking along the light, no warp"},
  };
  for (const Case& c : cases) {
    float got = 0;
    WB_TRY_EXERCISE(got = WB_CALL(lab11::warpNear(c.z0, c.d, c.sinGamma, c.strength, c.fadeSin)));
    if (std::isinf(c.want))
      EXPECT_TRUE(std::isinf(got) && got > 0) << "WRONG: " << c.what << ": n must be +infinity (got " << got << ")";
    else
      EXPECT_NEAR(got, c.want, 1e-4 * c.want)
          << "WRONG: " << c.what << " (z0 " << c.z0 << ", d " << c.d << ", sin g " << c.sinGamma << ", strength "
          << c.strength << ", fadeSin " << c.fadeSin << ")";
  }
}

// --- 11.4: the warped matrix --------------------------------------------------------------------------
namespace {
glm::vec3 ndc(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 c = m * glm::vec4(p, 1);
  return glm::vec3(c) / c.w;
}
std::vector<glm::vec3> box(glm::vec3 lo, glm::vec3 hi) {
  std::vector<glm::vec3> out;
  for (int k = 0; k < 8; ++k) out.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  return out;
}
std::string str(glm::vec3 p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}
}  // namespace

// Light space = world (lightView the identity): the body x -2..4, y 1..11, z -5..-3, caster reach 2,
// so the depth runs from z = -1 (near, -1) to z = -5 (far, 1), and z = -3 is 0.
// No warp: the orthographic fit: (-2, 1, -1) -> (-1, -1, -1), (4, 11, -5) -> (1, 1, 1), (1, 6, -3) -> 0.
// n = 5: the eye at y = 1 - 5 = -4 on x = 1; t = y + 4 runs 5..15 (f = 15); y' = 2 - 15 / t: -1 at
// t = 5, 0.5 at the middle (t = 10: the near half of the body gets three quarters of the map), 1 at
// t = 15. x' = 5 (x - 1) / t spans -3..3 over the body (at t = 5), so x = 5 (x - 1) / (3 t): (4, 1) ->
// 1, (4, 11) -> 1/3, (-2, 6) -> -0.5. Depth: the orthographic depth times n / t: (4, 11, -5) -> 1/3,
// (1, 1, -5) -> 1, (1, 6, -1) -> -0.5.
TEST(Lab11, Ex11_4_WarpOfABoxByHand) {
  const auto body = box({-2, 1, -5}, {4, 11, -3});
  glm::mat4 flat(1), warped(1);
  WB_TRY_EXERCISE(flat = WB_CALL(lab11::warpMatrix(glm::mat4(1), body, std::numeric_limits<float>::infinity(), 2)));
  WB_TRY_EXERCISE(warped = WB_CALL(lab11::warpMatrix(glm::mat4(1), body, 5, 2)));
  struct Case {
    const glm::mat4* m;
    glm::vec3 p, want;
    const char* what;
  };
  const Case cases[] = {
      {&flat, {-2, 1, -1}, {-1, -1, -1}, "no warp: the body's low corner, at the caster reach"},
      {&flat, {4, 11, -5}, {1, 1, 1}, "no warp: the body's high corner, far side"},
      {&flat, {1, 6, -3}, {0, 0, 0}, "no warp: the middle"},
      {&warped, {4, 1, -3}, {1, -1, 0}, "n = 5: the near side's right edge"},
      {&warped, {4, 11, -5}, {1.0f / 3, 1, 1.0f / 3}, "n = 5: the far side's right edge, far from the light"},
      {&warped, {-2, 6, -3}, {-0.5f, 0.5f, 0}, "n = 5: the middle of the body (y 6) lands at y 0.5"},
      {&warped, {1, 1, -5}, {0, -1, 1}, "n = 5: the near side, far from the light"},
      {&warped, {1, 6, -1}, {0, 0.5f, -0.5f}, "n = 5: the middle, at the caster reach"},
  };
  for (const Case& c : cases) {
    const glm::vec3 got = ndc(*c.m, c.p);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(got[a], c.want[a], 1e-4)
          << "WRONG: " << c.what << ": the point " << str(c.p) << " lands at " << str(got) << ", want " << str(c.want)
          << " (light space = world, body x -2..4, y 1..11, z -5..-3, reach 2)";
  }
}

// Any light view: the body's corners land inside the map, touching each of its four edges, and the
// map's y of each corner follows from its light-space y alone (the warp's axis): y' = (a t + b) / t with
// t = y - (smallest y) + n, a = (f + n) / (f - n), b = -2 f n / (f - n), f = n + d; a light view that
// is not the identity, so that one left out shows.
TEST(Lab11, Ex11_4_AnyLightViewTouchesEveryEdge) {
  const glm::vec3 dir = glm::normalize(glm::vec3(-0.5f, -0.6f, -0.62f)), eye(3, 5, 2);
  const glm::mat4 lightView = glm::lookAt(eye, eye + dir, glm::vec3(0.3f, 0.2f, -0.9f));
  const auto body = box({-6, 0, -40}, {7, 3, -2});
  for (float n : {2.0f, 15.0f, 200.0f}) {
    glm::mat4 m(1);
    WB_TRY_EXERCISE(m = WB_CALL(lab11::warpMatrix(lightView, body, n, 5)));
    double lo = 1e30, hi = -1e30;
    for (const glm::vec3& b : body)
      lo = std::min(lo, double((lightView * glm::vec4(b, 1)).y)),
      hi = std::max(hi, double((lightView * glm::vec4(b, 1)).y));
    const double f = n + (hi - lo), a = (f + n) / (f - n), bb = -2 * f * n / (f - n);
    glm::vec2 least(1e30f), most(-1e30f);
    for (const glm::vec3& b : body) {
      const glm::vec3 p = ndc(m, b);
      const double t = (lightView * glm::vec4(b, 1)).y - lo + n;
      EXPECT_NEAR(p.y, (a * t + bb) / t, 1e-3)
          << "WRONG: n = " << n << ", the corner " << str(b) << ": its map y must follow its light-space y (" << t - n
          << " past the body's nearest)";
      EXPECT_LE(std::abs(p.z), 1 + 1e-4) << "WRONG: n = " << n << ", the corner " << str(b) << " lands at depth " << p.z
                                         << ", outside the map's depth range";
      least = glm::min(least, glm::vec2(p)), most = glm::max(most, glm::vec2(p));
    }
    EXPECT_NEAR(least.x, -1, 1e-4) << "WRONG: n = " << n << ": the body must touch the map's left edge";
    EXPECT_NEAR(most.x, 1, 1e-4) << "WRONG: n = " << n << ": the body must touch the map's right edge";
    EXPECT_NEAR(least.y, -1, 1e-4) << "WRONG: n = " << n << ": the body's near side must be the map's bottom edge";
    EXPECT_NEAR(most.y, 1, 1e-4) << "WRONG: n = " << n << ": the body's far side must be the map's top edge";
  }
}

// --- 11.5: one step of the reduction ---------------------------------------------------------------
// (min, max) of the parts that hold something; (0, 0) holds nothing and must not pull the minimum to 0.
TEST_F(GlTest, Ex11_5_ReductionSkipsEmptyTexels) {
  struct Case {
    glm::vec4 ab, cd;
    glm::vec2 want;
    const char* what;
  };
  const Case cases[] = {
      {{3, 5, 2, 9}, {4, 4, 7, 8}, {2, 9}, "four parts that each hold something"},
      {{3, 5, 0, 0}, {4, 4, 0, 0}, {3, 5}, "two empty parts (the sky)"},
      {{0, 0, 0, 0}, {0, 0, 12, 40}, {12, 40}, "one part alone holds something"},
      {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0}, "nothing at all"},
  };
  std::vector<glm::vec4> inputs;
  for (const Case& c : cases) inputs.insert(inputs.end(), {c.ab, c.cd});
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "11.5", "result.xy = minMaxDepth(IN(0).xy, IN(0).zw, IN(1).xy, IN(1).zw);", int(std::size(cases)), 2,
              inputs);
  for (size_t k = 0; k < std::size(cases); ++k) {
    const Case& c = cases[k];
    EXPECT_NEAR(got[k].x, c.want.x, 1e-5)
        << "WRONG: the smallest, " << c.what << ": (" << c.ab.x << ", " << c.ab.y << "), (" << c.ab.z << ", " << c.ab.w
        << "), (" << c.cd.x << ", " << c.cd.y << "), (" << c.cd.z << ", " << c.cd.w << ")";
    EXPECT_NEAR(got[k].y, c.want.y, 1e-5) << "WRONG: the largest, " << c.what;
  }
}

// --- 11.6: fitted splits -----------------------------------------------------------------------------
// Empty bounds (0, 0) on near 1, far 100, four cascades, lambda 0.5: lab 10's practical row, 1, 14.45614,
// 30.25, 53.43639, 100. Bounds 3..48, two cascades: lambda 1: 3, sqrt(3 * 48) = 12, 48; lambda 0: 3, 25.5,
// 48. Bounds 0.05..500 clamp to near 0.1, far 120: lambda 1, 0.1, sqrt(12) = 3.464102, 120. Bounds
// 150..200 beyond far 100 clamp to an empty range, and (5, 5) holds one depth: near..far, lambda 0:
// 1, 50.5, 100.
TEST(Lab11, Ex11_6_SplitsBetweenTheBounds) {
  struct Case {
    glm::vec2 bounds;
    float nearPlane, farPlane;
    int cascades;
    float lambda;
    std::vector<float> want;
    const char* what;
  };
  const Case cases[] = {
      {{0, 0}, 1, 100, 4, 0.5f, {1, 14.45614f, 30.25f, 53.43639f, 100}, "nothing in view: near to far"},
      {{3, 48}, 1, 100, 2, 1, {3, 12, 48}, "bounds 3..48, lambda 1"},
      {{3, 48}, 1, 100, 2, 0, {3, 25.5f, 48}, "bounds 3..48, lambda 0"},
      {{0.05f, 500}, 0.1f, 120, 2, 1, {0.1f, 3.464102f, 120}, "bounds wider than near..far: clamped"},
      {{150, 200}, 1, 100, 2, 0, {1, 50.5f, 100}, "bounds beyond far: an empty range, near to far"},
      {{5, 5}, 1, 100, 2, 0, {1, 50.5f, 100}, "one depth alone: an empty range, near to far"},
  };
  for (const Case& c : cases) {
    std::vector<float> got;
    WB_TRY_EXERCISE(got = WB_CALL(lab11::fittedSplits(c.bounds, c.nearPlane, c.farPlane, c.cascades, c.lambda)));
    ASSERT_EQ(got.size(), c.want.size()) << "WRONG: " << c.what << ": " << c.cascades << " cascades have "
                                         << c.want.size() << " split distances";
    for (size_t i = 0; i < got.size(); ++i)
      EXPECT_NEAR(got[i], c.want[i], 1e-5 * c.want[i])
          << "WRONG: " << c.what << ", C_" << i << " (bounds " << c.bounds.x << ".." << c.bounds.y << ", near "
          << c.nearPlane << ", far " << c.farPlane << ", lambda " << c.lambda << ")";
  }
}

// --- Layer 2 ------------------------------------------------------------------------------------------
namespace {
const float kTol = 0.1f;
const double kMaxFraction = 0.01;
}  // namespace

TEST(Lab11, Ex11_3_SceneFieldLispsm) {
  wb::test::expectSceneMatchesGolden("11.3", "field_lispsm", wb::test::labArgs({}), kTol, kMaxFraction);
}
TEST(Lab11, Ex11_3_SceneOrchardTowardTheSun) {
  wb::test::expectSceneMatchesGolden("11.3", "orchard_toward_sun",
                                     wb::test::labArgs({"light.orbit=180", "warp.sdsm=on"}, "warp_orchard.json"), kTol,
                                     kMaxFraction);
}
TEST(Lab11, Ex11_4_SceneFieldUniform) {
  wb::test::expectSceneMatchesGolden("11.4", "field_uniform", wb::test::labArgs({"warp.scheme=uniform"}), kTol,
                                     kMaxFraction);
}
TEST(Lab11, Ex11_4_SceneFieldLispsm) {
  wb::test::expectSceneMatchesGolden("11.4", "field_lispsm", wb::test::labArgs({}), kTol, kMaxFraction);
}
TEST(Lab11, Ex11_4_SceneFieldCascadesWarped) {
  wb::test::expectSceneMatchesGolden("11.4", "field_csm_lispsm", wb::test::labArgs({"warp.scheme=csm_lispsm"}), kTol,
                                     kMaxFraction);
}
// (SDSM's scenes use one map: cascades fitted to the frame are hunt 11.H1's scenario.)
TEST(Lab11, Ex11_5_SceneFieldSdsm) {
  wb::test::expectSceneMatchesGolden("11.5", "field_lispsm_sdsm", wb::test::labArgs({"warp.sdsm=on"}), kTol,
                                     kMaxFraction);
}
TEST(Lab11, Ex11_5_SceneOrchardSdsm) {
  wb::test::expectSceneMatchesGolden("11.5", "orchard_toward_sun",
                                     wb::test::labArgs({"light.orbit=180", "warp.sdsm=on"}, "warp_orchard.json"), kTol,
                                     kMaxFraction);
}
TEST(Lab11, Ex11_6_SceneFieldCascades) {
  wb::test::expectSceneMatchesGolden("11.6", "field_csm", wb::test::labArgs({"warp.scheme=csm"}), kTol, kMaxFraction);
}
TEST(Lab11, Ex11_6_SceneFieldSdsm) {
  wb::test::expectSceneMatchesGolden("11.6", "field_lispsm_sdsm", wb::test::labArgs({"warp.sdsm=on"}), kTol,
                                     kMaxFraction);
}

// The measure over the ground (a measuring view writes it where the visibility goes, 0 on every
// other surface; the sky keeps the clear value 1 exactly): its quantile q (0.5: the median), or -1
// with `failure` set.
namespace {
double groundQuantile(const std::string& id, const std::string& name, const std::vector<std::string>& settings,
                      std::string& failure, double q = 0.5, const std::string& scene = "") {
  const auto file = wb::test::testOutputDir() / (name + ".pfm");
  std::vector<std::string> args = wb::test::labArgs(settings, scene);
  args.insert(args.end(), {"--size", "480x270", "--dump-visibility", file.string()});
  std::string why;
  wb::test::runLabOutput(id, name, args, why);
  if (!why.empty()) {
    if (failure.empty()) failure = why;
    return -1;
  }
  std::vector<float> v;
  for (float x : wb::readPfm(file).pixels) {
    if (x <= -1e29f) {
      if (failure.empty()) failure = "NOT IMPLEMENTED: the frame shows the not-implemented placeholder";
      return -1;
    }
    if (x > 0 && x != 1.0f && std::isfinite(x)) v.push_back(x);
  }
  if (v.size() < 1000) {
    if (failure.empty()) failure = "WRONG: the measure is 0, negative or not a number over most of the ground";
    return -1;
  }
  const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return double(v[k]);
}
}  // namespace

// Texels per pixel is linear in the map's resolution: the same view with a map twice as large (the
// same matrices) spans twice the texels per pixel, within 2% at the median (the solution at 480x270:
// 0.109 and 0.218).
TEST(Lab11, Ex11_1_MeasuredTwiceTheTexelsOnTwiceTheMap) {
  std::string failure;
  const double small = groundQuantile("11.1", "density_1024", {"warp.view=density", "warp.scheme=uniform"}, failure);
  const double large = groundQuantile("11.1", "density_2048",
                                      {"warp.view=density", "warp.scheme=uniform", "shadow.map_size=2048"}, failure);
  if (!failure.empty()) FAIL() << failure;
  EXPECT_NEAR(large / small, 2.0, 0.04) << "WRONG: the median texels per pixel over the ground is " << small
                                        << " with a 1024 map and " << large << " with a 2048 one";
}

// The perspective part is a distance over a texel's width: twice the map, twice the part. The
// projective part is a ratio of cosines: the map's size changes nothing (the solution at 480x270:
// perspective 0.138 and 0.277, projective 1.79 and 1.79).
TEST(Lab11, Ex11_2_MeasuredPartsAgainstTheMapSize) {
  std::string failure;
  const double p1 =
      groundQuantile("11.2", "perspective_1024", {"warp.view=perspective", "warp.scheme=uniform"}, failure);
  const double p2 = groundQuantile("11.2", "perspective_2048",
                                   {"warp.view=perspective", "warp.scheme=uniform", "shadow.map_size=2048"}, failure);
  const double q1 = groundQuantile("11.2", "projective_1024", {"warp.view=projective", "warp.scheme=uniform"}, failure);
  const double q2 = groundQuantile("11.2", "projective_2048",
                                   {"warp.view=projective", "warp.scheme=uniform", "shadow.map_size=2048"}, failure);
  if (!failure.empty()) FAIL() << failure;
  EXPECT_NEAR(p2 / p1, 2.0, 0.04) << "WRONG: the perspective part's median is " << p1 << " with a 1024 map and " << p2
                                  << " with a 2048 one";
  EXPECT_NEAR(q2 / q1, 1.0, 0.02) << "WRONG: the projective part's median is " << q1 << " with a 1024 map and " << q2
                                  << " with a 2048 one";
}

// The point of the lab: on the orchard, looking toward the sun, LiSPSM fitted to the frame's depths
// gives the worst pixels (the 1st percentile of texels per pixel over the ground) at least twice the
// texels of the uniform map (the solution, at 480x270: 0.0543 and 0.262, 4.8 times).
TEST(Lab11, Ex11_4_MeasuredTheWarpRaisesTheWorstPixels) {
  // (Where 11.3 failed its own tests, the grader replays its n here, and the gain would be its doing:
  // 11.4's scene and layer-1 tests judge it then.)
  if (wb::test::replaysFailedUse("11.3")) GTEST_SKIP() << "11.3 failed its own tests: its n decides this gain";
  std::string failure;
  const std::string orchard = "warp_orchard.json";
  const double uniform = groundQuantile("11.4", "orchard_uniform",
                                        {"warp.view=density", "warp.scheme=uniform", "light.orbit=180", "warp.sdsm=on"},
                                        failure, 0.01, orchard);
  const double warped = groundQuantile("11.4", "orchard_lispsm",
                                       {"warp.view=density", "warp.scheme=lispsm", "light.orbit=180", "warp.sdsm=on"},
                                       failure, 0.01, orchard);
  if (!failure.empty()) FAIL() << failure;
  EXPECT_GT(warped, 2 * uniform) << "WRONG: the orchard toward the sun: the worst 1% of the ground gets " << warped
                                 << " texels per pixel from the warped map and " << uniform
                                 << " from the uniform one (want at least twice)";
}

// --- Bug hunt 11.H1: "with SDSM on, the cascades give fewer texels than without" -------------------------
// The camera pass must move to the next cascade exactly where the maps were fitted to end: at C_1 ..
// C_(N-1) of 11.6, whatever range they were fitted over. Fitted to the frame, 4 .. 120 with C = 4, 12,
// 30, 120: 12 and 30 (the bug turns the fractions 8/116 and 26/116 back over 0.1 .. 120: 8.36 and 26.99).
// Not fitted (near 0.1 to 120): 10. Fitted 20 .. 60 on near 1, far 100: 35.
// --- The measure against the geometry -------------------------------------------------------------------
// scenes/warp_plane.json: a flat ground, a sun straight above, the camera at target (0, 0, -10),
// distance 8, yaw 20, pitch 25, fov 50 (OrbitCamera: eye = target + 8 (sin 20 cos 25, sin 25, cos 20
// cos 25)), near 0.1, at 480x270 (the grader turns sun and camera a little: the test reads the scene
// and turns it as the lab does); the uniform map covers the view's slice from 0.1 to 120 (the default
// warp.shadow_distance). Worked out here from the geometry alone: the slice's corners in the light's
// view (looking down, its y the view direction across the light) give the map's texel w_x by w_y; the
// rays through neighbouring pixel centres meet the ground at X; a pixel step moves the map by
// ((dX . e_x) / w_x, (dX . e_y) / w_y) texels. The GPU's derivative is a difference within a 2x2 quad,
// taken on either of its rows or columns (coarse or fine), so the bound is the smallest and largest of
// those candidates, widened by 0.2% for float: every ground pixel's measure must lie within it.
namespace {
struct PlaneTruth {
  glm::dmat4 toWorld;   // clip to world
  glm::dvec3 ex, ey;    // the map's axes in the world
  double wx, wy;        // a texel's width along them
  glm::dmat4 view;      // the camera's
  glm::dvec3 back;      // from the target towards the eye (unit)
  glm::dvec3 lightDir;  // the direction the light travels (unit)
  double fov = 0;       // vertical, radians
  int width = 480, height = 270;
  glm::dvec3 ground(double px, double py) const {  // where the ray through pixel centre (px, py) meets y = 0
    const glm::dvec4 a = toWorld * glm::dvec4((px + 0.5) / width * 2 - 1, (py + 0.5) / height * 2 - 1, -1, 1);
    const glm::dvec4 b = toWorld * glm::dvec4((px + 0.5) / width * 2 - 1, (py + 0.5) / height * 2 - 1, 1, 1);
    const glm::dvec3 p = glm::dvec3(a) / a.w, q = glm::dvec3(b) / b.w;
    return p + (q - p) * (-p.y / (q.y - p.y));
  }
  double texels(glm::dvec3 step) const {
    return glm::length(glm::dvec2(glm::dot(step, ex) / wx, glm::dot(step, ey) / wy));
  }
};

// The plane scene as the lab draws it: under the grader's variations (WB_VARY_SEED), turned as the
// lab turns it, so the geometry below is the varied one.
wb::Scene planeScene() {
  wb::Scene s = wb::Scene::load(wb::test::labArgs({}, "warp_plane.json").at(1));
  if (wb::test::varySeed() >= 0) wb::varyScene(s, uint32_t(wb::test::varySeed()));
  return s;
}

// The uniform map's texel on the plane, fitted to the view's slice between distances d0 and d1 (the
// whole shadow distance, or one cascade's slice).
PlaneTruth planeTruth(double d0 = 0.1, double d1 = 120.0) {
  PlaneTruth t;
  const wb::Scene s = planeScene();
  const wb::CameraBookmark& c = s.cameras.front();
  const double yaw = glm::radians(double(c.yaw)), pitch = glm::radians(double(c.pitch));
  const glm::dvec3 target(c.target);
  t.back = glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  t.lightDir = glm::normalize(glm::dvec3(s.lights.front().direction));
  t.view = glm::lookAt(target + double(c.distance) * t.back, target, glm::dvec3(0, 1, 0));
  t.fov = glm::radians(double(c.fov));
  const double aspect = double(t.width) / t.height;
  t.toWorld = glm::inverse(glm::perspective(t.fov, aspect, 0.1, 200.0) * t.view);
  const glm::dmat4 light = glm::lookAt(glm::dvec3(0), t.lightDir, -t.back);
  t.ex = glm::dvec3(light[0][0], light[1][0], light[2][0]), t.ey = glm::dvec3(light[0][1], light[1][1], light[2][1]);
  const glm::dmat4 slice = glm::inverse(glm::perspective(t.fov, aspect, d0, d1) * t.view);
  glm::dvec2 lo(1e30), hi(-1e30);
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 q = slice * glm::dvec4(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1, 1);
    const glm::dvec3 p = glm::dvec3(q) / q.w;
    const glm::dvec2 l(glm::dot(p, t.ex), glm::dot(p, t.ey));
    lo = glm::min(lo, l), hi = glm::max(hi, l);
  }
  t.wx = (hi.x - lo.x) / 1024, t.wy = (hi.y - lo.y) / 1024;
  return t;
}

// Runs the plane scene with `settings` and holds every sampled ground pixel's measure within the bound
// the geometry gives: `texels(at, step)` is a pixel step's texels at the ground point `at` (NaN: a
// pixel the geometry cannot decide, such as one on a cascade's split, which is skipped).
void expectPlaneMeasureWithinGeometry(const std::string& name, std::vector<std::string> settings,
                                      const std::function<double(glm::dvec3, glm::dvec3)>& texels) {
  const auto file = wb::test::testOutputDir() / (name + ".pfm");
  settings.insert(settings.begin(), "warp.view=density");
  std::vector<std::string> args = wb::test::labArgs(settings, "warp_plane.json");
  args.insert(args.end(), {"--size", "480x270", "--dump-visibility", file.string()});
  std::string why;
  wb::test::runLabOutput("11.1", name, args, why);
  if (!why.empty()) FAIL() << why;
  const wb::FloatImage got = wb::readPfm(file);
  const PlaneTruth t = planeTruth();
  int checked = 0, outside = 0;
  std::string first;
  for (int py = 2; py < t.height / 2; py += 5)
    for (int px = 2; px < t.width - 2; px += 7) {
      const float m = got.at(px, py);
      if (m <= -1e29f) FAIL() << "NOT IMPLEMENTED: the frame shows the not-implemented placeholder";
      if (!(m > 0) || m == 1.0f) continue;  // (the post, or the sky)
      const int qx = px & ~1, qy = py & ~1;
      const glm::dvec3 at = t.ground(px, py);
      double lo = 1e30, hi = 0;
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
          const double tx = texels(at, t.ground(qx + 1, qy + r) - t.ground(qx, qy + r));
          const double ty = texels(at, t.ground(qx + c, qy + 1) - t.ground(qx + c, qy));
          lo = std::min(lo, std::min(tx, ty)), hi = std::max(hi, std::min(tx, ty));
        }
      if (std::isnan(lo) || std::isnan(hi) || !(lo < 1e30)) continue;
      ++checked;
      if ((m < lo * 0.998 || m > hi * 1.002) && outside++ == 0)
        first = "pixel (" + std::to_string(px) + ", " + std::to_string(py) + "): measured " + std::to_string(m) +
                " texels per pixel, the geometry gives " + std::to_string(lo) + " to " + std::to_string(hi);
    }
  ASSERT_GT(checked, 200) << "ERROR: too few ground pixels were measured";
  EXPECT_EQ(outside, 0) << "WRONG: " << outside << " of " << checked << " ground pixels outside the bound; first, "
                        << first;
}
}  // namespace

// The same plane under LiSPSM at n_opt (warp.scheme=lispsm, strength 1: sin g, about cos 25 degrees,
// is past the fade): the map coordinate is the perspective of section 3, built here in double from the
// handout's definition (the slice's light-space bounds, n_opt from z0 = 0.1 and d, the eye n before
// the body on its x centre, x fitted after the divide), and a pixel step moves it by its Jacobian at
// the pixel (a central difference in double) times the step on the ground.
namespace {
struct WarpedPlane {
  PlaneTruth plane;
  glm::dmat4 light;
  double n = 0, lowY = 0, a = 0, b = 0, cx = 0, sx = 1, ox = 0;
  glm::dvec2 uv(glm::dvec3 p) const {
    const glm::dvec3 l(light * glm::dvec4(p, 1));
    const double t = l.y - lowY + n;
    return 0.5 * glm::dvec2(sx * n * (l.x - cx) / t + ox, (a * t + b) / t) + 0.5;
  }
  double texels(glm::dvec3 at, glm::dvec3 step) const {
    const double e = 1e-4;
    return glm::length((uv(at + e * step) - uv(at - e * step)) / (2 * e) * 1024.0);
  }
};

WarpedPlane warpedPlane() {
  WarpedPlane w;
  w.plane = planeTruth();
  const PlaneTruth& t = w.plane;
  w.light = glm::lookAt(glm::dvec3(0), t.lightDir, -t.back);
  const glm::dmat4 slice = glm::inverse(glm::perspective(t.fov, 480.0 / 270, 0.1, 120.0) * t.view);
  std::vector<glm::dvec3> body;
  glm::dvec3 lo(1e30), hi(-1e30);
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 c = slice * glm::dvec4(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1, 1);
    body.push_back(glm::dvec3(w.light * glm::dvec4(glm::dvec3(c) / c.w, 1)));
    lo = glm::min(lo, body.back()), hi = glm::max(hi, body.back());
  }
  const double sinGamma = glm::length(glm::cross(-t.back, t.lightDir)), d = hi.y - lo.y, z1 = 0.1 + d * sinGamma;
  const double fade = std::clamp((sinGamma - 0.02) / (0.5 - 0.02), 0.0, 1.0);  // (1 here: the view is steep)
  w.n = (0.1 + std::sqrt(0.1 * z1)) / sinGamma / fade, w.lowY = lo.y, w.cx = 0.5 * (lo.x + hi.x);
  const double f = w.n + d;
  w.a = (f + w.n) / (f - w.n), w.b = -2 * f * w.n / (f - w.n);
  double xl = 1e30, xh = -1e30;
  for (const glm::dvec3& l : body) {
    const double x = w.n * (l.x - w.cx) / (l.y - lo.y + w.n);
    xl = std::min(xl, x), xh = std::max(xh, x);
  }
  w.sx = 2 / (xh - xl), w.ox = -(xh + xl) / (xh - xl);
  return w;
}
}  // namespace

TEST(Lab11, Ex11_1_MeasuredAgainstTheWarpedPlaneTruth) {
  const WarpedPlane w = warpedPlane();
  expectPlaneMeasureWithinGeometry("plane_density_lispsm", {"warp.scheme=lispsm"},
                                   [&](glm::dvec3 at, glm::dvec3 step) { return w.texels(at, step); });
}

TEST(Lab11, Ex11_1_MeasuredAgainstTheGroundPlaneTruth) {
  const PlaneTruth t = planeTruth();
  expectPlaneMeasureWithinGeometry("plane_density", {"warp.scheme=uniform"},
                                   [&](glm::dvec3, glm::dvec3 step) { return t.texels(step); });
}

// Logarithmic splits (warp.scheme=csm, csm.lambda=1, three cascades): C_i = n (f / n)^(i/3) between
// the near plane 0.1 and the shadow distance 120, and each cascade a uniform map fitted to its slice
// as above. A ground pixel is drawn from the cascade its view distance falls in; pixels within 0.5%
// of a split are left out (a quad there may take its derivative from either side).
TEST(Lab11, Ex11_1_MeasuredAgainstTheLogarithmicPlaneTruth) {
  const int n = 3;
  std::vector<double> c;
  std::vector<PlaneTruth> slices;
  for (int i = 0; i <= n; ++i) c.push_back(0.1 * std::pow(120.0 / 0.1, double(i) / n));
  for (int i = 0; i < n; ++i) slices.push_back(planeTruth(c[size_t(i)], c[size_t(i) + 1]));
  const glm::dmat4 view = slices.front().view;
  expectPlaneMeasureWithinGeometry("plane_density_log", {"warp.scheme=csm", "csm.cascades=3", "csm.lambda=1"},
                                   [&](glm::dvec3 at, glm::dvec3 step) {
                                     const double depth = -(view * glm::dvec4(at, 1)).z;
                                     size_t k = 0;
                                     while (k + 1 < size_t(n) && depth >= c[k + 1]) ++k;
                                     for (size_t i = 1; i < size_t(n); ++i)
                                       if (std::abs(depth - c[i]) < 0.005 * c[i]) return std::nan("");
                                     return slices[k].texels(step);
                                   });
}

TEST(Lab11, Ex11_H1_SwitchWhereTheMapsWereFitted) {
  struct Case {
    std::vector<float> splits;
    float nearPlane, farPlane;
    std::vector<float> want;
    const char* what;
  };
  const Case cases[] = {
      {{4, 12, 30, 120}, 0.1f, 120, {12, 30}, "fitted to the frame, 4 .. 120"},
      {{0.1f, 10, 120}, 0.1f, 120, {10}, "near to far (no SDSM)"},
      {{20, 35, 60}, 1, 100, {35}, "fitted to the frame, 20 .. 60"},
  };
  for (const Case& c : cases) {
    std::vector<float> got;
    WB_TRY_EXERCISE(got = WB_CALL(lab11::switchDistances(c.splits, c.nearPlane, c.farPlane)));
    ASSERT_EQ(got.size(), c.want.size()) << "WRONG: " << c.what << ": " << c.splits.size() - 1 << " cascades switch at "
                                         << c.want.size() << " distances";
    for (size_t i = 0; i < got.size(); ++i)
      EXPECT_NEAR(got[i], c.want[i], 1e-4 * c.want[i])
          << "WRONG: " << c.what << ": the camera pass leaves cascade " << i << " at " << got[i]
          << ", but its map was fitted to end at C_" << i + 1 << " = " << c.want[i];
  }
}

// The scenario: three cascades fitted to the field's frame, logarithmic splits: the median texels per
// pixel over the ground must be at least 1.15 times that of the same cascades between near and far
// (the solution at 480x270: 1.01 and 0.775, 1.30 times; the bug as handed out: 0.838, 1.08 times).
TEST(Lab11, Ex11_H1_MeasuredSdsmGivesMoreTexels) {
  if (wb::test::replaysFailedUse("11.6")) GTEST_SKIP() << "11.6 failed its own tests: its splits decide this gain";
  std::string failure;
  const std::vector<std::string> common = {"warp.view=density", "warp.scheme=csm", "csm.lambda=1"};
  auto with = [&](const char* sdsm) {
    std::vector<std::string> s = common;
    s.push_back(std::string("warp.sdsm=") + sdsm);
    return s;
  };
  const double off = groundQuantile("11.H1", "csm_sdsm_off", with("off"), failure);
  const double on = groundQuantile("11.H1", "csm_sdsm_on", with("on"), failure);
  if (!failure.empty()) FAIL() << failure;
  EXPECT_GT(on, 1.15 * off) << "WRONG: three cascades fitted to the frame give the ground a median of " << on
                            << " texels per pixel, and between near and far " << off
                            << ": fitting to the frame must give more";
}

TEST(Lab11, Ex11_H1_SceneCascadesFittedToTheFrame) {
  wb::test::expectSceneMatchesGolden("11.H1", "field_csm_sdsm",
                                     wb::test::labArgs({"warp.scheme=csm", "warp.sdsm=on", "csm.lambda=1"}), kTol,
                                     kMaxFraction);
}
