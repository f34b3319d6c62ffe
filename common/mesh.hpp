/// @file mesh.hpp
/// Procedural meshes (plane, box, sphere, cylinder, torus, bench, tree) and their GPU upload.
#pragma once
#include "common/gl.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace wb {

/// One vertex: position, normal and texture coordinate.
struct Vertex {
  glm::vec3 position;  ///< object-space position
  glm::vec3 normal;    ///< object-space unit normal
  glm::vec2 uv;        ///< texture coordinate
};

/// Triangle-list geometry on the CPU.
struct MeshData {
  std::vector<Vertex> vertices;   ///< vertex array
  std::vector<uint32_t> indices;  ///< three indices per triangle, counter-clockwise = front
  /// Appends `other` transformed by `transform` (normals use the inverse transpose).
  void append(const MeshData& other, const glm::mat4& transform);
};

/// A plane in y = 0 of size sx × sz, centred at the origin, facing +y.
MeshData makePlane(float sx, float sz);
/// An axis-aligned box with the given half extents, centred at the origin.
MeshData makeBox(const glm::vec3& half);
/// A UV sphere of radius r.
MeshData makeSphere(float r, int slices = 32, int stacks = 16);
/// A closed cylinder of radius r from y = 0 to y = h.
MeshData makeCylinder(float r, float h, int slices = 32);
/// A torus around the y axis with major radius R and minor radius r.
MeshData makeTorus(float R, float r, int major = 48, int minor = 16);
/// A park bench (seat, back and four legs) about 2 × 1 × 0.6, standing on y = 0.
MeshData makeBench();
/// A tree trunk: a cylinder 0.15 wide and 1.6 tall, standing on y = 0.
MeshData makeTreeTrunk();
/// A tree canopy: three crossed, double-sided quads to be alpha-tested with a leaf texture.
MeshData makeTreeCanopy();

/// Geometry on the GPU, drawn as indexed triangles.
class Mesh {
 public:
  Mesh() = default;
  /// Uploads `data` (attributes 0 = position, 1 = normal, 2 = uv).
  explicit Mesh(const MeshData& data);
  /// Draws the whole mesh with the bound program.
  void draw() const;

 private:
  VertexArray vao_;
  Buffer vbo_, ibo_;
  GLsizei count_ = 0;
};

}  // namespace wb
