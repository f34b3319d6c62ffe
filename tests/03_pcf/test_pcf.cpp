// Lab 03 tests. Layer 1: every filter against a double-precision emulation of the same taps on a
// 16x16 depth map (nearest-texel lookups, depth 1 outside the map); layer 2: the canonical scene
// against golden visibility (./workbook golden 03).
#include "common/base/variant.hpp"
#include "common/judge/harness.hpp"
#include "common/judge/hunt.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/texture_io.hpp"

#include <glm/gtc/constants.hpp>

#include <cmath>

using wb::test::GlTest;

namespace {

constexpr int kSize = 16;

// A depth map with steps (edges for the filters to soften) and a gentle slope.
struct DepthMap {
  std::vector<float> depth = std::vector<float>(kSize * kSize);
  wb::Texture texture;
  DepthMap() {
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) depth[y * kSize + x] = ((x / 3 + y / 5) % 2 ? 0.3f : 0.7f) + 0.01f * float(x);
    texture = wb::makeTexture2D(GL_DEPTH_COMPONENT32F, kSize, kSize, GL_NEAREST, GL_CLAMP_TO_BORDER);
    const float outside[4] = {1, 1, 1, 1};
    wb::setTextureBorder(texture.id(), outside);
    wb::uploadTexture2D(texture.id(), 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  // Nearest-texel lookup as GL does it, with the border outside.
  double at(double u, double v) const {
    const int x = int(std::floor(u * kSize)), y = int(std::floor(v * kSize));
    if (x < 0 || y < 0 || x >= kSize || y >= kSize) return 1.0;
    return depth[y * kSize + x];
  }
  double lit(double u, double v, double z) const { return z <= at(u, v) ? 1.0 : 0.0; }
};

// Lookup positions a third of a texel off the texel grid, so no tap lands on a texel boundary.
std::vector<glm::vec4> probes() {
  std::vector<glm::vec4> in;
  for (int k = 0; k < 24; ++k) {
    const float u = (float(2 + (k * 5) % 12) + 0.33f) / kSize, v = (float(2 + (k * 7) % 12) + 0.33f) / kSize;
    in.emplace_back(u, v, k % 2 ? 0.5f : 0.66f, k % 3 ? 0.0f : 0.02f);  // xy, receiver depth, bias
  }
  return in;
}

}  // namespace

// --- 03.1: the grid ---------------------------------------------------------------------------------
TEST_F(GlTest, Ex03_1_GridAveragesComparisons) {
  DepthMap map;
  for (int radius : {0, 1, 2})
    for (float spacing : {1.0f, 2.0f}) {
      const auto in = probes();
      std::vector<glm::vec4> got;
      const std::string body = "result.x = pcfGrid(wb_tex0, IN(0).xyz, " + std::to_string(radius) + ", " +
                               std::to_string(spacing) + ", IN(0).w);";
      WB_RUN_GLSL(got, "03.1", body, int(in.size()), 1, in, {map.texture.id()});
      for (size_t k = 0; k < in.size(); ++k) {
        double sum = 0;
        for (int j = -radius; j <= radius; ++j)
          for (int i = -radius; i <= radius; ++i)
            sum += map.lit(in[k].x + i * spacing / kSize, in[k].y + j * spacing / kSize, double(in[k].z) - in[k].w);
        const double want = sum / ((2 * radius + 1) * (2 * radius + 1));
        ASSERT_NEAR(got[k].x, want, 1e-5) << "WRONG: radius " << radius << ", spacing " << spacing << ", case " << k;
      }
    }
}

// --- 03.2: the hardware filter, at texel centres where it must equal one comparison -------------
TEST_F(GlTest, Ex03_2_HardwareMatchesOneCompareAtTexelCentres) {
  DepthMap map;
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  wb::bindTexture(7, map.texture.id());
  glBindSampler(7, sampler);
  std::vector<glm::vec4> in;
  std::vector<double> want;
  for (int k = 0; k < 24; ++k) {
    const int x = 2 + (k * 5) % 12, y = 2 + (k * 7) % 12;
    // Receivers a little in front of, just behind and well behind the stored depth, with and
    // without a bias that decides the middle case.
    const float z = map.depth[y * kSize + x] + (k % 3 == 0 ? -0.03f : k % 3 == 1 ? 0.01f : 0.03f);
    const float bias = k % 2 ? 0.0f : 0.02f;
    in.emplace_back((x + 0.5f) / kSize, (y + 0.5f) / kSize, z, bias);
    want.push_back(double(z) - bias <= map.depth[y * kSize + x] ? 1.0 : 0.0);
  }
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "03.2", "result.x = pcfHardware(wb_shadow0, IN(0).xyz, IN(0).w);", int(in.size()), 1, in);
  glBindSampler(7, 0);
  glDeleteSamplers(1, &sampler);
  for (size_t k = 0; k < in.size(); ++k)
    ASSERT_NEAR(got[k].x, want[k], 1e-3) << "WRONG: at a texel centre the 2x2 filter is one comparison, case " << k;
}

