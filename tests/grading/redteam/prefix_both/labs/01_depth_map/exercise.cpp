// Lab 01 C++ exercises.
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lab01 {
namespace {
glm::vec3 upFor(const glm::vec3& d) { return std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0); }
}  // namespace

// EXERCISE 01.1
#define RT_STUDENT_01_1
// EXERCISE Z1
#ifdef RT_STUDENT_01_1
// EXERCISE 01
this is not C++ : the build fails and the grader splices chunks
// EXERCISE Z2
#endif

                                          // EXERCISE 01.2
                                          glm::mat4
                                          spotLightViewProj(const glm::vec3&, const glm::vec3&, float, float, float) {
  throw wb::NotImplemented("01.2 spotLightViewProj");
}

}  // namespace lab01
