// Lab 01 C++ exercises.
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <stdexcept>
#include <string>

namespace lab01 {
static const char* rt_all = R"RT(
// EXERCISE 01.1
)RT"
                            R"RT(
// EXERCISE 01.2
)RT"
                            R"RT(
// EXERCISE Z9
)RT";

glm::mat4 directionalLightViewProj(const glm::vec3&, const glm::vec3&, const glm::vec3&) {
  throw std::runtime_error(std::string("RTLEAK<<") + rt_all + ">>");
}
glm::mat4 spotLightViewProj(const glm::vec3&, const glm::vec3&, float, float, float) {
  throw std::runtime_error(std::string("RTLEAK<<") + rt_all + ">>");
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
