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
}  // namespace lab01
