// Instructor-only (tests/reference is not exported): its adjacency and silhouette helpers answer
// exercises 09.1 and 09.2. Welded meshes for lab 09's shadow volumes: every procedural mesh keeps
// welded positions beside its per-face vertices, closed shapes weld to closed, consistently oriented
// manifolds, and a GL_TRIANGLES_ADJACENCY buffer built from the welded data reaches a geometry shader
// through GpuScene, with depth clamp on request.
#include "common/base/error.hpp"
#include "common/base/variant.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/shader.hpp"
#include "common/platform/texture_io.hpp"
#include "common/scene/mesh.hpp"
#include "common/scene/scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Edge = std::pair<uint32_t, uint32_t>;

// Counts of a welded triangle list: edges by number of triangles, and repeated directed edges
// (a consistently oriented manifold has none).
struct Topology {
  size_t positions = 0, triangles = 0, edges = 0;
  size_t open = 0, shared = 0, overShared = 0;  // edges with 1, 2 and more than 2 triangles
  size_t repeatedDirected = 0;
  long euler() const { return long(positions) - long(edges) + long(triangles); }
  bool closed() const { return open == 0 && overShared == 0 && repeatedDirected == 0 && edges == shared; }
};

Topology topology(const wb::MeshData& m) {
  Topology t;
  t.positions = m.weldedPositions.size();
  t.triangles = m.weldedIndices.size() / 3;
  std::map<Edge, int> undirected;
  std::set<Edge> directed;
  const auto& w = m.weldedIndices;
  for (size_t k = 0; k + 2 < w.size(); k += 3)
    for (size_t e = 0; e < 3; ++e) {
      const uint32_t a = w[k + e], b = w[k + (e + 1) % 3];
      ++undirected[{std::min(a, b), std::max(a, b)}];
      if (!directed.insert({a, b}).second) ++t.repeatedDirected;
    }
  t.edges = undirected.size();
  for (const auto& [edge, n] : undirected) (n == 1 ? t.open : n == 2 ? t.shared : t.overShared) += 1;
  return t;
}

// Six indices per triangle, v0 a01 v1 a12 v2 a20: aij is the far corner of the triangle across
// edge ij (the triangle's own third corner on an open edge).
std::vector<uint32_t> adjacency(const wb::MeshData& m) {
  std::map<Edge, uint32_t> farCorner;  // directed edge of a triangle -> its third corner
  const auto& w = m.weldedIndices;
  for (size_t k = 0; k + 2 < w.size(); k += 3)
    for (size_t e = 0; e < 3; ++e) farCorner[{w[k + e], w[k + (e + 1) % 3]}] = w[k + (e + 2) % 3];
  std::vector<uint32_t> out;
  for (size_t k = 0; k + 2 < w.size(); k += 3)
    for (size_t e = 0; e < 3; ++e) {
      const uint32_t a = w[k + e], b = w[k + (e + 1) % 3];
      const auto across = farCorner.find({b, a});
      out.insert(out.end(), {a, across != farCorner.end() ? across->second : w[k + (e + 2) % 3]});
    }
  return out;
}

// Edges between a triangle facing `toLight` and one facing away (counted from the lit side).
int silhouetteEdges(const wb::MeshData& m, glm::vec3 toLight) {
  const std::vector<uint32_t> adj = adjacency(m);
  auto lit = [&](uint32_t a, uint32_t b, uint32_t c) {
    const auto& p = m.weldedPositions;
    return glm::dot(glm::cross(p[b] - p[a], p[c] - p[a]), toLight) > 0;
  };
  int n = 0;
  for (size_t k = 0; k + 5 < adj.size(); k += 6)
    if (lit(adj[k], adj[k + 2], adj[k + 4]))
      for (size_t e = 0; e < 3; ++e) n += !lit(adj[k + 2 * e], adj[k + 2 * e + 1], adj[k + (2 * e + 2) % 6]);
  return n;
}

