/// @file light_view.hpp
/// What a lab tells the debug views and the measurements about its shadow-casting light this frame:
/// the light, one matrix per face or cascade, and the map's texture target and size.
#pragma once
#include "common/platform/gl.hpp"
#include "common/scene/scene.hpp"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace wb {

/// The light of the current frame and the shadow map it cast (if any).
struct LightView {
  Light light;                      ///< the light as used this frame (after any lab setting changed it)
  std::vector<glm::mat4> viewProj;  ///< world → light clip space: 1 (2D map), 6 (cube faces +X..−Z) or N (layers)
  GLenum target = 0;                ///< GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP or GL_TEXTURE_2D_ARRAY; 0 = no map
  GLuint texture = 0;               ///< the map's depth texture (0 = none this frame)
  int size = 0;                     ///< width and height of one face or layer, in texels
  bool linearDistance = false;      ///< the map stores |p − light| / far instead of window depth
  int kernel = 1;                   ///< the prefilter's width (filtered maps): the footprint the PCF reference uses
  bool gaussian = false;            ///< the prefilter's weights: Gaussian, or a box
  /// A cube map's lookups, so the measurement can evaluate the same filter with rays: the offsets
  /// (world units) added to the direction p − light, one test each, averaged (empty: one lookup
  /// along p − light), and the depth bias each test subtracts from |p − light|.
  std::vector<glm::vec3> cubeOffsets;
  float cubeBias = 0;  ///< see cubeOffsets
  /// More boxes for debug.frustum, by their eight world-space corners (the near face's (−x, −y),
  /// (+x, −y), (+x, +y), (−x, +y), then the far face's): a cascade's slice of the view, drawn fainter
  /// in the colour of the matrix with the same index.
  std::vector<std::array<glm::vec3, 8>> outlines;

  /// True when a shadow map was rendered this frame.
  bool hasMap() const { return texture != 0 && !viewProj.empty(); }
  /// True for one 2D map seen through one matrix: the shape the contact gap and PCF reference need.
  bool isSingle2D() const { return hasMap() && target == GL_TEXTURE_2D && viewProj.size() == 1; }
  /// "2D map", "cube map" or "N-layer array", for messages.
  std::string shapeName() const {
    if (target == GL_TEXTURE_CUBE_MAP) return "cube map";
    if (target == GL_TEXTURE_2D_ARRAY) return std::to_string(viewProj.size()) + "-layer array";
    return hasMap() ? "2D map" : "no map";
  }
};

}  // namespace wb
