// Lab 08 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 08
#include "exercise.hpp"

#include <algorithm>

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace lab08 {

// EXERCISE 08.1
glm::mat4 cubeFaceViewProj([[maybe_unused]] int face, [[maybe_unused]] const glm::vec3& light,
                           [[maybe_unused]] float nearPlane, [[maybe_unused]] float farPlane) {
  throw wb::NotImplemented("08.1 cubeFaceViewProj");
  // Hints:
  // - Two small tables indexed by face: the axis to look along and the up vector.
  // - glm::lookAt(light, light + axis, up) is the view; glm::perspective takes the FULL field of
  //   view in radians and the aspect ratio (1: the faces are square).
}

// EXERCISE 08.H1: bug hunt, "the yard is black beyond a ring around the bulb" (README.md, Bug hunt
// 08.H1). Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in
// real engines. Find it from the symptom; the handout says how to see it and how it is measured.
// The faces' near and far planes for a light at `light`. Far: the farthest vertex from the light
// that the map must answer for, since a face's depth along its axis is never more than the distance.
// Near is a plane, not a sphere: a point at distance r sits at depth r cos(angle off the axis) in its
// face, as little as r / sqrt(3) in a corner, so a near plane at the nearest vertex's distance would
// clip the near side of casters seen off-axis. The depth written is a linear distance (08.2), so the
// projection's precision never matters and near can be small: 1 cm, which clips only what touches
// the bulb.
glm::vec2 cubeNearFar(const std::vector<wb::SceneObject>& objects, const glm::vec3& light) {
  float farthest = 0;
  for (const auto& o : objects) {
    if (!o.castsShadow) continue;
    for (const auto& v : o.mesh.vertices)
      farthest = std::max(farthest, glm::length(glm::vec3(o.model * glm::vec4(v.position, 1)) - light));
  }
  return {0.01f, std::max(farthest * 1.01f, 0.1f)};
}

}  // namespace lab08
