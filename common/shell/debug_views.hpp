/// @file debug_views.hpp
/// The shared debug views, drawn into the frame target so screenshots and headless runs show them:
/// the light's frustum (one per face or cascade), the shadow-map inset (one per layer of an array,
/// an unfolded cross for a cube map), the view from the light, and the measurement heatmap.
#pragma once
#include "common/platform/frame_target.hpp"
#include "common/platform/shader.hpp"
#include "common/scene/light_view.hpp"

#include <glm/glm.hpp>

namespace wb {

class Settings;

/// The debug settings every lab shares (debug.*).
struct DebugOptions {
  int view = 0;              ///< debug.view: 0 camera, 1 light
  int lightFace = 0;         ///< debug.light_face: the face or cascade the view from the light uses
  bool showMap = false;      ///< debug.shadow_map: the inset
  bool showFrustum = false;  ///< debug.frustum: the light's frustum lines
  /// Registers the debug.* settings every lab with a shadow map has.
  void addTo(Settings& settings);
  /// Registers debug.light_face, for labs whose light has several matrices (cube faces, cascades).
  void addLightFace(Settings& settings);
};

/// Draws the debug views; needs a GL context.
class DebugViews {
 public:
  /// Loads the debug programs from shaders/wb.
  DebugViews();
  /// The matrix the viewer sees through in "view from light": face or cascade `face` (wrapped to
  /// the ones there are) of `light`, letterboxed into `frame` instead of stretched.
  static glm::mat4 fromLight(const LightView& light, int face, glm::ivec2 frame);
  /// Draws what `options` asks for over the frame in `target` (colour only); `heatmap` (0 for
  /// none) is laid over everything.
  void draw(const DebugOptions& options, const LightView& light, const glm::mat4& viewer, const FrameTarget& target,
            GLuint heatmap) const;

 private:
  void drawFrusta(const LightView& light, const glm::mat4& viewer) const;
  void drawInset(const LightView& light, glm::ivec2 frame) const;
  void drawHeatmap(GLuint heatmap, glm::ivec2 frame) const;
  Program lines_, inset_, insetArray_, cube_, overlay_;
  VertexArray vao_;
  Sampler plain_;  // nearest, no comparison: a map may be set up for a shadow sampler
};

}  // namespace wb
