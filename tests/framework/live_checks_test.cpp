// The window's exercise verdicts are those of the running code: the checks do not run from a test
// binary older than the C++ exercise file (it may hold older code), and an exercise.cpp edited after
// the running app was built is noted (the verdicts are the running build's, not the edit's).
#include "common/exercise/live_checks.hpp"
#include "common/judge/harness.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

struct Files {
  fs::path dir = wb::test::testOutputDir() / "live-checks";
  fs::path app = dir / "lab77", tests = dir / "lab77_tests", cpp = dir / "exercise.cpp";
  Files() {
    fs::create_directories(dir);
    for (const auto& f : {app, tests, cpp}) std::ofstream(f) << "x";
  }
  // Sets the three files' times, in seconds from now.
  void times(int app_s, int tests_s, int cpp_s) const {
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(app, now + std::chrono::seconds(app_s));
    fs::last_write_time(tests, now + std::chrono::seconds(tests_s));
    fs::last_write_time(cpp, now + std::chrono::seconds(cpp_s));
  }
};

TEST(LiveChecks, RunWhenTheTestsHoldTheRunningCode) {
  Files f;
  f.times(0, 1, -10);  // edited, then the app and its tests built
  wb::LiveChecks checks(f.tests.string(), f.app.string(), f.cpp.string());
  EXPECT_TRUE(checks.available());
  EXPECT_EQ(checks.note(), "");
}

TEST(LiveChecks, DoNotRunFromTestsOlderThanTheExercise) {
  Files f;
  f.times(0, -20, -10);  // the tests built before the edit, the app after it
  wb::LiveChecks checks(f.tests.string(), f.app.string(), f.cpp.string());
  EXPECT_FALSE(checks.available());
  EXPECT_NE(checks.note().find("lab77_tests is older than your exercise.cpp (./workbook check 77"), std::string::npos)
      << checks.note();
}

TEST(LiveChecks, NoteAnEditTheRunningAppDoesNotHold) {
  Files f;
  f.times(-20, -20, -20);
  wb::LiveChecks checks(f.tests.string(), f.app.string(), f.cpp.string());
  EXPECT_TRUE(checks.available());
  EXPECT_EQ(checks.note(), "");
  f.times(-20, -20, 0);  // edited while the lab runs
  checks.pollEdits();
  EXPECT_NE(checks.note().find("exercise.cpp changed after this build"), std::string::npos) << checks.note();
}

TEST(LiveChecks, SayWhenTheTestsAreNotBuilt) {
  Files f;
  wb::LiveChecks checks((f.dir / "lab77_missing_tests").string(), f.app.string(), f.cpp.string());
  EXPECT_FALSE(checks.available());
  EXPECT_NE(checks.note().find("is not built"), std::string::npos) << checks.note();
}

}  // namespace
