/// @file host_settings.hpp
/// The host's settings: the camera bookmark, the motions of a clip (light.orbit, camera.dolly),
/// render.scale, ui.* and present.*. They belong to the app that hosts a lab, not to the lab: LabHost
/// owns them and lists them with every lab's settings, so --set, --compare, --sweep, --animate,
/// demo.json and the Settings window reach them by the same names, and a lab's code never reads them.
#pragma once
#include "common/scene/camera.hpp"
#include "common/scene/scene.hpp"

#include <vector>

namespace wb {

class Settings;

/// The host's settings; see the file comment.
struct HostSettings {
  int bookmark = 1;       ///< camera.bookmark: the scene file's camera bookmark, counted from 1 as the keys are
  float lightOrbit = 0;   ///< light.orbit: degrees the scene's lights turn about the vertical axis
  float cameraDolly = 0;  ///< camera.dolly: units the camera stands further back from its bookmark's target
  float renderScale = 1;  ///< render.scale: the scene's resolution over the window's (in a window)
  float uiScale = 0;      ///< ui.scale: the panels' text size over 16 px (0: follow the monitor)
  bool uiPanels = true;   ///< ui.panels: the panels shown (H toggles it)
  /// present.*, for lectures (demo.json turns them on); the visibility buffer that tests read never changes.
  struct Present {
    bool srgb = false;  ///< present.srgb: encode the colour for the screen (the shading is linear)
    bool grid = false;  ///< present.grid: a faint world-unit grid on the ground
    int msaa = 0;       ///< present.msaa: 0 off, 1 four samples per pixel in the camera pass
  } present;            ///< present.*

  /// Registers them in a hosted lab's `settings`, with their ranges and help.
  void addTo(Settings& settings);
  /// Moves `camera` to bookmark `k` (from 1) of `scene` and makes it camera.bookmark; false, changing
  /// nothing, where the scene has no bookmark `k`.
  bool goToBookmark(int k, const Scene& scene, OrbitCamera& camera);
};

/// light.orbit and camera.dolly applied to a hosted lab's scene and camera (a clip: --animate).
class SceneMotion {
 public:
  /// Turns the scene's lights to light.orbit and moves the camera to its bookmark's distance plus
  /// camera.dolly, each where it changed since the last call (a new scene: a new SceneMotion).
  void apply(const HostSettings& settings, Scene& scene, OrbitCamera& camera);

 private:
  float appliedOrbit_ = 0, appliedDolly_ = 0;
  std::vector<Light> baseLights_;  // the scene's lights before light.orbit
};

}  // namespace wb
