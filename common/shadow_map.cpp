#include "common/shadow_map.hpp"

#include "common/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace wb {

void ShadowMap::resize(int size) {
  if (size == size_ && texture_.id()) return;
  size_ = size;
  texture_ = makeTexture2D(GL_DEPTH_COMPONENT32F, size, size, GL_NEAREST, GL_CLAMP_TO_BORDER);
  const float outside[4] = {1, 1, 1, 1};
  glTextureParameterfv(texture_.id(), GL_TEXTURE_BORDER_COLOR, outside);
  fbo_ = makeFramebuffer({}, texture_.id());
}

void ShadowMap::begin() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_, size_);
  glClear(GL_DEPTH_BUFFER_BIT);
}

glm::mat4 lightViewProj(const Light& light, const Scene& scene) {
  const glm::vec3 d = glm::normalize(light.direction);
  const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  if (light.type == LightType::Spot)
    return glm::perspective(glm::radians(2 * light.angle), 1.0f, light.nearPlane, light.farPlane) *
           glm::lookAt(light.position, light.position + d, up);
  if (light.type != LightType::Directional) throw Error("lightViewProj: point lights need a cube map (lab 08)");
  const glm::vec3 centre = 0.5f * (scene.boundsMin + scene.boundsMax);
  const float r = 0.5f * glm::length(scene.boundsMax - scene.boundsMin);
  return glm::ortho(-r, r, -r, r, 0.0f, 2 * r) * glm::lookAt(centre - d * r, centre, up);
}

float texelWorldSize(const glm::mat4& m, int mapSize) {
  // Clip x changes by |row 0| per world unit, and the map spans 2 clip units.
  const glm::vec3 row0(m[0][0], m[1][0], m[2][0]);
  return 2.0f / (glm::length(row0) * float(mapSize));
}

}  // namespace wb
