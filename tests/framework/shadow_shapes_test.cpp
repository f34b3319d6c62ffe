// Shadow maps of every shape render a known scene, the debug views show them the right way up, and
// the frame target counts in its stencil. Every expected value is worked out by hand in a comment.
#include "common/base/variant.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/frame_target.hpp"
#include "common/platform/shader.hpp"
#include "common/platform/texture_io.hpp"
#include "common/scene/scene.hpp"
#include "common/shadows/shadow_map.hpp"
#include "common/shell/debug_views.hpp"
#include "common/truth/measurement.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using wb::test::GlTest;

namespace {

// A 10 x 10 ground plane at y = 0 and one point light 2 above its centre.
wb::Scene groundScene() {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "shapes";
  fs::create_directories(dir);
  std::ofstream(dir / "ground.json") << R"({"objects": [{"shape": "plane", "size": [10, 0, 10]}],
      "lights": [{"type": "point", "position": [0, 2, 0], "near": 0.5, "far": 10}]})";
  return wb::Scene::load(dir / "ground.json");
}

// Window depth of a point `d` in front of a perspective camera (near n, far f): NDC
// z = (f + n)/(f - n) - 2 f n / ((f - n) d), mapped from [-1, 1] to [0, 1].
float perspectiveDepth(float d, float n, float f) {
  const float ndc = (f + n) / (f - n) - 2 * f * n / ((f - n) * d);
  return 0.5f * ndc + 0.5f;
}

// The six face matrices with GL's cube-map orientation (the up vectors lab 08.1 asks for).
std::vector<glm::mat4> faceMatrices(glm::vec3 eye, float n, float f) {
  const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  std::vector<glm::mat4> m;
  for (int k = 0; k < 6; ++k)
    m.push_back(glm::perspective(glm::radians(90.0f), 1.0f, n, f) * glm::lookAt(eye, eye + dirs[k], ups[k]));
  return m;
}

float texel(GLuint texture, int x, int y, int layer) {
  float v = -1;
  wb::readTextureRect(texture, x, y, layer, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &v);
  return v;
}

