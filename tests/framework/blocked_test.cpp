// A GLSL compile error belongs to the exercise whose chunk of the shared exercise file holds it: the
// lab's runs for every other exercise then fail as "blocked by" it, and only it shows the error.
// This build has no solution (like the student edition), so nothing isolates the chunks: lab 01's
// stub file is broken in 01.4's chunk and handed to the lab through WB_SHADER_OVERLAY.
#include "common/base/variant.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/shader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

class BrokenChunk : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string glsl = wb::readFile(fs::path(wb::variant::kLabDir) / "shaders/exercise.glsl");
    const size_t marker = wb::findMarker(glsl, "01.4");
    ASSERT_NE(marker, std::string::npos) << "lab 01's stub has no 01.4 marker";
    const size_t body = glsl.find("return", marker);
    ASSERT_NE(body, std::string::npos);
    glsl.replace(body, 6, "retrun");  // a typo in 01.4's body
    brokenLine_ = 1 + int(std::count(glsl.begin(), glsl.begin() + body, '\n'));
    dir_ = wb::test::testOutputDir() / "broken-chunk";
    fs::create_directories(dir_);
    std::ofstream(dir_ / "exercise.glsl") << glsl;
    setenv("WB_SHADER_OVERLAY", dir_.c_str(), 1);
  }
  void TearDown() override { unsetenv("WB_SHADER_OVERLAY"); }
  fs::path dir_;
  int brokenLine_ = 0;
};

TEST_F(BrokenChunk, TheLineBelongsToItsExercise) {
  EXPECT_EQ(wb::exerciseAtLine("exercise.glsl", brokenLine_), "01.4");
  EXPECT_EQ(wb::exerciseAtLine("exercise.glsl", 1), "") << "above the first marker is no exercise's";
  EXPECT_EQ(wb::exerciseAtLine("no_such_file.glsl", brokenLine_), "");
}

TEST_F(BrokenChunk, OtherExercisesAreBlockedAndOnlyItsOwnShowsTheError) {
  const std::string where = "exercise.glsl:" + std::to_string(brokenLine_) + ": error";
  std::string failure;
  wb::test::runLabOutput("01.4", "Broken", {"--size", "64x36"}, failure);
  EXPECT_NE(failure.find(where), std::string::npos) << "01.4 should show its compile error:\n" << failure;
  for (const char* other : {"01.3", "01.5", "01.1"}) {  // GLSL exercises and a C++ one
    wb::test::runLabOutput(other, "Broken", {"--size", "64x36"}, failure);
    EXPECT_EQ(failure.rfind("ERROR: blocked by 01.4:", 0), 0u) << other << " got:\n" << failure;
    EXPECT_EQ(failure.find(where), std::string::npos) << other << " repeats 01.4's error:\n" << failure;
  }
}

}  // namespace