// --- 03.3: Gaussian weights ---------------------------------------------------------------------
TEST_F(GlTest, Ex03_3_GaussianWeightAndFilter) {
  DepthMap map;
  std::vector<glm::vec4> win;
  for (glm::vec2 o : {glm::vec2(0), glm::vec2(1, 0), glm::vec2(1, 2), glm::vec2(-3, 0.5f)})
    for (float sigma : {0.5f, 1.0f, 2.0f}) win.emplace_back(o, sigma, 0);
  std::vector<glm::vec4> w;
  WB_RUN_GLSL(w, "03.3", "result.x = gaussianWeight(IN(0).xy, IN(0).z);", int(win.size()), 1, win);
  for (size_t k = 0; k < win.size(); ++k) {
    const double want = std::exp(-(win[k].x * win[k].x + win[k].y * win[k].y) / (2.0 * win[k].z * win[k].z));
    ASSERT_NEAR(w[k].x, want, 1e-5) << "WRONG: gaussianWeight(" << win[k].x << ", " << win[k].y << "; sigma "
                                    << win[k].z << ")";
  }
  // Tap (i, j) is (i, j) * spacing texels away, and weighted by that offset in texels (sigma is in texels).
  const auto in = probes();
  for (float spacing : {1.0f, 2.0f}) {
    std::vector<glm::vec4> got;
    WB_RUN_GLSL(got, "03.3",
                "result.x = pcfGaussian(wb_tex0, IN(0).xyz, 2, " + std::to_string(spacing) + ", 1.2, IN(0).w);",
                int(in.size()), 1, in, {map.texture.id()});
    for (size_t k = 0; k < in.size(); ++k) {
      double sum = 0, weights = 0;
      for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
          const double ox = i * spacing, oy = j * spacing;  // texels
          const double wt = std::exp(-(ox * ox + oy * oy) / (2.0 * 1.2 * 1.2));
          sum += wt * map.lit(in[k].x + ox / kSize, in[k].y + oy / kSize, double(in[k].z) - in[k].w);
          weights += wt;
        }
      ASSERT_NEAR(got[k].x, sum / weights, 1e-5)
          << "WRONG: the weighted mean, normalised by the weights, spacing " << spacing << ", case " << k;
    }
  }
}

