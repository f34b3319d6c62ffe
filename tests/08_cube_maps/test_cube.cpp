// Lab 08 tests. Layer 1: each face matrix against directions worked out by hand (the centre of face
// +X looks along +X, its top is GL's up for that face, its edge is 45 degrees off the axis), the
// distance write against |p - light| / far, and the lookups against a double-precision emulation of
// GL's cube-map face selection on a synthetic 8x8 cube; layer 2: the lantern room against golden
// visibility (./workbook golden 08).
#include "common/base/variant.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/judge/hunt.hpp"
#include "common/judge/tape.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/shader.hpp"
#include "common/platform/texture_io.hpp"
#include "common/scene/scene.hpp"
#include "common/shadows/shadow_map.hpp"
#include "exercise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include <iomanip>
#include <sstream>

using wb::test::GlTest;

namespace {

const char* const kFace[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
const glm::vec3 kAxis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 kUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

glm::vec3 ndc(const glm::mat4& m, const glm::vec3& p) {
  const glm::vec4 c = m * glm::vec4(p, 1);
  return glm::vec3(c) / c.w;
}

}  // namespace

// --- 08.1: the face matrices -------------------------------------------------------------------------
TEST(Lab08, Ex08_1_EachFaceLooksAlongItsAxisWithGlsUp) {
  const glm::vec3 light(0.5f, 1.5f, -2);
  const float n = 0.1f, f = 20;
  for (int k = 0; k < 6; ++k) {
    glm::mat4 m;
    WB_TRY_EXERCISE(m = WB_CALL(lab08::cubeFaceViewProj(k, light, n, f)));
    const std::string face = std::string("face ") + std::to_string(k) + " (" + kFace[k] + ")";
    const glm::vec3 centre = ndc(m, light + 3.0f * kAxis[k]);
    ASSERT_NEAR(glm::length(glm::vec2(centre)), 0, 1e-4)
        << "WRONG: " << face << ": a point straight along " << kFace[k] << " from the light must land in the centre "
        << "of the face, got x " << centre.x << ", y " << centre.y << " (is it looking the wrong way?)";
    ASSERT_GT(centre.z, -1) << "WRONG: " << face << ": a point 3 m along " << kFace[k] << " is behind the near plane";
    const glm::vec3 top = ndc(m, light + 3.0f * kAxis[k] + 1.0f * kUp[k]);
    ASSERT_GT(top.y, 0.2f) << "WRONG: " << face << ": its up vector is not GL's (a point above the centre, along "
                           << "(" << kUp[k].x << ", " << kUp[k].y << ", " << kUp[k].z << "), lands at y " << top.y
                           << ")";
    ASSERT_NEAR(top.x, 0, 1e-4) << "WRONG: " << face << ": its up vector is not GL's (a point above the centre "
                                << "lands beside it, x " << top.x << ")";
    const glm::vec3 edge = ndc(m, light + 3.0f * kAxis[k] + 3.0f * kUp[k]);  // 45 degrees off the axis
    ASSERT_NEAR(edge.y, 1, 1e-3) << "WRONG: " << face << ": 45 degrees off the axis must be the face's edge "
                                 << "(a 90 degree field of view), got y " << edge.y;
    ASSERT_NEAR(ndc(m, light + n * kAxis[k]).z, -1, 1e-3) << "WRONG: " << face << ": the near plane";
    ASSERT_NEAR(ndc(m, light + f * kAxis[k]).z, 1, 1e-3) << "WRONG: " << face << ": the far plane";
  }
}

// --- 08.2: the distance write ---------------------------------------------------------------------------
TEST_F(GlTest, Ex08_2_StoresDistanceOverFar) {
  const std::vector<glm::vec4> in = {
      {1, 0, 0, 10}, {0, 3, 4, 10}, {-2, 2, 1, 6}, {0.1f, -0.2f, 0.2f, 1}, {5, 5, 5, 20}};
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "08.2", "result.x = cubeDepth(IN(0).xyz + vec3(1.0, 2.0, 3.0), vec3(1.0, 2.0, 3.0), IN(0).w);",
              int(in.size()), 1, in);
  for (size_t k = 0; k < in.size(); ++k)
    ASSERT_NEAR(got[k].x, glm::length(glm::vec3(in[k])) / in[k].w, 1e-5)
        << std::setprecision(4) << "WRONG: a point (" << in[k].x << ", " << in[k].y << ", " << in[k].z
        << ") from the light, far " << in[k].w;
}