// The welded triangle k is the triangle k of `indices`, corner by corner.
void expectWeldedMatchesFaces(const wb::MeshData& m, const std::string& name) {
  ASSERT_TRUE(m.isWelded()) << name;
  ASSERT_EQ(m.weldedIndices.size(), m.indices.size()) << name;
  for (size_t k = 0; k < m.indices.size(); ++k) {
    ASSERT_LT(m.weldedIndices[k], m.weldedPositions.size()) << name << ", index " << k;
    const glm::vec3 d = m.weldedPositions[m.weldedIndices[k]] - m.vertices[m.indices[k]].position;
    ASSERT_LE(glm::length(d), 2 * wb::kWeldEpsilon) << name << ", index " << k;
  }
}

}  // namespace

TEST(Geometry, ABoxWeldsToEightCornersEveryEdgeBetweenTwoTriangles) {
  const wb::MeshData box = wb::makeBox(glm::vec3(0.5f, 1.0f, 2.0f));
  EXPECT_EQ(box.vertices.size(), 24u);  // per face: hard edges keep their own normals
  expectWeldedMatchesFaces(box, "box");
  const Topology t = topology(box);
  EXPECT_EQ(t.positions, 8u);
  EXPECT_EQ(t.triangles, 12u);
  EXPECT_EQ(t.edges, 18u);
  EXPECT_EQ(t.shared, 18u) << "every edge of a closed box has exactly two triangles";
  EXPECT_EQ(t.repeatedDirected, 0u) << "neighbours must run a shared edge in opposite directions";
  for (const glm::vec3& p : box.weldedPositions)
    EXPECT_EQ(glm::abs(p), glm::vec3(0.5f, 1.0f, 2.0f)) << "a welded position that is not a corner";
  // Seen from a light towards (1, 2, 3), three faces are lit and the silhouette is a hexagon.
  EXPECT_EQ(silhouetteEdges(box, {1, 2, 3}), 6);
}

TEST(Geometry, ClosedShapesWeldToClosedOrientedManifolds) {
  struct Case {
    std::string name;
    wb::MeshData mesh;
    long euler;  // 2 per closed genus-0 part, 0 for a torus
  } cases[] = {{"sphere", wb::makeSphere(0.7f, 24, 12), 2}, {"cylinder", wb::makeCylinder(0.3f, 1.5f, 20), 2},
               {"torus", wb::makeTorus(0.6f, 0.2f), 0},     {"bench", wb::makeBench(), 12},
               {"tree trunk", wb::makeTreeTrunk(), 2},      {"tree canopy", wb::makeTreeCanopy(), 6}};
  for (const auto& c : cases) {
    expectWeldedMatchesFaces(c.mesh, c.name);
    const Topology t = topology(c.mesh);
    EXPECT_TRUE(t.closed()) << c.name << ": " << t.open << " open, " << t.overShared << " over-shared edges, "
                            << t.repeatedDirected << " repeated directed edges";
    EXPECT_EQ(t.euler(), c.euler) << c.name;
  }
  // The UV sphere's poles are fans: (stacks - 1) rings of `slices` positions and two poles.
  const Topology sphere = topology(cases[0].mesh);
  EXPECT_EQ(sphere.positions, 11u * 24u + 2u);
  EXPECT_EQ(sphere.triangles, 2u * 24u * 11u);
  EXPECT_EQ(cases[0].mesh.indices.size(), 3u * 2u * 24u * 11u) << "no degenerate pole triangles";
  EXPECT_EQ(topology(cases[3].mesh).positions, 6u * 8u) << "the bench's six boxes stay separate parts";
}

TEST(Geometry, APlaneIsOpenWithFourBoundaryEdges) {
  const wb::MeshData plane = wb::makePlane(4, 2);
  expectWeldedMatchesFaces(plane, "plane");
  const Topology t = topology(plane);
  EXPECT_EQ(t.positions, 4u);
  EXPECT_EQ(t.triangles, 2u);
  EXPECT_EQ(t.open, 4u) << "the border: one triangle each";
  EXPECT_EQ(t.shared, 1u) << "the diagonal: two triangles";
  EXPECT_FALSE(t.closed());
}

