// Lab 08 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 08
#include "exercise.hpp"

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

}  // namespace lab08