// --- 08.4 and 08.5: lookups on a synthetic cube -----------------------------------------------------------
namespace {

constexpr int kTexels = 8;

// An 8x8-per-face depth cube: face f, texel (s, t) stores value(f, s, t) (a distance over far).
struct Cube {
  std::array<std::vector<float>, 6> texel;
  wb::Texture texture;
  explicit Cube(float (*value)(int, int, int)) {
    texture = wb::makeTexture(GL_TEXTURE_CUBE_MAP);
    {
      wb::BoundTexture edit(GL_TEXTURE_CUBE_MAP, texture.id());
      wb::allocateTexture(GL_TEXTURE_CUBE_MAP, 1, GL_DEPTH_COMPONENT32F, kTexels, kTexels);
    }
    wb::setTextureParameter(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    wb::setTextureParameter(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    std::vector<float> faces;
    for (int f = 0; f < 6; ++f) {
      for (int t = 0; t < kTexels; ++t)
        for (int s = 0; s < kTexels; ++s) texel[size_t(f)].push_back(value(f, s, t));
      faces.insert(faces.end(), texel[size_t(f)].begin(), texel[size_t(f)].end());
    }
    wb::uploadTextureLayers(texture.id(), kTexels, kTexels, 6, GL_DEPTH_COMPONENT, GL_FLOAT, faces.data());
  }
  // GL's face selection (the major axis) and (s, t) on it, nearest texel.
  double at(glm::dvec3 r) const {
    const glm::dvec3 a = glm::abs(r);
    int f;
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z)
      f = r.x > 0 ? 0 : 1, sc = r.x > 0 ? -r.z : r.z, tc = -r.y, ma = a.x;
    else if (a.y >= a.z)
      f = r.y > 0 ? 2 : 3, sc = r.x, tc = r.y > 0 ? r.z : -r.z, ma = a.y;
    else
      f = r.z > 0 ? 4 : 5, sc = r.z > 0 ? r.x : -r.x, tc = -r.y, ma = a.z;
    const int s = std::clamp(int(std::floor((sc / ma + 1) / 2 * kTexels)), 0, kTexels - 1);
    const int t = std::clamp(int(std::floor((tc / ma + 1) / 2 * kTexels)), 0, kTexels - 1);
    return texel[size_t(f)][size_t(t * kTexels + s)];
  }
};

// Each face stores its own distance, (f + 2) / 10, and the +X face has a nearer blocker (0.1) on its
// upper-left quarter: every face and a blocker to find.
float facesAndBlocker(int f, int s, int t) { return f == 0 && s < 4 && t < 4 ? 0.1f : float(f + 2) / 10; }

// Directions that keep away from texel edges and face seams: a third of a texel off the grid.
std::vector<glm::vec4> directions() {
  std::vector<glm::vec4> in;
  for (int k = 0; k < 30; ++k) {
    const int f = k % 6;
    const float s = (float(1 + (k * 3) % 6) + 0.33f) / kTexels * 2 - 1,
                t = (float(1 + (k * 5) % 6) + 0.33f) / kTexels * 2 - 1;
    glm::vec3 d = kAxis[f];  // then the face's two other axes, scaled by s and t
    const glm::vec3 u = f < 2 ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0),
                    v = f < 4 && f >= 2 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    d += 0.8f * s * u + 0.8f * t * v;
    in.emplace_back(d, 0);
  }
  return in;
}

}  // namespace

