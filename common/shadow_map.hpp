/// @file shadow_map.hpp
/// The pieces of shadow mapping every lab after the first reuses: a depth-only render target, and
/// the framework's light camera (lab 01 asks students to build a tighter one themselves).
#pragma once
#include "common/gl.hpp"
#include "common/scene.hpp"

#include <glm/glm.hpp>

namespace wb {

/// A square depth-only render target: GL_DEPTH_COMPONENT32F, nearest filtering, and a border of
/// depth 1 so lookups outside the map read "nothing blocks the light".
class ShadowMap {
 public:
  /// (Re)allocates the map when `size` differs from the current size.
  void resize(int size);
  /// Binds the framebuffer, sets the viewport to the whole map and clears depth to 1.
  void begin() const;
  /// The depth texture.
  GLuint texture() const { return texture_.id(); }
  /// Width and height in texels (0 before the first resize).
  int size() const { return size_; }

 private:
  Texture texture_;
  Framebuffer fbo_;
  int size_ = 0;
};

/// The framework's light camera: a directional light gets an orthographic box around the scene's
/// bounding sphere (the same for every light direction, so resolution does not jump as it turns); a
/// spot light gets its cone as a square perspective frustum. Point lights are not supported here.
glm::mat4 lightViewProj(const Light& light, const Scene& scene);

/// The world-space width of one shadow-map texel for an orthographic light matrix.
float texelWorldSize(const glm::mat4& orthoViewProj, int mapSize);

}  // namespace wb
