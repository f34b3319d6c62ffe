#include "common/mesh.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

namespace wb {
namespace {
constexpr float kPi = glm::pi<float>();

// Adds a quad with corners a, b, c, d (counter-clockwise seen from the front) and normal n.
void quad(MeshData& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
  const auto base = static_cast<uint32_t>(m.vertices.size());
  m.vertices.push_back({a, n, {0, 0}});
  m.vertices.push_back({b, n, {1, 0}});
  m.vertices.push_back({c, n, {1, 1}});
  m.vertices.push_back({d, n, {0, 1}});
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

// A grid of (u, v) in [0,1]² mapped through `f`, which fills position and normal.
template <class F>
MeshData grid(int nu, int nv, F f) {
  MeshData m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      glm::vec2 uv(float(i) / nu, float(j) / nv);
      Vertex v{};
      v.uv = uv;
      f(uv, v);
      m.vertices.push_back(v);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      uint32_t a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
      for (uint32_t k : {a, b, c, b, d, c}) m.indices.push_back(k);
    }
  return m;
}
}  // namespace

void MeshData::append(const MeshData& other, const glm::mat4& t) {
  const auto base = static_cast<uint32_t>(vertices.size());
  const glm::mat3 nt = glm::transpose(glm::inverse(glm::mat3(t)));
  for (Vertex v : other.vertices) {
    v.position = glm::vec3(t * glm::vec4(v.position, 1));
    v.normal = glm::normalize(nt * v.normal);
    vertices.push_back(v);
  }
  for (uint32_t i : other.indices) indices.push_back(base + i);
}

MeshData makePlane(float sx, float sz) {
  MeshData m;
  const float x = sx / 2, z = sz / 2;
  quad(m, {-x, 0, z}, {x, 0, z}, {x, 0, -z}, {-x, 0, -z}, {0, 1, 0});
  for (auto& v : m.vertices) v.uv *= glm::vec2(sx, sz);  // one texture repeat per unit
  return m;
}

MeshData makeBox(const glm::vec3& h) {
  MeshData m;
  // Each face: centre axis n, and two tangent axes u, v with u × v = n.
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a)
    for (float s : {1.0f, -1.0f}) {
      glm::vec3 n = axes[a] * s, u = axes[(a + 1) % 3] * s, v = axes[(a + 2) % 3];
      glm::vec3 c = n * h, du = u * h, dv = v * h;
      quad(m, c - du - dv, c + du - dv, c + du + dv, c - du + dv, n);
    }
  return m;
}

MeshData makeSphere(float r, int slices, int stacks) {
  return grid(slices, stacks, [r](glm::vec2 uv, Vertex& v) {
    float phi = uv.x * 2 * kPi, theta = uv.y * kPi;
    v.normal = {std::sin(theta) * std::cos(phi), -std::cos(theta), -std::sin(theta) * std::sin(phi)};
    v.position = v.normal * r;
  });
}

MeshData makeCylinder(float r, float h, int slices) {
  MeshData m = grid(slices, 1, [r, h](glm::vec2 uv, Vertex& v) {
    float phi = uv.x * 2 * kPi;
    v.normal = {std::cos(phi), 0, -std::sin(phi)};
    v.position = v.normal * r + glm::vec3(0, uv.y * h, 0);
  });
  for (float y : {0.0f, h}) {  // caps as triangle fans
    const auto centre = static_cast<uint32_t>(m.vertices.size());
    glm::vec3 n(0, y > 0 ? 1 : -1, 0);
    m.vertices.push_back({{0, y, 0}, n, {0.5f, 0.5f}});
    for (int i = 0; i <= slices; ++i) {
      float phi = float(i) / slices * 2 * kPi;
      m.vertices.push_back({{r * std::cos(phi), y, -r * std::sin(phi)}, n, {0, 0}});
    }
    for (int i = 0; i < slices; ++i) {
      uint32_t a = centre + 1 + i, b = a + 1;
      if (y < h) std::swap(a, b);  // the bottom cap faces down
      m.indices.insert(m.indices.end(), {centre, a, b});
    }
  }
  return m;
}

MeshData makeTorus(float R, float r, int major, int minor) {
  return grid(major, minor, [R, r](glm::vec2 uv, Vertex& v) {
    float phi = uv.x * 2 * kPi, theta = uv.y * 2 * kPi;
    glm::vec3 ring(std::cos(phi), 0, -std::sin(phi));
    v.normal = ring * std::cos(theta) + glm::vec3(0, std::sin(theta), 0);
    v.position = ring * R + v.normal * r;
  });
}

MeshData makeBench() {
  MeshData m;
  auto add = [&m](glm::vec3 centre, glm::vec3 half) { m.append(makeBox(half), glm::translate(glm::mat4(1), centre)); };
  add({0, 0.45f, 0}, {1.0f, 0.04f, 0.3f});       // seat: light leaks under it in the filter labs
  add({0, 0.85f, -0.28f}, {1.0f, 0.2f, 0.03f});  // back rest
  for (float x : {-0.9f, 0.9f})
    for (float z : {-0.25f, 0.25f}) add({x, 0.2f, z}, {0.05f, 0.2f, 0.05f});  // legs
  return m;
}

MeshData makeTreeTrunk() { return makeCylinder(0.075f, 1.6f, 16); }

MeshData makeTreeCanopy() {
  MeshData m;
  // Three vertical quads at 60° steps, each with both faces so culling never hides a side.
  for (int i = 0; i < 3; ++i) {
    float a = i * kPi / 3;
    glm::vec3 u(std::cos(a), 0, -std::sin(a)), n(std::sin(a), 0, std::cos(a));
    glm::vec3 lo(0, 1.0f, 0), hi(0, 2.6f, 0);
    quad(m, lo - u * 0.8f, lo + u * 0.8f, hi + u * 0.8f, hi - u * 0.8f, n);
    quad(m, lo + u * 0.8f, lo - u * 0.8f, hi - u * 0.8f, hi + u * 0.8f, -n);
  }
  return m;
}

Mesh::Mesh(const MeshData& d) {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  vao_ = VertexArray(vao);
  vbo_ = makeBuffer(d.vertices.size() * sizeof(Vertex), d.vertices.data(), 0);
  ibo_ = makeBuffer(d.indices.size() * sizeof(uint32_t), d.indices.data(), 0);
  glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, ibo_.id());
  const GLuint offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
  const GLint sizes[3] = {3, 3, 2};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  count_ = static_cast<GLsizei>(d.indices.size());
}

void Mesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace wb