// Every object of every scene file is closed, except the flat ones (ground planes and walls).
TEST(Geometry, SceneObjectsAreClosedUnlessFlat) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(wb::variant::kSourceDir) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const wb::Scene scene = wb::Scene::load(entry.path());
    for (const auto& o : scene.objects) {
      const std::string name = entry.path().filename().string() + ": " + o.name;
      expectWeldedMatchesFaces(o.mesh, name);
      const bool flat = std::all_of(o.mesh.weldedPositions.begin(), o.mesh.weldedPositions.end(),
                                    [](const glm::vec3& p) { return p.y == 0; });
      const Topology t = topology(o.mesh);
      EXPECT_EQ(t.closed(), !flat) << name << ": " << t.open << " open edges";
      EXPECT_EQ(t.overShared + t.repeatedDirected, 0u) << name;
    }
  }
  EXPECT_GE(files, 3);
}

TEST(Geometry, WeldMergesWithinEpsilonAcrossCellBorders) {
  const float e = wb::kWeldEpsilon;
  wb::MeshData m;
  // Corners 1 and 2 straddle a multiple of epsilon (a hash-grid cell border) and are 0.2 e apart;
  // corner 4 is 0.5 e from corner 0 in every axis; corner 5 is 3 e from corner 3.
  const glm::vec3 p[6] = {{0, 0, 0}, {7 * e - 0.1f * e, 1, 0}, {7 * e + 0.1f * e, 1, 0},
                          {0, 0, 1}, glm::vec3(0.5f * e),      {0, 3 * e, 1}};
  for (const auto& q : p) m.vertices.push_back({q, {0, 0, 1}, {0, 0}});
  m.indices = {0, 1, 3, 4, 2, 5};
  EXPECT_FALSE(m.isWelded());
  m.weld();
  EXPECT_EQ(m.weldedPositions.size(), 4u);
  EXPECT_EQ(m.weldedIndices, (std::vector<uint32_t>{0, 1, 2, 0, 1, 3}));
  EXPECT_THROW(m.weld(0), wb::Error);
  // append() welds a part that was not welded, and keeps the parts apart.
  wb::MeshData raw;
  raw.vertices = {{{0, 0, 0}, {}, {}}, {{1, 0, 0}, {}, {}}, {{0, 1, 0}, {}, {}}, {{1, 0, 0}, {}, {}}};
  raw.indices = {0, 1, 2, 2, 3, 0};
  wb::MeshData sum = wb::makeBox(glm::vec3(1));
  sum.append(raw, glm::translate(glm::mat4(1), {1, 1, 1}));  // raw's (0,0,0) lands on a box corner
  expectWeldedMatchesFaces(sum, "box + raw");
  EXPECT_EQ(sum.weldedPositions.size(), 8u + 3u);
  EXPECT_EQ(sum.weldedIndices.back(), 8u) << "the raw part's first position, after the box's eight";
}

// --- On the GPU ----------------------------------------------------------------------------------

namespace {

fs::path shaderFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "geometry";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

const char* const kVertex = R"(#version 410 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform int u_world;  // 1: hand world space to the geometry shader
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  gl_Position = u_world == 1 ? world : u_viewProj * world;
}
)";

