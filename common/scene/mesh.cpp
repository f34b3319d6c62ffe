#include "common/scene/mesh.hpp"

#include "common/base/error.hpp"

#include <glm/ext/vector_int3_sized.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
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
  // A triangle with two corners at one position (a sphere's pole) is left out: it draws nothing,
  // and welded it would give its edges a third triangle.
  auto same = [&m](uint32_t a, uint32_t b) { return m.vertices[a].position == m.vertices[b].position; };
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (!same(a, b) && !same(b, c) && !same(c, a)) m.indices.insert(m.indices.end(), {a, b, c});
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      uint32_t a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
      triangle(a, b, c);
      triangle(b, d, c);
    }
  m.weld();
  return m;
}

// The hash-grid cell of `p` for cells of size `epsilon`.
glm::i64vec3 cellOf(glm::vec3 p, float epsilon) {
  const glm::dvec3 c = glm::floor(glm::dvec3(p) / double(epsilon));
  return glm::i64vec3(c);
}

uint64_t cellKey(glm::i64vec3 c) {
  return uint64_t(c.x) * 73856093u ^ uint64_t(c.y) * 19349663u ^ uint64_t(c.z) * 83492791u;
}
}  // namespace

void MeshData::weld(float epsilon) {
  if (!(epsilon > 0)) throw Error("MeshData::weld: epsilon must be greater than 0, got " + std::to_string(epsilon));
  weldedPositions.clear();
  weldedIndices.clear();
  // Each welded position sits in the bucket of its cell; a position within epsilon of it lies in
  // the same or a neighbouring cell, so 27 buckets are searched (keys may collide: harmless).
  std::unordered_map<uint64_t, std::vector<uint32_t>> buckets;
  std::vector<uint32_t> remap(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) {
    const glm::vec3 p = vertices[v].position;
    const glm::i64vec3 c = cellOf(p, epsilon);
    uint32_t found = UINT32_MAX;
    for (int dz = -1; dz <= 1 && found == UINT32_MAX; ++dz)
      for (int dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
        for (int dx = -1; dx <= 1 && found == UINT32_MAX; ++dx) {
          auto it = buckets.find(cellKey(c + glm::i64vec3(dx, dy, dz)));
          if (it == buckets.end()) continue;
          for (uint32_t w : it->second)
            if (glm::all(glm::lessThanEqual(glm::abs(weldedPositions[w] - p), glm::vec3(epsilon)))) {
              found = w;
              break;
            }
        }
    if (found == UINT32_MAX) {
      found = static_cast<uint32_t>(weldedPositions.size());
      weldedPositions.push_back(p);
      buckets[cellKey(c)].push_back(found);
    }
    remap[v] = found;
  }
  weldedIndices.reserve(indices.size());
  for (uint32_t i : indices) weldedIndices.push_back(remap[i]);
}

bool MeshData::isWelded() const {
  return weldedIndices.size() == indices.size() && (indices.empty() || !weldedPositions.empty());
}

void MeshData::append(const MeshData& other, const glm::mat4& t) {
  if (!isWelded()) weld();
  MeshData weldedOther;
  if (!other.isWelded()) {
    weldedOther = other;
    weldedOther.weld();
  }
  const MeshData& o = other.isWelded() ? other : weldedOther;
  const auto weldedBase = static_cast<uint32_t>(weldedPositions.size());
  for (glm::vec3 p : o.weldedPositions) weldedPositions.emplace_back(t * glm::vec4(p, 1));
  for (uint32_t i : o.weldedIndices) weldedIndices.push_back(weldedBase + i);
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
  m.weld();
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
  m.weld();
  return m;
}

MeshData makeSphere(float r, int slices, int stacks) {
  return grid(slices, stacks, [r](glm::vec2 uv, Vertex& v) {
    float phi = uv.x * 2 * kPi, theta = uv.y * kPi;
    const float s = uv.y == 0 || uv.y == 1 ? 0.0f : std::sin(theta);  // the poles are one point each
    v.normal = {s * std::cos(phi), -std::cos(theta), -s * std::sin(phi)};
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
  m.weld();
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
  m.weld();
  return m;
}

Mesh::Mesh(const MeshData& d) {
  vao_ = makeEmptyVertexArray();
  vbo_ = makeBuffer(d.vertices.size() * sizeof(Vertex), d.vertices.data(), GL_STATIC_DRAW);
  ibo_ = makeBuffer(d.indices.size() * sizeof(uint32_t), d.indices.data(), GL_STATIC_DRAW);
  {
    BoundVertexArray edit(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vbo_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_.id());  // (part of the vertex array's state)
    const size_t offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<const void*>(offsets[a]));
    }
  }
  count_ = static_cast<GLsizei>(d.indices.size());
  if (d.isWelded()) {
    uploadWelded(d);
  } else {
    MeshData welded = d;
    welded.weld();
    uploadWelded(welded);
  }
}

void Mesh::draw(int instances) const {
  glBindVertexArray(vao_.id());
  glDrawElementsInstanced(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr, instances);
}

void Mesh::uploadWelded(const MeshData& d) {
  weldedVao_ = makeEmptyVertexArray();
  weldedPositions_ = static_cast<uint32_t>(d.weldedPositions.size());
  if (weldedPositions_ > 0) {
    weldedVbo_ = makeBuffer(d.weldedPositions.size() * sizeof(glm::vec3), d.weldedPositions.data(), GL_STATIC_DRAW);
    BoundVertexArray edit(weldedVao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, weldedVbo_.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  }
  setWeldedIndices(d.weldedIndices, GL_TRIANGLES);
}

int indicesPerPrimitive(GLenum mode) {
  switch (mode) {
    case GL_POINTS:
      return 1;
    case GL_LINES:
      return 2;
    case GL_TRIANGLES:
      return 3;
    case GL_LINES_ADJACENCY:
      return 4;
    case GL_TRIANGLES_ADJACENCY:
      return 6;
    default:
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", mode);
      throw Error(std::string("primitive mode ") + hex +
                  " is not an indexed list (expected GL_POINTS, GL_LINES, GL_LINES_ADJACENCY, GL_TRIANGLES or "
                  "GL_TRIANGLES_ADJACENCY)");
  }
}

void Mesh::setWeldedIndices(const std::vector<uint32_t>& indices, GLenum mode) {
  const int per = indicesPerPrimitive(mode);
  if (indices.size() % size_t(per) != 0)
    throw Error(std::to_string(indices.size()) + " welded indices are not a whole number of primitives of " +
                std::to_string(per) + " indices");
  for (size_t k = 0; k < indices.size(); ++k)
    if (indices[k] >= weldedPositions_)
      throw Error("welded index " + std::to_string(k) + " is " + std::to_string(indices[k]) + ", but the mesh has " +
                  std::to_string(weldedPositions_) + " welded positions");
  weldedIbo_ =
      indices.empty() ? Buffer() : makeBuffer(indices.size() * sizeof(uint32_t), indices.data(), GL_STATIC_DRAW);
  BoundVertexArray edit(weldedVao_.id());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, weldedIbo_.id());  // (part of the vertex array's state)
  weldedCount_ = static_cast<GLsizei>(indices.size());
  weldedMode_ = mode;
}

void Mesh::drawWelded() const {
  if (weldedCount_ == 0) return;
  glBindVertexArray(weldedVao_.id());
  glDrawElements(weldedMode_, weldedCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace wb
