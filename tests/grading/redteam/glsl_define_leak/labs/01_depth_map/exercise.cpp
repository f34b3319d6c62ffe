// Lab 01 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 01
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace lab01 {

// EXERCISE 01.1
glm::mat4 directionalLightViewProj([[maybe_unused]] const glm::vec3& direction,
                                   [[maybe_unused]] const glm::vec3& boundsMin,
                                   [[maybe_unused]] const glm::vec3& boundsMax) {
  throw wb::NotImplemented("01.1 directionalLightViewProj");
  // Hints:
  // - glm::lookAt(eye, target, up) builds the light's view; pick an `up` that is not parallel to
  //   `direction`.
  // - Put the eye far enough back along -direction from the box centre to see every corner.
  // - The half-extent along each light axis is the largest |(corner - centre) · axis| over the
  //   8 corners; glm::ortho(left, right, bottom, top, near, far) takes them.
  // - The product order matters: clip = projection * view * world.
}

// EXERCISE 01.2
glm::mat4 spotLightViewProj([[maybe_unused]] const glm::vec3& position, [[maybe_unused]] const glm::vec3& direction,
                            [[maybe_unused]] float halfAngleDeg, [[maybe_unused]] float nearPlane,
                            [[maybe_unused]] float farPlane) {
  throw wb::NotImplemented("01.2 spotLightViewProj");
  // Hints:
  // - glm::perspective takes the FULL vertical field of view, in radians.
  // - The shadow map is square, so the aspect ratio is 1.
}

// EXERCISE 01.H1: bug hunt, "the shadows swim while the sun moves" (README.md, Bug hunt 01.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in a real sample. Find it
// from the symptom; the handout says how to see it and how it is measured.
PassMatrices updatePassMatrices(const PassMatrices& last, const glm::mat4& lightViewProj) {
  PassMatrices now = last;
  now.cameraPass = now.shadowPass;  // the camera pass reads the map that the shadow pass renders
  now.shadowPass = lightViewProj;
  return now;
}

}  // namespace lab01