TEST_F(GlTest, Ex08_4_LooksUpTheFaceOfTheDirectionAndCompares) {
  const Cube cube(facesAndBlocker);
  const float far = 10, bias = 0.05f;
  std::vector<glm::vec4> in;
  for (const glm::vec4& d : directions())
    for (float dist : {0.5f, 1.5f, 2.5f, 4.5f}) in.emplace_back(glm::vec3(d) / glm::length(glm::vec3(d)) * dist, 0);
  // Then the bias: points just in front of and just behind the surface each direction finds, 0.03 from
  // it (within the bias: lit) and 0.08 beyond it (past the bias: shadowed).
  for (const glm::vec4& d : directions()) {
    const glm::vec3 u = glm::vec3(d) / glm::length(glm::vec3(d));
    const float surface = float(cube.at(glm::dvec3(u)) * far);
    for (float off : {-0.03f, 0.03f, 0.08f}) in.emplace_back(u * (surface + off), 0);
  }
  std::vector<glm::vec4> got;
  WB_RUN_GLSL(got, "08.4", "result.x = cubeShadow(wb_tex0, IN(0).xyz + vec3(1.0, 1.0, 1.0), vec3(1.0), 10.0, 0.05);",
              int(in.size()), 1, in, {cube.texture.id()});
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec3 d(in[k]);
    const double want = glm::length(d) - bias <= cube.at(d) * far ? 1 : 0;
    ASSERT_EQ(got[k].x, want) << std::setprecision(4) << "WRONG: a point (" << d.x << ", " << d.y << ", " << d.z
                              << ") from the light, " << glm::length(d) << " away; the map stores " << cube.at(d) * far
                              << " (far 10, bias 0.05) in that direction, case " << k;
  }
}

TEST_F(GlTest, Ex08_5_AveragesTestsInThreeDimensions) {
  const Cube cube(facesAndBlocker);
  std::vector<glm::vec4> sphere;  // the offsets, from the GPU (cube_common.glsl)
  WB_RUN_GLSL(sphere, "08.5", "result = vec4(cubeOffsetDir(wb_i, 32), 0.0);", 32, 1, {});
  std::vector<glm::vec4> in;
  for (const glm::vec4& d : directions()) in.emplace_back(glm::vec3(d) / glm::length(glm::vec3(d)) * 1.5f, 0);
  for (const float radius : {0.1f, 0.4f}) {
    std::vector<glm::vec4> got;
    const std::string body = "result.x = cubePcf(wb_tex0, IN(0).xyz + vec3(1.0), vec3(1.0), 10.0, 0.05, " +
                             std::to_string(radius) + ", 32);";
    WB_RUN_GLSL(got, "08.5", body, int(in.size()), 1, in, {cube.texture.id()});
    for (size_t k = 0; k < in.size(); ++k) {
      const glm::dvec3 d(in[k]);
      double lit = 0;
      for (int j = 0; j < 32; ++j)
        lit += glm::length(d) - 0.05 <= cube.at(d + glm::dvec3(sphere[size_t(j)]) * double(radius)) * 10;
      // A tap within rounding of a texel edge may fall either way: one tap of slack.
      ASSERT_NEAR(got[k].x, lit / 32, 1.0 / 32 + 1e-5)
          << std::setprecision(4) << "WRONG: radius " << radius << ", a point (" << d.x << ", " << d.y << ", " << d.z
          << ") from the light, case " << k;
    }
  }
}

