// Lab 08 C++ exercises: reference solution.
#include "exercise.hpp"

#include <algorithm>

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace lab08 {

// EXERCISE 08.1
glm::mat4 cubeFaceViewProj(int face, const glm::vec3& light, float nearPlane, float farPlane) {
  static const glm::vec3 axis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  if (face < 0 || face > 5) throw wb::Error("cubeFaceViewProj: face " + std::to_string(face) + " is not 0..5");
  return glm::perspective(glm::radians(90.0f), 1.0f, nearPlane, farPlane) *
         glm::lookAt(light, light + axis[face], up[face]);
}

// EXERCISE 08.H1: bug hunt, "the yard is black beyond a ring around the bulb".
// The faces' near and far planes for a light at `light`. Far: the farthest vertex from the light
// that the map must answer for, since a face's depth along its axis is never more than the distance.
// Near is a plane, not a sphere: a point at distance r sits at depth r cos(angle off the axis) in its
// face, as little as r / sqrt(3) in a corner, so a near plane at the nearest vertex's distance would
// clip the near side of casters seen off-axis. The depth written is a linear distance (08.2), so the
// projection's precision never matters and near can be small: 1 cm, which clips only what touches
// the bulb.
glm::vec2 cubeNearFar(const std::vector<wb::SceneObject>& objects, const glm::vec3& light) {
  float farthest = 0;
  for (const auto& o : objects)
    for (const auto& v : o.mesh.vertices)
      farthest = std::max(farthest, glm::length(glm::vec3(o.model * glm::vec4(v.position, 1)) - light));
  return {0.01f, std::max(farthest * 1.01f, 0.1f)};
}

}  // namespace lab08
