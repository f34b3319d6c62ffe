// Lab 01 C++ exercises: reference solution.
#include "exercise.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lab01 {
namespace {
// Any up vector works except one parallel to the view direction.
glm::vec3 upFor(const glm::vec3& d) { return std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0); }
}  // namespace

// EXERCISE 01.1
glm::mat4 directionalLightViewProj(const glm::vec3& direction, const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 centre = 0.5f * (boundsMin + boundsMax);
  // The light's axes, from a view that looks along d through the centre.
  const glm::mat4 axes = glm::lookAt(glm::vec3(0), d, upFor(d));
  glm::vec3 half(0);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? boundsMax.x : boundsMin.x, (i & 2) ? boundsMax.y : boundsMin.y,
                           (i & 4) ? boundsMax.z : boundsMin.z);
    half = glm::max(half, glm::abs(glm::vec3(axes * glm::vec4(corner - centre, 0))));
  }
  // Step back by the depth half-extent so the nearest corner sits on the near plane (z = 0).
  const glm::mat4 view = glm::lookAt(centre - d * half.z, centre, upFor(d));
  const glm::mat4 ortho = glm::ortho(-half.x, half.x, -half.y, half.y, 0.0f, 2 * half.z);
  return ortho * view;
}

// EXERCISE 01.2
glm::mat4 spotLightViewProj(const glm::vec3& position, const glm::vec3& direction, float halfAngleDeg, float nearPlane,
                            float farPlane) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::mat4 view = glm::lookAt(position, position + d, upFor(d));
  const glm::mat4 projection = glm::perspective(glm::radians(2 * halfAngleDeg), 1.0f, nearPlane, farPlane);
  return projection * view;
}

// EXERCISE 01.H1: bug hunt, "the shadows swim while the sun moves".
PassMatrices updatePassMatrices(const PassMatrices& last, const glm::mat4& lightViewProj) {
  PassMatrices now = last;
  now.shadowPass = lightViewProj;   // this frame's light first...
  now.cameraPass = now.shadowPass;  // ...then the camera pass reads the map through the same matrix
  return now;
}

}  // namespace lab01