// --- 08.3: the three ways to fill the cube, texel for texel ----------------------------------------------------
namespace {

constexpr int kCubeSize = 64;

// The direction from the cube's centre through texel (i, j) of face k's centre (GL's cube map
// table: s and t along each face as a lookup reads them).
glm::vec3 texelDirection(int k, int i, int j) {
  const float s = 2 * (float(i) + 0.5f) / kCubeSize - 1, t = 2 * (float(j) + 0.5f) / kCubeSize - 1;
  const glm::vec3 dirs[6] = {{1, -t, -s}, {-1, -t, s}, {s, 1, t}, {s, -1, -t}, {s, -t, 1}, {-s, -t, -1}};
  return dirs[k];
}

// Every state a depth pass reads that the shadow map's begin() does not set: what an earlier test
// (or the driver's defaults) left must not decide the texels.
void depthPassState() {
  for (GLenum off : {GL_CULL_FACE, GL_SCISSOR_TEST, GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_STENCIL_TEST,
                     GL_RASTERIZER_DISCARD, GL_BLEND})
    glDisable(off);
  glDepthFunc(GL_LESS);
  glDepthRange(0, 1);
  glClearDepth(1);
}

// The lantern room's cube (64 texels a face) filled one way; the texels of all six faces, in GL's
// order, read as the lab reads them: sampled at each texel's centre through a samplerCube (a read
// back of a layered attachment's texels is a path the lab never takes).
std::vector<float> fillCube(const wb::GpuScene& scene, const wb::Program& program, int way, const glm::vec3& light) {
  const float n = 0.05f, f = 12;
  wb::CubeShadowMap cube;
  cube.resize(kCubeSize);
  program.set("u_lightPos", light);
  program.set("u_far", f);
  program.set("u_alphaCutoff", 0.5f);
  std::vector<glm::mat4> faces;
  for (int k = 0; k < 6; ++k)  // built here from the hand-derived axes: 08.1 is not what is tested
    faces.push_back(glm::perspective(glm::radians(90.0f), 1.0f, n, f) * glm::lookAt(light, light + kAxis[k], kUp[k]));
  for (int k = 0; k < 6; ++k) program.set(("u_faceViewProj[" + std::to_string(k) + "]").c_str(), faces[size_t(k)]);
  depthPassState();
  if (way == 0) {
    for (int k = 0; k < 6; ++k) {
      cube.begin(k);
      program.set("u_lightViewProj", faces[size_t(k)]);
      scene.draw(program);
    }
  } else {
    cube.beginLayered();
    scene.draw(program, wb::GpuScene::kAlbedoUnit, way == 2 ? 6 : 1);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<glm::vec4> directions;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < kCubeSize; ++j)
      for (int i = 0; i < kCubeSize; ++i) directions.emplace_back(texelDirection(k, i, j), 0);
  const auto read = wb::runGlslKernel("", "cube_read", "result = texture(wb_tex0, IN(0).xyz);", int(directions.size()),
                                      1, directions, {cube.texture()});
  std::vector<float> texels;
  for (const auto& r : read) texels.push_back(r.x);
  return texels;
}

// "" when `got` matches `want` on every face, else which faces differ and on what share of their
// texels. Two programs that draw the same triangles may cover a texel on a silhouette differently
// (GL makes gl_Position invariant between programs only when it is declared so): a texel may differ
// where the reference's depth jumps beside it (by more than 2% of the far plane, 24 cm), nowhere else.
std::string facesThatDiffer(const std::vector<float>& want, const std::vector<float>& got) {
  const int n = kCubeSize, perFace = n * n;
  auto at = [&](int k, int i, int j) {
    return want[size_t(k * perFace + std::clamp(j, 0, n - 1) * n + std::clamp(i, 0, n - 1))];
  };
  std::ostringstream out;
  for (int k = 0; k < 6; ++k) {
    int differ = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float w = at(k, i, j);
        if (std::abs(w - got[size_t(k * perFace + j * n + i)]) <= 1e-5f) continue;
        float jump = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) jump = std::max(jump, std::abs(at(k, i + di, j + dj) - w));
        differ += jump <= 0.02f;
      }
    if (differ)
      out << " face " << k << " (" << kFace[k] << "): " << std::setprecision(3) << differ * 100.0 / perFace << "%;";
  }
  return out.str();
}

}  // namespace

