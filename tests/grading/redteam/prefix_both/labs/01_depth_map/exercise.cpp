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
