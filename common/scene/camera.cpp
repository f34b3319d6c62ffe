#include "common/scene/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace wb {

glm::vec3 OrbitCamera::eye() const {
  const float yaw = glm::radians(pose.yaw), pitch = glm::radians(pose.pitch);
  const glm::vec3 back(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  return pose.target + back * pose.distance;
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), pose.target, {0, 1, 0}); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  return glm::perspective(glm::radians(pose.fov), aspect, nearPlane, farPlane);
}

void OrbitCamera::orbit(float dx, float dy) {
  pose.yaw -= dx * 0.3f;
  pose.pitch = std::clamp(pose.pitch + dy * 0.3f, -85.0f, 85.0f);
}

void OrbitCamera::zoom(float steps) { pose.distance = std::clamp(pose.distance * std::pow(0.9f, steps), 0.5f, 150.0f); }

}  // namespace wb
