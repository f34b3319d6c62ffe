/// @file exercise.hpp
/// Lab 09 C++ exercises. The signatures are fixed: the app, the tests and the grader call them.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace lab09 {

/// EXERCISE 09.1: adjacency for GL_TRIANGLES_ADJACENCY. `triangles` holds three indices per
/// triangle, counter-clockwise seen from outside. The result holds six per triangle, in the same
/// order: v0, a01, v1, a12, v2, a20, where aij is the third corner of the triangle across edge
/// (vi, vj), the one that has that edge the other way round, (vj, vi). An open edge (no triangle
/// across it) gets the triangle's own third corner, so that it always counts as a silhouette.
std::vector<uint32_t> buildAdjacency(const std::vector<uint32_t>& triangles);

/// The stencil operations of one side of a volume, as glStencilOpSeparate takes them: when the
/// stencil test fails (`stencilFail`), when it passes and the depth test fails (`depthFail`), and
/// when both pass (`depthPass`). GL enums: GL_KEEP, GL_INCR_WRAP, GL_DECR_WRAP, ...
struct StencilOps {
  uint32_t stencilFail = 0;  ///< the stencil test fails
  uint32_t depthFail = 0;    ///< the stencil test passes and the depth test fails
  uint32_t depthPass = 0;    ///< both pass
};
/// How the volumes are counted: the operations for front and back faces, and whether the volumes
/// need their caps (the light-facing triangles, and the same pushed to infinity).
struct StencilSetup {
  StencilOps front;   ///< for the volume's faces that face the camera
  StencilOps back;    ///< for those that face away from it
  bool caps = false;  ///< close the volumes at both ends (the light-facing triangles, and at infinity)
};

/// EXERCISE 09.4: depth-pass (z-pass) counting: +1 where a front face of a volume is in front of the
/// scene, -1 where a back face is; wrapping, so the order of the faces does not matter.
StencilSetup zPassSetup();
/// EXERCISE 09.5: depth-fail (z-fail, "Carmack's reverse") counting: +1 where a back face of a
/// volume is behind the scene, -1 where a front face is; wrapping; and the caps it needs.
StencilSetup zFailSetup();

/// EXERCISE 09.6: may the camera's near plane be inside the shadow volume of a caster whose
/// bounding box is [boxMin, boxMax]? `nearQuad` is the near plane's rectangle in world space (four
/// corners, in order around it); `light` is a point light (w = 1, xyz its position) or a
/// directional light (w = 0, xyz the direction *towards* the light). Answer true whenever the box
/// reaches into the region between the light and the near quad (for a directional light, the quad
/// swept towards the light): z-pass is then unsafe. A true for a box that misses the region only
/// costs z-fail's caps; a false for a box in it inverts the shadows.
bool nearPlaneMayBeShadowed(const std::array<glm::vec3, 4>& nearQuad, const glm::vec4& light, const glm::vec3& boxMin,
                            const glm::vec3& boxMax);

}  // namespace lab09