wb::Program depthProgram() {
  return wb::Program({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
}

// Renders the six faces of `cube` (64 texels) from `faces`, one face at a time.
void renderCube(const wb::Scene& scene, const std::vector<glm::mat4>& faces, wb::CubeShadowMap& cube) {
  const wb::GpuScene gpu(scene);
  const wb::Program depth = depthProgram();
  depth.set("u_alphaCutoff", 0.5f);
  cube.resize(64);
  for (int face = 0; face < 6; ++face) {
    cube.begin(face);
    depth.set("u_lightViewProj", faces[size_t(face)]);
    gpu.draw(depth);
  }
}

}  // namespace

// The cube's −Y face looks straight down at the plane, 2 away along its axis, so every texel holds
// the window depth of 2. The +Y face sees nothing (depth 1). The +X face, with up = −Y, sees the
// ground in its top rows: row r looks down by ndc_y = (r + 0.5)/32 − 1 per unit ahead, meeting the
// ground 2 / ndc_y ahead; its bottom rows see the sky.
TEST_F(GlTest, CubeShadowMapRendersEachFaceTheRightWayUp) {
  const wb::Scene scene = groundScene();
  const auto faces = faceMatrices({0, 2, 0}, 0.5f, 10);
  wb::CubeShadowMap cube;
  renderCube(scene, faces, cube);
  const float down = perspectiveDepth(2, 0.5f, 10);  // 0.78947
  for (int x : {0, 31, 63}) {
    EXPECT_NEAR(texel(cube.texture(), x, 17, 3), down, 1e-4) << "-Y face, column " << x;
    EXPECT_EQ(texel(cube.texture(), x, 40, 2), 1.0f) << "+Y face sees no ground";
  }
  const float ndcY = 63.5f / 32 - 1;
  EXPECT_NEAR(texel(cube.texture(), 32, 63, 0), perspectiveDepth(2 / ndcY, 0.5f, 10), 1e-3) << "+X face, top row";
  EXPECT_EQ(texel(cube.texture(), 32, 0, 0), 1.0f) << "+X face, bottom row: sky";
  const wb::LightView v = cube.describe(scene.lights[0], faces, false);
  EXPECT_EQ(v.viewProj.size(), 6u);
  EXPECT_EQ(v.target, GLenum(GL_TEXTURE_CUBE_MAP));
  EXPECT_FALSE(v.isSingle2D());
}

// The unfolded cross reads the cube through samplerCube (the lookup lab 08 uses): the −Y cell shows
// the linear depth (2 − 0.5) / 9.5 = 0.158 (40 of 255), the +Y cell white, and the +X cell (left of
// +Z, as seen from the light) the ground below its middle and the sky above it.
TEST_F(GlTest, CubeInsetShowsTheUnfoldedCross) {
  const wb::Scene scene = groundScene();
  const auto faces = faceMatrices({0, 2, 0}, 0.5f, 10);
  wb::CubeShadowMap cube;
  renderCube(scene, faces, cube);
  wb::FrameTarget target;
  target.resize({448, 224});
  target.clear();
  wb::DebugOptions show;
  show.showMap = true;
  wb::DebugViews().draw(show, cube.describe(scene.lights[0], faces, false), glm::mat4(1), target, 0);
  const auto px = target.readColor();
  wb::writePng(fs::path(wb::variant::kOutputDir) / "shapes" / "cube_cross.png", 448, 224, px);  // to look at
  auto red = [&](int x, int y) { return int(px[(size_t(y) * 448 + size_t(x)) * 4]); };
  // Cells are 224 / 7 = 32 pixels (the cross fits the left half of 448), from (8, 8): cell (i, j) is centred at (8 + 32
  // i + 16, 8 + 32 j + 16).
  EXPECT_NEAR(red(56, 24), 40, 2) << "-Y cell";
  EXPECT_EQ(red(56, 88), 255) << "+Y cell";
  EXPECT_LT(red(24, 44), 128) << "+X cell (left of +Z), lower part: the ground";
  EXPECT_EQ(red(24, 68), 255) << "+X cell, upper part: the sky";
}

// Two layers looking straight down through orthographic boxes with near 0 and far 4, from 1 and
// from 3 above the plane: window depth is distance / 4, so 0.25 and 0.75 everywhere.
TEST_F(GlTest, ShadowMapArrayRendersEachLayer) {
  const wb::Scene scene = groundScene();
  const wb::GpuScene gpu(scene);
  const wb::Program depth = depthProgram();
  wb::ShadowMapArray array;
  array.resize(32, 2);
  std::vector<glm::mat4> layers;
  for (float h : {1.0f, 3.0f})
    layers.push_back(glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.0f, 4.0f) *
                     glm::lookAt(glm::vec3(0, h, 0), glm::vec3(0), {0, 0, -1}));
  for (int k = 0; k < 2; ++k) {
    array.begin(k);
    depth.set("u_lightViewProj", layers[size_t(k)]);
    gpu.draw(depth);
  }
  EXPECT_NEAR(texel(array.texture(), 16, 16, 0), 0.25f, 1e-5);
  EXPECT_NEAR(texel(array.texture(), 3, 29, 1), 0.75f, 1e-5);
  const wb::LightView v = array.describe(scene.lights[0], layers);
  EXPECT_EQ(v.shapeName(), "2-layer array");
  EXPECT_FALSE(v.isSingle2D());
}

// The frame target has a stencil buffer: three full-screen draws with GL_INCR leave 3 everywhere,
// and clear() sets it back to 0 (lab 09 counts shadow-volume faces this way).
TEST_F(GlTest, FrameTargetCountsInItsStencil) {
  wb::FrameTarget target;
  target.resize({32, 16});
  target.clear();
  const wb::Program flat({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/flat.frag"}});
  const wb::VertexArray vao = wb::makeEmptyVertexArray();
  glBindVertexArray(vao.id());
  flat.use();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  for (int k = 0; k < 3; ++k) glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  auto stencil = target.readStencil();
  ASSERT_EQ(stencil.size(), 32u * 16u);
  EXPECT_EQ(stencil.front(), 3);
  EXPECT_EQ(stencil.back(), 3);
  target.clear();
  stencil = target.readStencil();
  EXPECT_EQ(stencil[100], 0);
}

// The contact gap and the PCF reference need one orthographic 2D map; for a cube map the
// measurement says so instead of computing them.
TEST_F(GlTest, MeasurementsOfOneShapeAreSkippedForOthers) {
  const wb::Scene scene = groundScene();
  wb::CubeShadowMap cube;
  cube.resize(16);
  wb::FrameTarget target;
  target.resize({16, 16});
  target.clear();
  const wb::LightView light = cube.describe(scene.lights[0], faceMatrices({0, 2, 0}, 0.5f, 10), true);
  wb::Measurement measurement;
  const wb::MeasureResult r = measurement.measure({target, scene, 0.5f, light, scene.lights[0], {}, nullptr, 64});
  EXPECT_EQ(r.gapTexels, -1);
  EXPECT_EQ(r.reference.pixels, 0);
  EXPECT_NE(r.notes.find("cube map"), std::string::npos) << r.notes;
  EXPECT_NE(r.text.find("n/a"), std::string::npos) << r.text;
}