// --- 03.4: the rotated Poisson disk ---------------------------------------------------------------
// The disk and the hash are the harness's (shaders/wb/poisson.glsl, hash.glsl): read them from the
// GPU, then emulate the rotated taps in double.
TEST_F(GlTest, Ex03_4_PoissonRotatesTheDiskPerPixel) {
  DepthMap map;
  std::vector<glm::vec4> disk, hash;
  WB_RUN_GLSL(disk, "03.4", "result = vec4(WB_POISSON_DISK[wb_i], 0.0, 0.0);", 64, 1, {});
  const auto in = probes();
  std::vector<glm::vec4> pixels;
  for (size_t k = 0; k < in.size(); ++k) pixels.emplace_back(float(k * 37 % 101), float(k * 11 % 53), 0, 0);
  WB_RUN_GLSL(hash, "03.4", "result.x = wbHash01(uvec2(IN(0).xy));", int(pixels.size()), 1, pixels);
  for (int count : {16, 64}) {
    std::vector<glm::vec4> both;
    for (size_t k = 0; k < in.size(); ++k) both.push_back(in[k]), both.push_back(pixels[k]);
    std::vector<glm::vec4> got;
    const std::string body =
        "result.x = pcfPoisson(wb_tex0, IN(0).xyz, " + std::to_string(count) + ", 2.5, uvec2(IN(1).xy), IN(0).w);";
    WB_RUN_GLSL(got, "03.4", body, int(in.size()), 2, both, {map.texture.id()});
    for (size_t k = 0; k < in.size(); ++k) {
      const double a = 2 * glm::pi<double>() * hash[k].x, c = std::cos(a), s = std::sin(a);
      double sum = 0;
      for (int t = 0; t < count; ++t) {
        const double px = c * disk[t].x - s * disk[t].y, py = s * disk[t].x + c * disk[t].y;
        sum += map.lit(in[k].x + px * 2.5 / kSize, in[k].y + py * 2.5 / kSize, double(in[k].z) - in[k].w);
      }
      // A tap within rounding of a texel edge may fall either way: allow one tap of difference.
      ASSERT_NEAR(got[k].x, sum / count, 1.0 / count + 1e-5) << "WRONG: " << count << " taps, case " << k;
    }
  }
}

// --- 03.5: textureGather gives the grid's answer ----------------------------------------------------
TEST_F(GlTest, Ex03_5_GatherEqualsTheGrid) {
  DepthMap map;
  for (int radius : {0, 1, 2, 3}) {
    const auto in = probes();
    std::vector<glm::vec4> got;
    WB_RUN_GLSL(got, "03.5", "result.x = pcfGather(wb_tex0, IN(0).xyz, " + std::to_string(radius) + ", IN(0).w);",
                int(in.size()), 1, in, {map.texture.id()});
    for (size_t k = 0; k < in.size(); ++k) {
      double sum = 0;
      for (int j = -radius; j <= radius; ++j)
        for (int i = -radius; i <= radius; ++i)
          sum += map.lit(in[k].x + double(i) / kSize, in[k].y + double(j) / kSize, double(in[k].z) - in[k].w);
      ASSERT_NEAR(got[k].x, sum / ((2 * radius + 1) * (2 * radius + 1)), 1e-5)
          << "WRONG: radius " << radius << ": the gathered taps must equal the " << 2 * radius + 1 << "x"
          << 2 * radius + 1 << " grid, case " << k;
    }
  }
}

// --- Layer 2 ----------------------------------------------------------------------------------------
// Filtered visibility is fractional: a pixel fails beyond 0.1, with the usual 3x3 neighbourhood.
namespace {
const float kTol = 0.1f;
const double kMaxFraction = 0.005;
}  // namespace

// 03.2 is implementation-defined (each GPU filters its own way), so it has no golden image. In the
// app it must still draw the scene's shadows: against exact visibility, little light leaks into them
// and almost no acne. (A shadow map bound where the scene's textures go once passed every other test
// and leaked 85% of the shadows; this one caught it.)
TEST(Lab03, Ex03_2_MeasuredHardwareDrawsTheShadows) {
  const auto m = wb::test::measureScene("03.2", "measure_hardware", wb::test::labArgs({"pcf.method=hardware"}));
  if (!m.failure.empty()) FAIL() << m.failure;
  EXPECT_LT(m.leakPercent, 20) << "WRONG: " << m.leakPercent << "% of the truly shadowed pixels are drawn lit";
  EXPECT_LT(m.acnePercent, 2) << "WRONG: " << m.acnePercent << "% of the lit pixels are drawn shadowed";
}

