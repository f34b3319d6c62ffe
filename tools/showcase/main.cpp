// The showcase: every technique of the ten labs on one scene, in one window (./workbook showcase).
// ---------------------------------------------------------------------------------------------
// Each technique is a lab's own solution, hosted (common/shell/embedded_lab.hpp): nothing is copied here.
// showcase.technique switches live and keeps the camera; the shared split screen compares any two
// techniques (compare showcase.technique) or two settings of one; "ray_traced" is the exact
// visibility as a render mode, timed like the others; "Measure" compares any of them with it (and
// with the area-light reference, since the scene's spot light has a size).
// ./workbook showcase --table sweeps every technique with --metrics into one table.
#include "common/shell/bench.hpp"
#include "common/shell/embedded_lab.hpp"

#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

namespace wb::showcase {
extern const std::vector<std::pair<std::string, EmbeddedLab::MainFunction>> kLabMains;  // generated
}

namespace {

// One row of the showcase: a lab's solution with some of its settings. Every technique lights the
// scene alike (Lab::beginCameraPass: the direction to the light per pixel and the spot's cone), from
// light 0, a spot light with a size; two cannot: a cube map is a point light's (light 1) and
// cascades are a sun's (light 2).
struct Technique {
  const char* name;               // showcase.technique's value
  const char* lab;                // the lab whose solution draws it
  std::vector<std::string> sets;  // its settings in that lab
  const char* kernelKey;          // the lab's filter-width setting that showcase.kernel sets ("": none)
};

const std::vector<Technique> kTechniques = {
    {"hard", "01_depth_map", {}, ""},
    {"slope_bias", "02_bias", {"bias.method=slope"}, "pcf.kernel"},
    {"pcf", "03_pcf", {"pcf.method=grid"}, "pcf.kernel"},
    {"esm", "04_esm", {}, "prefilter.kernel"},
    {"vsm", "05_vsm", {}, "prefilter.kernel"},
    {"evsm", "06_evsm", {}, "prefilter.kernel"},
    {"msm", "06_evsm", {"evsm.technique=msm"}, "prefilter.kernel"},
    {"pcss", "07_pcss", {}, ""},
    {"cube_map", "08_cube_maps", {"light.index=1", "cube.filter=pcf", "cube.cache=off"}, ""},  // six faces every frame
    {"volumes", "09_shadow_volumes", {}, ""},
    {"cascades", "10_cascades", {"light.index=2", "csm.shadow_distance=30", "csm.lambda=0.3"}, "csm.kernel"},
    {"lispsm", "11_warping", {"light.index=2", "warp.shadow_distance=30", "warp.scheme=lispsm"}, ""},
    {"sdsm",
     "11_warping",
     {"light.index=2", "warp.shadow_distance=30", "warp.scheme=csm", "warp.sdsm=on", "csm.lambda=1"},
     ""},
    {"ray_traced", "09_shadow_volumes", {"shadow.technique=ray_traced"}, ""},
};

const std::vector<std::string> kKernels = {"lab", "1", "3", "5", "7"};
const std::vector<std::string> kMapSizes = {"lab", "512", "1024", "2048", "4096"};

wb::EmbeddedLab::MainFunction mainOf(const std::string& lab) {
  for (const auto& [name, f] : wb::showcase::kLabMains)
    if (name == lab) return f;
  throw wb::Error("the showcase was built without lab " + lab);
}

class Showcase : public wb::Lab {
 public:
  Showcase() : Lab("scenes/showcase.json", wb::ShadowKind::Geometry) {
    std::vector<std::string> names;
    for (const auto& t : kTechniques) names.push_back(t.name);
    settings.addChoice("showcase.technique", technique, names,
                       "the technique drawn: a lab's solution (compare two with the split screen)");
    settings.addChoice("showcase.kernel", kernel, kKernels,
                       "filter width set in every technique that has one (lab: each lab's own setting)");
    settings.addChoice("showcase.map_size", mapSize, kMapSizes,
                       "shadow.map_size set in every technique with a map (lab: each lab's own setting)");
    own.include(settings, [](const wb::Setting& s) { return s.name != "alpha.cutoff" && s.name != "light.index"; });
    own.onChange("showcase.technique", [this] { adopt(); });
    for (const auto& t : kTechniques) hosted.push_back(std::make_unique<wb::EmbeddedLab>(t.lab, mainOf(t.lab), t.sets));
    frameMs.assign(kTechniques.size(), wb::RollingTimes());
    splitMs.assign(kTechniques.size(), wb::RollingTimes());
    lastMeasured.assign(kTechniques.size(), "");
    adopt();
  }

 protected:
  void init() override {}

