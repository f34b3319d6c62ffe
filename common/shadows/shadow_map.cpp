#include "common/shadows/shadow_map.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace wb {
namespace {

// A depth texture of any shape: nearest filtering (graded paths use explicit taps) and a border of
// depth 1, so a lookup outside the map reads "nothing blocks the light".
Texture makeDepthTexture(GLenum target, int size, int layers) {
  Texture texture = makeTexture(target);
  BoundTexture edit(target, texture.id());
  allocateTexture(target, 1, GL_DEPTH_COMPONENT32F, size, size, layers);
  const GLint wrap = target == GL_TEXTURE_CUBE_MAP ? GL_CLAMP_TO_EDGE : GL_CLAMP_TO_BORDER;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTexParameteri(target, axis, wrap);
  const float outside[4] = {1, 1, 1, 1};
  glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, outside);
  return texture;
}

// Attaches one layer (face) of `texture` as the bound framebuffer's depth. (GL 4.1 attaches a cube
// map's face as a 2D image: glFramebufferTextureLayer takes cube maps from 4.5 on.)
void attachDepthLayer(GLuint texture, int layer) {
  if (textureTarget(texture) == GL_TEXTURE_CUBE_MAP)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(layer), texture,
                           0);
  else
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture, 0, layer);
}

// A depth-only framebuffer on one layer (face) of `texture`, or on all of them when layer < 0.
Framebuffer depthFramebuffer(GLuint texture, int layer) {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  Framebuffer fbo(id);
  BoundFramebuffer edit(id);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (layer < 0)
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture, 0);
  else
    attachDepthLayer(texture, layer);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("shadow map framebuffer incomplete (0x" + std::to_string(status) + ")");
  return fbo;
}

// Every map is drawn with the depth test on, whatever the pass before it left.
void bindAndClear(const Framebuffer& fbo, int size) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace

void ShadowMap::resize(int size) {
  if (size == size_ && texture_.id()) return;
  size_ = size;
  texture_ = makeDepthTexture(GL_TEXTURE_2D, size, 1);
  fbo_ = depthFramebuffer(texture_.id(), -1);
}

void ShadowMap::begin() const { bindAndClear(fbo_, size_); }

LightView ShadowMap::describe(const Light& light, const glm::mat4& viewProj) const {
  LightView v;
  v.light = light, v.viewProj = {viewProj}, v.target = GL_TEXTURE_2D, v.texture = texture(), v.size = size_;
  return v;
}

void CubeShadowMap::resize(int size) {
  if (size == size_ && texture_.id()) return;
  size_ = size;
  texture_ = makeDepthTexture(GL_TEXTURE_CUBE_MAP, size, 6);
  layeredFbo_ = depthFramebuffer(texture_.id(), -1);
  fbo_ = depthFramebuffer(texture_.id(), 0);
}

void CubeShadowMap::begin(int face) const {
  if (face < 0 || face > 5) throw Error("CubeShadowMap::begin: face " + std::to_string(face) + " is not in 0..5");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  attachDepthLayer(texture_.id(), face);
  bindAndClear(fbo_, size_);
}

void CubeShadowMap::beginLayered() const { bindAndClear(layeredFbo_, size_); }

LightView CubeShadowMap::describe(const Light& light, const std::vector<glm::mat4>& faceViewProj,
                                  bool linearDistance) const {
  LightView v;
  v.light = light, v.target = GL_TEXTURE_CUBE_MAP, v.texture = texture(), v.size = size_;
  v.viewProj.assign(faceViewProj.begin(), faceViewProj.begin() + std::min<long>(6, long(faceViewProj.size())));
  v.linearDistance = linearDistance;
  return v;
}

void ShadowMapArray::resize(int size, int layers) {
  if (size == size_ && layers == layers_ && texture_.id()) return;
  size_ = size, layers_ = layers;
  texture_ = makeDepthTexture(GL_TEXTURE_2D_ARRAY, size, layers);
  fbos_.clear();
  for (int k = 0; k < layers; ++k) fbos_.push_back(depthFramebuffer(texture_.id(), k));
  layeredFbo_ = depthFramebuffer(texture_.id(), -1);
}

void ShadowMapArray::begin(int layer) const {
  if (layer < 0 || layer >= layers_)
    throw Error("ShadowMapArray::begin: layer " + std::to_string(layer) + " is not in 0.." +
                std::to_string(layers_ - 1));
  bindAndClear(fbos_[size_t(layer)], size_);
}

void ShadowMapArray::beginLayered() const { bindAndClear(layeredFbo_, size_); }

LightView ShadowMapArray::describe(const Light& light, const std::vector<glm::mat4>& layerViewProj) const {
  LightView v;
  v.light = light, v.target = GL_TEXTURE_2D_ARRAY, v.texture = texture(), v.size = size_;
  v.viewProj.assign(layerViewProj.begin(), layerViewProj.begin() + std::min<long>(layers_, long(layerViewProj.size())));
  return v;
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
