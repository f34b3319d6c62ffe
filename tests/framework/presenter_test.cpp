// Presenter steps (common/shell/presenter.hpp): a malformed demo.json is named with its step and what is
// wrong, steps do not accumulate (paging back shows what paging forward showed), a step that does
// not exist is a usage error, and the showcase's settings follow its technique at once.
#include "common/shell/presenter.hpp"
#include "common/base/error.hpp"
#include "common/base/settings.hpp"
#include "common/base/variant.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

// One file per test: ctest runs the tests of this file side by side, each in its own process.
fs::path demoFile(const std::string& json) {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / "presenter";
  fs::create_directories(dir);
  const fs::path file = dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json");
  std::ofstream(file) << json;
  return file;
}

std::string loadError(const std::string& json) {
  try {
    wb::loadDemo(demoFile(json));
  } catch (const wb::UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Presenter, AMalformedDemoIsNamedWithItsStepAndWhatIsWrong) {
  EXPECT_NE(loadError("{\"steps\": [").find("cannot read the demo"), std::string::npos);
  EXPECT_NE(loadError("{\"steps\": []}").find("has no steps"), std::string::npos);
  const std::string noCaption =
      loadError(R"({"steps": [{"title": "a", "caption": "b"}, {"title": "c", "settings": {}}]})");
  EXPECT_NE(noCaption.find("step 2"), std::string::npos) << noCaption;
  EXPECT_NE(noCaption.find("caption"), std::string::npos) << noCaption;
  const std::string badValue = loadError(R"({"steps": [{"title": "a", "caption": "b", "settings": {"k": null}}]})");
  EXPECT_NE(badValue.find("step 1"), std::string::npos) << badValue;
}

TEST(Presenter, SettingsApplyInTheOrderWritten) {  // (the showcase's technique before its own settings)
  const auto steps = wb::loadDemo(demoFile(R"({"steps": [{"title": "t", "caption": "c",
      "settings": {"z.technique": "b", "a.its_own": "1"}}]})"));
  ASSERT_EQ(steps.at(0).sets.size(), 2u);
  EXPECT_EQ(steps[0].sets[0], "z.technique=b");
}

TEST(Presenter, StepsStartFromTheSettingsAtStartAndDoNotAccumulate) {
  float a = 1, b = 2;
  bool on = false;
  wb::Settings s;
  s.add("x.a", a, 0.0f, 10.0f, "");
  s.add("x.b", b, 0.0f, 10.0f, "");
  s.add("x.on", on, "");
  const fs::path file = demoFile(R"({"settings": {"x.on": true}, "steps": [
      {"title": "one", "caption": "a is 5", "settings": {"x.a": "5"}, "bookmark": 2,
       "compare": {"key": "x.b", "a": 3, "b": "4"}, "measure": true},
      {"title": "two", "caption": "b is 7", "settings": {"x.b": 7}}]})");
  const wb::Presenter p(file, s);
  ASSERT_EQ(p.count(), 2);
  const wb::DemoStep& one = p.apply(1, s);
  EXPECT_EQ(a, 5);
  EXPECT_EQ(b, 2);
  EXPECT_TRUE(on);
  EXPECT_EQ(one.bookmark, 2);
  EXPECT_TRUE(one.measure);
  EXPECT_TRUE(one.compare.on);
  EXPECT_EQ(one.compare.a, "3");
  p.apply(2, s);
  EXPECT_EQ(a, 1) << "step 2 starts from the start, not from step 1";
  EXPECT_EQ(b, 7);
  p.apply(1, s);
  EXPECT_EQ(a, 5);
  EXPECT_EQ(b, 2);
  EXPECT_THROW(p.apply(3, s), wb::UsageError);
  EXPECT_THROW(p.apply(0, s), wb::UsageError);
}

TEST(Presenter, AStepThatSetsWhatTheLabDoesNotHaveIsAUsageErrorNamingTheStep) {
  float a = 1;
  wb::Settings s;
  s.add("x.a", a, 0.0f, 10.0f, "");
  const wb::Presenter p(demoFile(R"({"steps": [{"title": "t", "caption": "c", "settings": {"x.nope": "1"}}]})"), s);
  try {
    p.apply(1, s);
    FAIL() << "no error";
  } catch (const wb::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("demo step 1 (\"t\")"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("x.nope"), std::string::npos) << e.what();
  }
}

TEST(Settings, OnChangeAndIncludeLetAHostFollowAHostedLabsSettings) {
  int which = 0;
  float mine = 0, theirs = 0, shared = 0;
  wb::Settings host, hosted;
  hosted.add("t.theirs", theirs, 0.0f, 1.0f, "");
  hosted.add("t.shared", shared, 0.0f, 1.0f, "");
  host.add("t.shared", mine, 0.0f, 1.0f, "");
  host.include(hosted, [](const wb::Setting& s) { return s.name != "t.hidden"; });
  host.assign("t.theirs=0.5");
  host.assign("t.shared=0.25");
  EXPECT_EQ(theirs, 0.5f) << "an included setting writes the hosted lab's value";
  EXPECT_EQ(mine, 0.25f) << "a name the host has stays the host's";
  EXPECT_EQ(shared, 0.0f);
  int calls = 0;
  host.addChoice("t.which", which, {"a", "b"}, "");
  host.onChange("t.which", [&] { ++calls; });
  host.assign("t.which=b");
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(which, 1);
}