TEST(Lab03, Ex03_1_SceneGrid5x5) {
  wb::test::expectSceneMatchesGolden("03.1", "grid_5x5", wb::test::labArgs({"pcf.method=grid", "pcf.kernel=5"}), kTol,
                                     kMaxFraction);
}
TEST(Lab03, Ex03_3_SceneGaussian) {
  wb::test::expectSceneMatchesGolden("03.3", "gaussian_5x5",
                                     wb::test::labArgs({"pcf.method=gaussian", "pcf.kernel=5", "pcf.spacing=1.5"}),
                                     kTol, kMaxFraction);
}
TEST(Lab03, Ex03_4_ScenePoisson) {
  wb::test::expectSceneMatchesGolden(
      "03.4", "poisson_32", wb::test::labArgs({"pcf.method=poisson", "pcf.poisson_count=32"}), kTol, kMaxFraction);
}
// The gather filter is held to the grid's golden data: the same answer from fewer fetches.
TEST(Lab03, Ex03_5_SceneGatherMatchesGrid) {
  wb::test::expectSceneMatchesGolden("03.5", "grid_5x5", wb::test::labArgs({"pcf.method=gather", "pcf.kernel=5"}), kTol,
                                     kMaxFraction);
}

// --- Bug hunt 03.H1: "dark ground under the short lamp" -------------------------------------------
// The lamp of scenes/pcf_short_lamp.json ends 15 units away, inside the ground it lights: beyond its far
// plane the map holds no depth, and nothing there is in shadow (the exact answer, by rays, says so).
// Judged against that exact answer, not against a line of code: any fix that removes the dark band
// and keeps every true shadow passes; hiding shadows, a margin or a bias does not.
std::vector<std::string> shortLamp() {
  return wb::test::labArgs({"pcf.method=grid", "pcf.kernel=3"}, "pcf_short_lamp.json");
}

// The reference measures 0.04% acne and 2.15% leak (./workbook run 03 --headless --size 480x270
// --scene scenes/pcf_short_lamp.json --set pcf.kernel=3 --metrics); as handed out, 4.47% acne.
TEST(Lab03, Ex03_H1_MeasuredNoShadowBeyondTheLampsReach) {
  wb::test::expectSymptomGone("03.H1", "hunt_short_lamp", shortLamp(), {1.0, 10.0});
}

TEST(Lab03, Ex03_H1_SceneShortLamp) {
  wb::test::expectSceneMatchesGolden("03.H1", "hunt_short_lamp", shortLamp(), kTol, kMaxFraction);
}

// --- Bug hunt 03.H2: "acne when the filter is one tap wide" -----------------------------------------
// The contract (exercise.glsl): shadow.bias is a single tap's, and each texel a filter's taps reach
// along an axis of the map needs one more of it. Values at reaches 0 to 7, the handed-out bug's
// "none at all for one tap" first.
TEST_F(GlTest, Ex03_H2_BiasGrowsWithTheReach) {
  const std::vector<glm::vec4> in = {{0.003f, 0.0f, 0, 0}, {0.003f, 1.0f, 0, 0}, {0.002f, 2.5f, 0, 0},
                                     {0.01f, 7.0f, 0, 0},  {0.003f, 0.5f, 0, 0}, {0.0f, 3.0f, 0, 0}};
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "03.H2", "result.x = filterBias(IN(0).x, IN(0).y);", int(in.size()), 1, in, {});
  for (size_t k = 0; k < in.size(); ++k)
    ASSERT_NEAR(got[k].x, in[k].x * (1.0 + in[k].y), 1e-7 + 1e-5 * in[k].x * (1.0 + in[k].y))
        << "WRONG: a single tap's bias " << in[k].x << ", taps reaching " << in[k].y
        << " texels: one more bias per texel of reach";
}

// Judged against exact visibility: one tap (pcf.kernel=1) must show no acne, and the widest grid must
// show neither acne (too little bias for its reach) nor the leaks of far too much.
TEST(Lab03, Ex03_H2_MeasuredNoAcneWithOneTap) {
  wb::test::expectSymptomGone("03.H2", "hunt_one_tap", wb::test::labArgs({"pcf.method=grid", "pcf.kernel=1"}),
                              {1.0, 10.0});
}
TEST(Lab03, Ex03_H2_MeasuredNoAcneWithTheWidestGrid) {
  wb::test::expectSymptomGone("03.H2", "hunt_wide_grid",
                              wb::test::labArgs({"pcf.method=grid", "pcf.kernel=7", "pcf.spacing=2"}), {1.0, 35.0});
}
