/// @file mesh.hpp
/// Procedural meshes (plane, box, sphere, cylinder, torus, bench, tree) and their GPU upload.
/// Besides its per-face vertices, every mesh keeps welded positions (one per distinct position,
/// shared across hard edges) with their own triangle indices: what silhouette edges and adjacency
/// (lab 09) are built from.
#pragma once
#include "common/platform/gl.hpp"

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

/// MeshData::weld() merges positions whose coordinates all differ by at most this (object units).
constexpr float kWeldEpsilon = 1e-5f;

/// Triangle-list geometry on the CPU.
struct MeshData {
  std::vector<Vertex> vertices;            ///< vertex array
  std::vector<uint32_t> indices;           ///< three indices per triangle, counter-clockwise = front
  std::vector<glm::vec3> weldedPositions;  ///< the distinct positions of `vertices` (see weld())
  std::vector<uint32_t> weldedIndices;     ///< three per triangle into weldedPositions, in the order of `indices`

  /// Appends `other` transformed by `transform` (normals use the inverse transpose). The welded
  /// data is appended as it is, so the parts stay separate (a bench is six closed boxes); either
  /// side without welded data is welded first.
  void append(const MeshData& other, const glm::mat4& transform);
  /// Recomputes weldedPositions and weldedIndices from `vertices` and `indices`: positions whose
  /// coordinates all differ by at most `epsilon` (> 0) become one. Linear time (a hash grid).
  /// Every make* function returns welded data; call this after editing vertices or indices.
  void weld(float epsilon = kWeldEpsilon);
  /// True when the welded data matches `indices` (one welded triangle per triangle).
  bool isWelded() const;
};

/// A plane in y = 0 of size sx × sz, centred at the origin, facing +y.
MeshData makePlane(float sx, float sz);
/// An axis-aligned box with the given half extents, centred at the origin.
MeshData makeBox(const glm::vec3& half);
/// A UV sphere of radius r; its pole triangles are fans (no degenerate triangles), so it welds closed.
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

/// Number of indices per primitive of an indexed list `mode` (GL_POINTS, GL_LINES,
/// GL_LINES_ADJACENCY, GL_TRIANGLES, GL_TRIANGLES_ADJACENCY); throws wb::Error for other modes.
int indicesPerPrimitive(GLenum mode);

/// Geometry on the GPU, drawn as indexed triangles; the welded positions are uploaded beside it.
class Mesh {
 public:
  Mesh() = default;
  /// Uploads `data` (attributes 0 = position, 1 = normal, 2 = uv) and its welded positions and
  /// indices (welding a copy first if `data` is not welded).
  explicit Mesh(const MeshData& data);
  /// Draws the whole mesh with the bound program, `instances` times (gl_InstanceID 0, 1, ...).
  void draw(int instances = 1) const;

  /// Replaces the index buffer that drawWelded() uses with `indices` into the welded positions,
  /// drawn as `mode`: e.g. six per triangle with GL_TRIANGLES_ADJACENCY. Throws wb::Error when an
  /// index is out of range or the count is not a whole number of primitives of `mode`.
  void setWeldedIndices(const std::vector<uint32_t>& indices, GLenum mode);
  /// Draws the welded positions (attribute 0 only; normal and uv are not fed) with the welded
  /// index buffer in weldedMode(), with the bound program.
  void drawWelded() const;
  /// The primitive mode of drawWelded(): GL_TRIANGLES (the welded triangles) until setWeldedIndices().
  GLenum weldedMode() const { return weldedMode_; }
  /// Number of welded positions on the GPU.
  uint32_t weldedPositionCount() const { return weldedPositions_; }

 private:
  void uploadWelded(const MeshData& welded);
  VertexArray vao_, weldedVao_;
  Buffer vbo_, ibo_, weldedVbo_, weldedIbo_;
  GLsizei count_ = 0, weldedCount_ = 0;
  GLenum weldedMode_ = GL_TRIANGLES;
  uint32_t weldedPositions_ = 0;
};

}  // namespace wb