  // The frame time goes to the technique drawn. A frame that measured (Measure, a presenter step)
  // is not a frame of the technique's and is left out; a split screen's goes to both of its halves'
  // techniques, in a list of its own (a frame with both halves is not either one's frame).
  void update(float dt) override {
    if (adopted != technique) adopt();  // (the settings panel changed it)
    const bool skip = std::exchange(measuredLastFrame, false);
    const wb::CompareChoice& split = comparison();
    if (!skip && split.on && split.key == "showcase.technique") {
      for (const std::string& half : {split.a, split.b})
        for (size_t k = 0; k < kTechniques.size(); ++k)
          if (half == kTechniques[k].name) splitMs[k].add(dt * 1000.0);
    } else if (!skip && !split.on) {
      frameMs[size_t(technique)].add(dt * 1000.0);
    }
    lastDt = dt;
  }

  void render() override {
    wb::EmbeddedLab& h = *hosted[size_t(technique)];
    const Technique& t = kTechniques[size_t(technique)];
    if (kernel > 0 && *t.kernelKey) h.lab().settings.assign(std::string(t.kernelKey) + "=" + kKernels[size_t(kernel)]);
    if (mapSize > 0 && h.lab().settings.has("shadow.map_size"))
      h.lab().settings.assign("shadow.map_size=" + kMapSizes[size_t(mapSize)]);
    h.render(*this, lastDt);
    drawn = technique;
    for (const auto& w : h.takeWarnings()) warn(w);
  }

  // The app's debug views and measurements describe the technique drawn last.
  wb::FrameShown shown() const override { return drawn < 0 ? Lab::shown() : hosted[size_t(drawn)]->lab().shown(); }

  // Each technique keeps its last measurement (Measure, whole frame), shown beside its frame time.
  void measured(const std::string& numbers, bool split) override {
    if (!split) lastMeasured[size_t(technique)] = numbers.substr(numbers.find(':') + 2);
    measuredLastFrame = true;  // (the next frame's time includes the measurement)
  }

  void ui() override {
    hosted[size_t(technique)]->ui();  // (the lab's own widgets, in the Settings window)
    techniquesWindow();
  }

 private:
  // A window of its own, bottom left (the Settings window is long): every technique, its frame time
  // while shown and its last whole-frame measurement.
  void techniquesWindow() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(8, display.y - 8), ImGuiCond_FirstUseEver, ImVec2(0, 1));
    // One line until opened, like the Settings window: opened, it covers the lower left of the scene.
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    ImGui::Begin("Techniques (frame ms while shown)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    const float unit = ImGui::GetFontSize();
    for (size_t k = 0; k < kTechniques.size(); ++k) {
      const std::string row = std::string(kTechniques[k].name) + "  (lab " + std::string(kTechniques[k].lab, 2) + ")";
      if (ImGui::Selectable(row.c_str(), int(k) == technique, 0, ImVec2(11 * unit, 0))) technique = int(k), adopt();
      ImGui::SameLine(12 * unit);
      const wb::RollingTimes& t = frameMs[k];
      if (!t.empty())
        ImGui::Text("%5.1f ms (%.1f–%.1f)  %s", t.median(), t.low(), t.high(), lastMeasured[k].c_str());
      else
        ImGui::TextUnformatted("    -");
      if (!splitMs[k].empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("split screen %.1f ms", splitMs[k].median());
      }
    }
    ImGui::TextDisabled("median of the last 60 frames (10th to 90th percentile); frames that measured are left out");
    ImGui::TextDisabled("Measure (info panel) fills in a row's acne, leak and error against the truth");
    ImGui::End();
  }

  // The settings shown are the showcase's own, the chosen technique's (they write its lab's values)
  // and the app's (camera.bookmark, ui.*, present.*: the host adds them after the constructor).
  void adopt() {
    clearWarnings();  // the warnings shown are the technique's own (a cube map's stays with the cube map)
    hosted[size_t(technique)]->resendWarnings();
    wb::Settings next = own;
    next.include(hosted[size_t(technique)]->lab().settings, [](const wb::Setting&) { return true; });
    const wb::Settings* before = adopted < 0 ? nullptr : &hosted[size_t(adopted)]->lab().settings;
    next.include(settings, [&](const wb::Setting& s) { return !before || !before->has(s.name); });  // the app's
    settings = next;
    adopted = technique;
  }

  std::vector<std::unique_ptr<wb::EmbeddedLab>> hosted;  // one per technique, in kTechniques' order
  wb::Settings own;                                      // showcase.*
  std::vector<wb::RollingTimes> frameMs;                 // per technique, its whole frames
  std::vector<wb::RollingTimes> splitMs;                 // per technique, split-screen frames with it in a half
  bool measuredLastFrame = false;                        // that frame's time includes a measurement
  std::vector<std::string> lastMeasured;                 // per technique, its last whole-frame measurement
  int technique = 2, adopted = -1, drawn = -1;           // pcf; the one whose settings are shown; drawn last
  int kernel = 2, mapSize = 2;                           // 3 taps, 1024 texels: seed 000's defaults
  float lastDt = 1.0f / 60;
};

}  // namespace

int main(int argc, char** argv) { return wb::run<Showcase>(argc, argv); }