// Draws the triangles of a GL_TRIANGLES_ADJACENCY draw. Built with WB_COUNT_TRIANGLES it emits one
// point per input triangle instead, and with WB_COUNT_SILHOUETTE one per silhouette edge (an edge
// from a lit triangle to an unlit neighbour): a GL_PRIMITIVES_GENERATED query counts them (OpenGL
// 4.1 has no atomic counters in a geometry shader).
const char* const kGeometry = R"(#version 410 core
layout(triangles_adjacency) in;
#if defined(WB_COUNT_TRIANGLES) || defined(WB_COUNT_SILHOUETTE)
layout(points, max_vertices = 3) out;
#else
layout(triangle_strip, max_vertices = 3) out;
#endif
uniform mat4 u_viewProj;
uniform vec3 u_toLight;
bool lit(vec3 a, vec3 b, vec3 c) { return dot(cross(b - a, c - a), u_toLight) > 0.0; }
void count() {
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
  EmitVertex();
  EndPrimitive();
}
void main() {
  vec3 p[6];
  for (int i = 0; i < 6; ++i) p[i] = gl_in[i].gl_Position.xyz;
#if defined(WB_COUNT_TRIANGLES)
  count();
#elif defined(WB_COUNT_SILHOUETTE)
  if (lit(p[0], p[2], p[4]))
    for (int e = 0; e < 3; ++e)
      if (!lit(p[2 * e], p[2 * e + 1], p[(2 * e + 2) % 6])) count();
#else
  for (int i = 0; i < 6; i += 2) {
    gl_Position = u_viewProj * vec4(p[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
#endif
}
)";

const char* const kFragment = R"(#version 410 core
out vec4 o_color;
void main() { o_color = vec4(1.0); }
)";

// A 32² colour target; draw() renders into it and returns the number of covered pixels.
struct Target {
  static constexpr int kSize = 32;
  wb::Texture color = wb::makeTexture2D(GL_RGBA8, kSize, kSize);
  wb::Framebuffer fbo = wb::makeFramebuffer({color.id()}, 0);
  template <class F>
  int draw(F&& f) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, kSize, kSize);
    const float black[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, black);
    f();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<uint8_t> px(kSize * kSize * 4);
    wb::readTexture(color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    int covered = 0;
    for (size_t k = 0; k < px.size(); k += 4) covered += px[k] > 0;
    return covered;
  }
};

}  // namespace

using wb::test::GlTest;

