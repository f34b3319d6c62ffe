#include "common/shell/host_settings.hpp"

#include "common/base/settings.hpp"

#include <algorithm>

namespace wb {

void HostSettings::addTo(Settings& settings) {
  settings.add("camera.bookmark", bookmark, 1, 9, "camera bookmark of the scene file, 1 = the first (keys 1-9)");
  settings.add("light.orbit", lightOrbit, -180.0f, 180.0f,
               "degrees the scene's lights turn about the vertical axis through the origin (a clip: --animate "
               "light.orbit=0:90)");
  settings.add("camera.dolly", cameraDolly, -20.0f, 20.0f,
               "units the camera stands further back from its bookmark's target (negative: closer; a clip: "
               "--animate camera.dolly=4:0)");
  settings.add("render.scale", renderScale, 0.25f, 1.0f,
               "in a window, draw the scene at this fraction of the window's resolution and stretch it (the "
               "panels and captions stay sharp): 0.5 at 1920x1080 costs about what 960x540 does");
  settings.add("ui.scale", uiScale, 0.0f, 4.0f,
               "the panels' text size: 1 = 16 px, 2 = 32 px; 0 = follow the monitor (and 1.25x while presenting)");
  settings.add("ui.panels", uiPanels, "in a window, the panels (H toggles them; off: the scene alone, for a lecture)");
  settings.add("present.srgb", present.srgb, "write sRGB-encoded colour (the shading is linear)");
  settings.add("present.grid", present.grid, "a faint one-unit grid on the ground, to read texel sizes off");
  settings.addChoice("present.msaa", present.msaa, {"off", "4"},
                     "multisampling of the camera pass (an edge pixel's visibility becomes its samples' mean)");
}

bool HostSettings::goToBookmark(int k, const Scene& scene, OrbitCamera& camera) {
  if (k < 1 || k > int(scene.cameras.size())) return false;
  bookmark = k;
  camera.pose = scene.cameras[size_t(k - 1)];
  return true;
}

void SceneMotion::apply(const HostSettings& s, Scene& scene, OrbitCamera& camera) {
  if (s.lightOrbit != appliedOrbit_) {
    if (baseLights_.empty()) baseLights_ = scene.lights;
    for (size_t k = 0; k < scene.lights.size() && k < baseLights_.size(); ++k)
      scene.lights[k] = turnedAboutY(baseLights_[k], s.lightOrbit);
    appliedOrbit_ = s.lightOrbit;
  }
  if (s.cameraDolly != appliedDolly_ && s.bookmark >= 1 && s.bookmark <= int(scene.cameras.size())) {
    camera.pose.distance = std::max(0.05f, scene.cameras[size_t(s.bookmark - 1)].distance + s.cameraDolly);
    appliedDolly_ = s.cameraDolly;
  }
}

}  // namespace wb
