/// @file shadow_map.hpp
/// Depth render targets of every shape a shadow map takes: one 2D map, a cube map (point lights)
/// and a 2D array (cascades). Each binds itself for drawing one face or layer and describes itself
/// to the debug views and measurements as a LightView. Also the framework's light camera.
#pragma once
#include "common/platform/gl.hpp"
#include "common/scene/light_view.hpp"
#include "common/scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

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
  /// This map seen through `viewProj`, for the debug views and measurements.
  LightView describe(const Light& light, const glm::mat4& viewProj) const;

 private:
  Texture texture_;
  Framebuffer fbo_;
  int size_ = 0;
};

/// Six square depth faces in one GL_TEXTURE_CUBE_MAP (GL_DEPTH_COMPONENT32F, nearest), in GL's face
/// order +X, −X, +Y, −Y, +Z, −Z. A point light renders one face at a time, or all six in one pass
/// through a layered framebuffer and gl_Layer.
class CubeShadowMap {
 public:
  /// (Re)allocates the six faces when `size` differs from the current size.
  void resize(int size);
  /// Binds face `face` (0..5) alone, sets the viewport and clears its depth to 1.
  void begin(int face) const;
  /// Binds all six faces as layers (gl_Layer picks the face), sets the viewport, clears them to 1.
  void beginLayered() const;
  /// The cube-map depth texture.
  GLuint texture() const { return texture_.id(); }
  /// Width and height of one face in texels.
  int size() const { return size_; }
  /// This map with its face matrices (the first six); `linearDistance` when it stores |p − light| / far.
  LightView describe(const Light& light, const std::vector<glm::mat4>& faceViewProj, bool linearDistance) const;

 private:
  Texture texture_;
  Framebuffer fbo_, layeredFbo_;
  int size_ = 0;
};

/// N square depth layers in one GL_TEXTURE_2D_ARRAY (GL_DEPTH_COMPONENT32F, nearest, border depth
/// 1): one layer per cascade.
class ShadowMapArray {
 public:
  /// (Re)allocates when the size or the number of layers changes.
  void resize(int size, int layers);
  /// Binds layer `layer` alone, sets the viewport and clears its depth to 1.
  void begin(int layer) const;
  /// Binds every layer (gl_Layer picks one), sets the viewport and clears them all to 1.
  void beginLayered() const;
  /// The array depth texture.
  GLuint texture() const { return texture_.id(); }
  /// Width and height of one layer in texels.
  int size() const { return size_; }
  /// The number of layers.
  int layers() const { return layers_; }
  /// This array with one matrix per layer (extra matrices are dropped).
  LightView describe(const Light& light, const std::vector<glm::mat4>& layerViewProj) const;

 private:
  Texture texture_;
  std::vector<Framebuffer> fbos_;
  Framebuffer layeredFbo_;
  int size_ = 0, layers_ = 0;
};

/// The framework's light camera: a directional light gets an orthographic box around the scene's
/// bounding sphere (the same for every light direction, so resolution does not jump as it turns); a
/// spot light gets its cone as a square perspective frustum. Point lights need six (lab 08).
glm::mat4 lightViewProj(const Light& light, const Scene& scene);

/// The world-space width of one shadow-map texel for an orthographic light matrix.
float texelWorldSize(const glm::mat4& orthoViewProj, int mapSize);

}  // namespace wb