// The box (with adjacency) lies beyond the far plane: with depth clamp it is drawn, without it is
// clipped; the plane (no adjacency) is left out of a GL_TRIANGLES_ADJACENCY draw.
TEST_F(GlTest, AdjacencyDrawThroughGpuSceneReachesTheGeometryShaderWithDepthClamp) {
  wb::Scene scene;
  const glm::mat4 farAway = glm::translate(glm::mat4(1), {0, 0, -5});
  scene.objects.push_back({"box", wb::makeBox(glm::vec3(0.5f)), farAway, {}});
  scene.objects.push_back({"plane", wb::makePlane(1, 1), farAway, {}});
  scene.objects.push_back({"sphere", wb::makeSphere(0.4f, 12, 6), farAway, {}});
  wb::GpuScene gpu(scene);
  ASSERT_EQ(gpu.objectCount(), 3u);
  gpu.setIndices(0, adjacency(scene.objects[0].mesh), GL_TRIANGLES_ADJACENCY);
  EXPECT_THROW(gpu.setIndices(3, {}, GL_TRIANGLES), wb::Error);
  EXPECT_THROW(gpu.setIndices(1, {0, 1, 2, 4, 0, 1}, GL_TRIANGLES_ADJACENCY), wb::Error) << "index 4, four positions";
  EXPECT_THROW(gpu.setIndices(1, {0, 1, 2, 3}, GL_TRIANGLES), wb::Error) << "not whole triangles";
  EXPECT_THROW(gpu.setIndices(1, {0, 1, 2}, GL_TRIANGLE_STRIP), wb::Error) << "not a list";

  // The drawing program, then the two counting ones (the same shaders with a define).
  std::vector<wb::Program> programs;
  for (const char* defines : {"", "#define WB_COUNT_TRIANGLES\n", "#define WB_COUNT_SILHOUETTE\n"})
    programs.emplace_back(
        std::vector<wb::ShaderStage>{{GL_VERTEX_SHADER, shaderFile("adj.vert", kVertex).string()},
                                     {GL_GEOMETRY_SHADER, shaderFile("adj.geom", kGeometry).string()},
                                     {GL_FRAGMENT_SHADER, shaderFile("adj.frag", kFragment).string()}},
        defines);
  auto setAll = [&](const char* name, auto value) {
    for (const wb::Program& p : programs) p.use(), p.set(name, value);
  };
  const wb::Program& program = programs[0];
  setAll("u_world", 1);
  setAll("u_viewProj", glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 1.0f));
  setAll("u_toLight", glm::vec3(1, 2, 3));
  GLuint queryId = 0;
  glGenQueries(1, &queryId);
  const wb::Query query(queryId);
  Target target;
  auto run = [&](bool clamp, size_t& drawn, uint32_t(&got)[2]) {
    const int covered = target.draw([&] { drawn = gpu.drawWelded(program, GL_TRIANGLES_ADJACENCY, clamp); });
    wb::BoundFramebuffer into(target.fbo.id());  // (a headless context has no framebuffer of its own)
    glEnable(GL_RASTERIZER_DISCARD);             // counted, not drawn
    for (int k = 0; k < 2; ++k) {
      glBeginQuery(GL_PRIMITIVES_GENERATED, query.id());
      gpu.drawWelded(programs[size_t(k) + 1], GL_TRIANGLES_ADJACENCY, clamp);
      glEndQuery(GL_PRIMITIVES_GENERATED);
      glGetQueryObjectuiv(query.id(), GL_QUERY_RESULT, &got[k]);
    }
    glDisable(GL_RASTERIZER_DISCARD);
    return covered;
  };
  size_t drawn = 0;
  uint32_t got[2] = {0, 0};
  glDisable(GL_DEPTH_CLAMP);
  EXPECT_GT(run(true, drawn, got), 0) << "depth clamp keeps the box beyond the far plane";
  EXPECT_EQ(drawn, 1u) << "only the box has adjacency";
  EXPECT_EQ(got[0], 12u) << "the box's twelve triangles";
  EXPECT_EQ(got[1], 6u) << "the hexagonal silhouette, as on the CPU";
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_CLAMP)) << "depth clamp must be put back";
  EXPECT_EQ(run(false, drawn, got), 0) << "without depth clamp the box is clipped";
  EXPECT_EQ(got[0], 12u) << "clipping comes after the geometry shader";
  glEnable(GL_DEPTH_CLAMP);
  EXPECT_GT(run(false, drawn, got), 0) << "a depth clamp the caller enabled stays on";
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_CLAMP));
  glDisable(GL_DEPTH_CLAMP);

  // A rounder caster: the GPU's silhouette is the CPU's, edge for edge.
  gpu.setIndices(2, adjacency(scene.objects[2].mesh), GL_TRIANGLES_ADJACENCY);
  gpu.setIndices(0, scene.objects[0].mesh.weldedIndices, GL_TRIANGLES);  // back to plain triangles
  const glm::vec3 toLight(0.3f, 1.0f, -0.45f);
  setAll("u_toLight", toLight);
  run(true, drawn, got);
  EXPECT_EQ(drawn, 1u);
  EXPECT_EQ(got[0], scene.objects[2].mesh.weldedIndices.size() / 3);
  EXPECT_EQ(int(got[1]), silhouetteEdges(scene.objects[2].mesh, toLight));
  EXPECT_GT(got[1], 6u);
}

// The welded triangles cover the same pixels as the per-face ones.
TEST_F(GlTest, WeldedTrianglesDrawLikeTheFaceVertices) {
  const wb::MeshData box = wb::makeBox(glm::vec3(0.6f, 0.4f, 0.5f));
  const wb::Mesh mesh(box);
  EXPECT_EQ(mesh.weldedPositionCount(), 8u);
  EXPECT_EQ(mesh.weldedMode(), GLenum(GL_TRIANGLES));
  wb::Program program({{GL_VERTEX_SHADER, shaderFile("plain.vert", kVertex).string()},
                       {GL_FRAGMENT_SHADER, shaderFile("plain.frag", kFragment).string()}});
  program.use();
  program.set("u_world", 0);
  program.set("u_model", glm::rotate(glm::mat4(1), 0.6f, glm::normalize(glm::vec3(1, 2, 0.5f))));
  program.set("u_viewProj", glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -2.0f, 2.0f));
  Target target;
  const int faces = target.draw([&] { mesh.draw(); });
  const int welded = target.draw([&] { mesh.drawWelded(); });
  EXPECT_GT(faces, 100);
  EXPECT_EQ(welded, faces);
}
