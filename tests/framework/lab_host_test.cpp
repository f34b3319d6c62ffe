// The app hosts lab objects: a program can create one lab, draw it, and switch to another in the
// same context, and the first lab's GL objects go before the context does (by ownership).
#include "common/shell/lab_host.hpp"
#include "common/base/variant.hpp"
#include "common/platform/context.hpp"
#include "common/shell/lab.hpp"
#include "common/truth/measurement.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

// A lab that fills the frame with one colour and counts its instances.
class SolidLab : public wb::Lab {
 public:
  explicit SolidLab(glm::vec4 colour) : Lab("scenes/depth_map.json"), colour_(colour) { ++alive; }
  ~SolidLab() override { --alive; }
  static inline int alive = 0;

 protected:
  void init() override {
    program_ = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "wb/flat.frag"}});
  }
  void render() override {
    bindFrameTarget();
    glClearBufferfv(GL_COLOR, 0, &colour_.x);
  }

 private:
  glm::vec4 colour_;
  wb::Program* program_ = nullptr;
};

int hostTwoLabs() {
  wb::Options options;
  options.headless = true, options.size = {32, 16}, options.frames = 1, options.quiet = true;
  options.record = "unused.json";  // (no default screenshot)
  wb::LabHost app(options);
  app.open("Lab 00: hosting");
  auto first = std::make_unique<SolidLab>(glm::vec4(1, 0, 0, 1));
  app.loadScene(*first);
  app.host(std::move(first));
  app.frame(1.0f / 60);
  if (app.target().readColor()[0] != 255) return 10;  // red
  auto second = std::make_unique<SolidLab>(glm::vec4(0, 0, 1, 1));
  app.loadScene(*second);
  app.host(std::move(second));
  if (SolidLab::alive != 1) return 11;  // the first lab is gone, while the context still lives
  app.frame(1.0f / 60);
  const auto px = app.target().readColor();
  if (px[0] != 0 || px[2] != 255) return 12;  // blue
  if (!wb::takeGlErrors().empty()) return 13;
  return 0;
}

}  // namespace

// A lab whose shadows come from geometry gets no shadow-map settings; one with a map gets them.
TEST(LabHost, SharedSettingsOnlyWhereTheyMeanSomething) {
  struct VolumeLab : wb::Lab {
    VolumeLab() : Lab("scenes/depth_map.json", wb::ShadowKind::Geometry) {}
    void init() override {}
    void render() override {}
  } volumes;
  auto names = [](wb::Lab& lab) {
    std::string all;
    for (const auto& s : lab.settings.all()) all += s.name + " ";
    return all;
  };
  EXPECT_EQ(names(volumes).find("shadow.map_size"), std::string::npos) << names(volumes);
  EXPECT_EQ(names(volumes).find("debug."), std::string::npos) << names(volumes);
  EXPECT_EQ(names(volumes).find("shadow.bias"), std::string::npos) << names(volumes);
  EXPECT_NE(names(volumes).find("light.index"), std::string::npos) << names(volumes);
  SolidLab mapped(glm::vec4(1));
  EXPECT_NE(names(mapped).find("shadow.map_size"), std::string::npos) << names(mapped);
  EXPECT_NE(names(mapped).find("debug.shadow_map"), std::string::npos) << names(mapped);
  EXPECT_EQ(names(mapped).find("shadow.bias"), std::string::npos) << "registered only by useDepthBias()";
  EXPECT_EQ(names(mapped).find("debug.light_face"), std::string::npos) << "registered only by useLightFaces()";
}

// The app's settings (camera.bookmark, light.orbit, camera.dolly, render.scale, ui.*, present.*) are
// the host's: a lab has none of them until a host lists them after its own, where --set reaches them
// by the same names. Nothing opens: the settings are checked before any window.
TEST(LabHost, ListsItsOwnSettingsAfterTheLabs) {
  SolidLab lab(glm::vec4(1));
  for (const auto& s : lab.settings.all())
    EXPECT_TRUE(s.name.rfind("ui.", 0) != 0 && s.name.rfind("present.", 0) != 0 && s.name != "render.scale" &&
                s.name != "camera.bookmark" && s.name != "light.orbit" && s.name != "camera.dolly")
        << s.name << " is the host's, not the lab's";
  const size_t own = lab.settings.all().size();
  wb::Options options;
  options.sets = {"ui.scale=2", "present.msaa=4", "camera.bookmark=3", "render.scale=0.5", "ui.panels=off"};
  wb::LabHost host(options);
  host.configure(lab);
  const std::vector<std::string> hosts = {"camera.bookmark", "light.orbit",  "camera.dolly", "render.scale", "ui.scale",
                                          "ui.panels",       "present.srgb", "present.grid", "present.msaa"};
  ASSERT_EQ(lab.settings.all().size(), own + hosts.size());
  for (size_t k = 0; k < hosts.size(); ++k) EXPECT_EQ(lab.settings.all()[own + k].name, hosts[k]);
  EXPECT_EQ(lab.settings.value("ui.scale"), "2");
  EXPECT_EQ(lab.settings.value("present.msaa"), "4");
  EXPECT_EQ(lab.settings.value("camera.bookmark"), "3");
  EXPECT_EQ(lab.settings.value("render.scale"), "0.5");
  EXPECT_EQ(lab.settings.value("ui.panels"), "false");
  wb::Options bad;
  bad.sets = {"ui.scale=9"};
  SolidLab other(glm::vec4(1));
  EXPECT_THROW(wb::LabHost(bad).configure(other), wb::UsageError);
}

// Run in a fresh process (gtest's threadsafe death-test style re-runs this binary), so the app's
// context is the only one there.
TEST(LabHost, HostsOneLabAfterAnotherInOneContext) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(std::exit(hostTwoLabs()), ::testing::ExitedWithCode(0), "");
}
