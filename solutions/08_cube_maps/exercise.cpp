// Lab 08 C++ exercises: reference solution.
#include "exercise.hpp"

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

}  // namespace lab08