// The same cube, whichever way it is filled: six passes, the geometry shader of 08.3, and (where the
// driver has GL_ARB_shader_viewport_layer_array) six instances; texel for texel but on a silhouette. A scene test (its
// name says so): it draws the room with 08.2's distance write, which the student edition has only as the student wrote
// it, so there a wrong 08.2 makes 08.3 wait on it instead of failing it.
TEST_F(GlTest, Ex08_3_SceneFilledThreeWaysIsOneCube) {
  if (wb::test::tapeMode() == wb::test::TapeMode::Record) return;  // GLSL is the judge's to run
  const wb::test::IsolatedShaders shaders("08.3");
  if (shaders.text("exercise_layered.geom").find("WB_TODO") != std::string::npos)
    FAIL() << "NOT IMPLEMENTED: shaders/exercise_layered.geom still holds WB_TODO";
  const wb::Scene room = wb::Scene::load(std::string(wb::variant::kSourceDir) + "/scenes/cube_lantern.json");
  const wb::GpuScene scene(room);
  const glm::vec3 light = room.lights.at(0).position;
  std::vector<std::vector<float>> cubes;
  try {
    const wb::Program six({{GL_VERTEX_SHADER, "depth_cube.vert"}, {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
    const wb::Program geometry({{GL_VERTEX_SHADER, "depth_layered.vert"},
                                {GL_GEOMETRY_SHADER, "exercise_layered.geom"},
                                {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
    cubes.push_back(fillCube(scene, six, 0, light));
    cubes.push_back(fillCube(scene, geometry, 1, light));
    if (wb::hasGlExtension("GL_ARB_shader_viewport_layer_array")) {
      const wb::Program instanced(
          {{GL_VERTEX_SHADER, "depth_instanced.vert"}, {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
      cubes.push_back(fillCube(scene, instanced, 2, light));
    }
  } catch (const std::exception& e) {
    FAIL() << "ERROR: " << e.what();
  }
  size_t written = 0;
  for (float t : cubes[0]) written += t < 1;
  ASSERT_GT(written, cubes[0].size() / 2) << "ERROR: six passes left most of the cube empty (the test's own setup)";
  const std::string geometry = facesThatDiffer(cubes[0], cubes[1]);
  EXPECT_TRUE(geometry.empty()) << "WRONG: the geometry shader's cube differs from six passes' on" << geometry
                                << " (is gl_Layer set to the face, and gl_Position through that face's matrix?)";
  const std::string instanced = cubes.size() > 2 ? facesThatDiffer(cubes[0], cubes[2]) : "";
  EXPECT_TRUE(instanced.empty()) << "ERROR: the instanced fill (the lab's own shader) differs on" << instanced;
}

// --- Layer 2 ------------------------------------------------------------------------------------------------
namespace {
const float kTol = 0.1f;
const double kMaxFraction = 0.01;
}  // namespace

TEST(Lab08, Ex08_1_SceneRoom) {
  wb::test::expectSceneMatchesGolden("08.1", "room_hard", wb::test::labArgs({"cube.filter=hard"}), kTol, kMaxFraction);
}
TEST(Lab08, Ex08_2_SceneRoom) {
  wb::test::expectSceneMatchesGolden("08.2", "room_hard", wb::test::labArgs({"cube.filter=hard"}), kTol, kMaxFraction);
}
// The geometry shader fills the same cube as six passes: held to the same golden data.
TEST(Lab08, Ex08_3_SceneGeometryShaderFillsTheSameCube) {
  wb::test::expectSceneMatchesGolden(
      "08.3", "room_hard", wb::test::labArgs({"cube.filter=hard", "cube.method=geometry"}), kTol, kMaxFraction);
}
TEST(Lab08, Ex08_4_SceneRoom) {
  wb::test::expectSceneMatchesGolden("08.4", "room_hard", wb::test::labArgs({"cube.filter=hard"}), kTol, kMaxFraction);
}
TEST(Lab08, Ex08_5_SceneRoom) {
  wb::test::expectSceneMatchesGolden("08.5", "room_pcf", wb::test::labArgs({"cube.filter=pcf"}), kTol, kMaxFraction);
}

// Measured: the 3D offsets cross a face's edge into the next face, so the seams are no worse than
// the rest. Both are the frame against the same lookups made with rays instead of the map.
TEST(Lab08, Ex08_5_MeasuredSeamsNoWorseThanTheRest) {
  const auto m = wb::test::measureScene("08.5", "measure_seams", wb::test::labArgs({"cube.filter=pcf"}));
  if (!m.failure.empty()) FAIL() << m.failure;
  ASSERT_GE(m.seamErrorPercent, 0) << "ERROR: the run measured no seams (is the light's map a cube?)";
  EXPECT_LE(m.seamErrorPercent, 1.25 * m.restErrorPercent + 0.25)
      << std::setprecision(3)
      << "WRONG: within 2 degrees of a cube face's edge the shadow differs from the same lookups made with rays by "
      << m.seamErrorPercent << "% on average, against " << m.restErrorPercent << "% elsewhere: do the offsets "
      << "stay on one face (clamped at its edge) instead of crossing into the next?";
  EXPECT_LT(m.restErrorPercent, 3) << std::setprecision(3)
                                   << "WRONG: away from the seams the shadow differs from the same lookups made "
                                   << "with rays by " << m.restErrorPercent << "% on average";
}

// --- Bug hunt 08.H1: "the yard is black beyond a ring around the bulb" --------------------------------
// scenes/cube_yard.json: cube_floor's clutter on a 30 m yard that receives but casts nothing. The
// reference (./workbook run 08 --headless --size 480x270 --scene scenes/cube_yard.json --metrics):
// acne 0.39%, leak 0.21%.
TEST(Lab08, Ex08_H1_MeasuredTheWholeYardIsLit) {
  wb::test::expectSymptomGone("08.H1", "hunt_yard", wb::test::labArgs({}, "cube_yard.json"), {1.0, 1.0});
}
// The hunt's function alone, on a yard four times as wide as the scene's: a bulb 1 m above a 120 m
// yard that casts nothing, a crate beside the bulb that does. The far plane must reach the yard's
// farthest corner (worked out here from the corners), and not be more than twice that: beyond, the
// stored distances lose precision for nothing. A far plane that only has a floor (of 10 or 20 m,
// which holds the 30 m scene) fails here.
TEST(Lab08, Ex08_H1_TheFarPlaneReachesTheFarthestReceiver) {
  std::vector<wb::SceneObject> objects(2);
  objects[0].name = "yard", objects[0].mesh = wb::makePlane(120, 120), objects[0].castsShadow = false;
  objects[1].name = "crate", objects[1].mesh = wb::makeBox(glm::vec3(0.3f));
  objects[1].model = glm::translate(glm::mat4(1), glm::vec3(1.5f, 0.3f, 0));
  const glm::vec3 bulb(0, 1, 0);
  const float farthest = glm::length(glm::vec3(60, 0, 60) - bulb);  // every corner is as far
  glm::vec2 nearFar(0);
  WB_TRY_EXERCISE(nearFar = WB_CALL(lab08::cubeNearFar(objects, bulb)));
  ASSERT_GE(nearFar.y, farthest) << std::setprecision(4)
                                 << "WRONG: a bulb 1 m above the middle of a 120 m yard that casts nothing, a crate "
                                 << "beside it: far is " << nearFar.y << " m, but the yard's corners are " << farthest
                                 << " m away, and the lookup is asked about them";
  EXPECT_LE(nearFar.y, 2 * farthest) << std::setprecision(4) << "WRONG: far is " << nearFar.y
                                     << " m, more than twice the farthest point (" << farthest
                                     << " m): the stored distances lose precision for nothing";
  EXPECT_GT(nearFar.x, 0) << "WRONG: near must be above 0, got " << nearFar.x;
  EXPECT_LT(nearFar.x, 0.5f) << "WRONG: near is " << nearFar.x << " m, but the crate is 1.2 m from the bulb";
}
TEST(Lab08, Ex08_H1_SceneYardLowAndLong) {
  wb::test::expectSceneMatchesGolden("08.H1", "hunt_yard_low",
                                     wb::test::labArgs({"camera.bookmark=3"}, "cube_yard.json"), kTol, kMaxFraction);
}
