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
  wb::LabHost app(options, "Lab 00: hosting");
  auto first = std::make_unique<SolidLab>(glm::vec4(1, 0, 0, 1));
  wb::LabHost::loadScene(*first, options);
  app.host(std::move(first));
  app.frame(1.0f / 60);
  if (app.target().readColor()[0] != 255) return 10;  // red
  auto second = std::make_unique<SolidLab>(glm::vec4(0, 0, 1, 1));
  wb::LabHost::loadScene(*second, options);
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
    for (const auto& s : lab.tunables().all()) all += s.name + " ";
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

// Run in a fresh process (gtest's threadsafe death-test style re-runs this binary), so the app's
// context is the only one there.
TEST(LabHost, HostsOneLabAfterAnotherInOneContext) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(std::exit(hostTwoLabs()), ::testing::ExitedWithCode(0), "");
}
