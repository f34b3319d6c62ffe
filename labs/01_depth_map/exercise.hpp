/// @file exercise.hpp
/// Lab 01 C++ exercises. The signatures are fixed: the app, the tests and the grader call them.
#pragma once
#include <glm/glm.hpp>

namespace lab01 {

/// EXERCISE 01.1: the view-projection of a directional light travelling along `direction`,
/// an orthographic box fitted around the axis-aligned scene bounds [boundsMin, boundsMax].
/// Every point of the bounds must land inside clip space [-1, 1]³, and depth must grow along
/// `direction` (the light looks the way it travels).
glm::mat4 directionalLightViewProj(const glm::vec3& direction, const glm::vec3& boundsMin, const glm::vec3& boundsMax);

/// EXERCISE 01.2: the view-projection of a spot light at `position` pointing along `direction`,
/// with a square perspective frustum whose half-angle is `halfAngleDeg` degrees, and the given
/// near and far planes.
glm::mat4 spotLightViewProj(const glm::vec3& position, const glm::vec3& direction, float halfAngleDeg, float nearPlane,
                            float farPlane);

/// The light's matrix as each pass of a frame uses it: the shadow pass renders the map through
/// `shadowPass`, and the camera pass reads the map through `cameraPass`.
struct PassMatrices {
  glm::mat4 shadowPass{1};  ///< the light's matrix the shadow pass renders the map with
  glm::mat4 cameraPass{1};  ///< the light's matrix the camera pass reads the map with
};

/// EXERCISE 01.H1 (a bug hunt: working code with a real bug in it; README.md): the passes' matrices
/// for this frame, from last frame's `last` and this frame's light matrix `lightViewProj`.
PassMatrices updatePassMatrices(const PassMatrices& last, const glm::mat4& lightViewProj);

}  // namespace lab01
