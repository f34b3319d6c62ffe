// A file written against an earlier edition of a lab (before one of its exercises, such as a bug
// hunt, was added) is graded exercise by exercise: what it lacks comes from the stub.
#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/shader.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace {

using Ids = std::vector<std::string>;

fs::path source(const std::string& rel) { return fs::path(wb::variant::kSourceDir) / rel; }

// `text` without exercise `id`'s chunk, marker and all: the file as it was before `id` existed.
std::string without(const std::string& text, const std::string& id) {
  const auto [begin, end] = wb::chunkRange(text, id);
  std::string out = text.substr(0, begin) + text.substr(end);
  if (end == text.size()) out += "\n";  // (a C++ file's last chunk holds its namespace's end: keep it)
  const size_t close = text.find("}  // namespace", begin);
  if (close != std::string::npos && close < end) out += text.substr(close);
  return out;
}

TEST(EarlierEdition, ACppFileWithoutTheHuntGetsTheStubsHuntInsideItsNamespace) {
  const std::string stub = wb::readFile(source("labs/01_depth_map/exercise.cpp"));
  const std::string mine = wb::readFile(source("solutions/01_depth_map/exercise.cpp"));
  const wb::FilledChunks filled = wb::fillMissingChunks(without(mine, "01.H1"), stub);
  EXPECT_EQ(filled.added, Ids{"01.H1"});
  const size_t begin = wb::chunkRange(filled.text, "01.H1").first, sBegin = wb::chunkRange(stub, "01.H1").first;
  const std::string hunt = stub.substr(sBegin, stub.rfind("}  // namespace") - sBegin);  // (its last chunk)
  EXPECT_EQ(filled.text.find(hunt), begin) << filled.text;
  EXPECT_EQ(filled.text.substr(begin + hunt.size()), "}  // namespace lab01\n");  // the namespace closes after it
  // Every exercise the file has is its own, as written.
  for (const char* id : {"01.1", "01.2"}) {
    const auto [b, e] = wb::chunkRange(mine, id);
    EXPECT_NE(filled.text.find(mine.substr(b, e - b)), std::string::npos) << id;
  }
}

TEST(EarlierEdition, NothingIsAddedToACurrentFileOrForADeletedMarker) {
  const std::string stub = wb::readFile(source("labs/01_depth_map/exercise.cpp"));
  const std::string mine = wb::readFile(source("solutions/01_depth_map/exercise.cpp"));
  EXPECT_EQ(wb::fillMissingChunks(mine, stub).text, mine);
  EXPECT_TRUE(wb::fillMissingChunks(stub, stub).added.empty());
  // The marker deleted, the code kept: the student's own code is graded (no second definition).
  std::string unmarked = mine;
  unmarked.erase(wb::findMarker(unmarked, "01.2"), std::string("// EXERCISE 01.2").size());
  EXPECT_TRUE(wb::fillMissingChunks(unmarked, stub).added.empty());
}

TEST(EarlierEdition, TheLineSaysWhichFilePredatesWhatAndWhereItsStubIs) {
  const std::string grader = wb::filledChunkLine("labs/03_pcf/shaders/exercise.glsl", "03.H1",
                                                 "tests/stubs/03_pcf/shaders/exercise.glsl", false);
  EXPECT_NE(grader.find("labs/03_pcf/shaders/exercise.glsl predates exercise 03.H1"), std::string::npos);
  EXPECT_NE(grader.find("copy its chunk from tests/stubs/03_pcf/shaders/exercise.glsl"), std::string::npos);
  EXPECT_NE(wb::filledChunkLine("f", "03.H1", "s", true).find("check put its stub into the file"), std::string::npos);
}

// In every lab's GLSL, a solution without any one exercise's chunk compiles once filled in, with that
// exercise alone added: the rest of the file is graded as written (a later chunk may call an
// earlier one, so the chunk goes back where the stub has it).
using wb::test::GlTest;
TEST_F(GlTest, EveryLabsShaderWithoutAnyOneExerciseCompilesOnceFilled) {
  int tried = 0;
  const char* const ownLab = wb::variant::kLabDir;
  for (const auto& lab : fs::directory_iterator(source("labs"))) {
    const fs::path stubFile = lab.path() / "shaders/exercise.glsl";
    const fs::path solutionFile = source("solutions") / lab.path().filename() / "shaders/exercise.glsl";
    if (!fs::exists(stubFile) || !fs::exists(solutionFile)) continue;
    const std::string labDir = lab.path().string();
    wb::variant::kLabDir = labDir.c_str();  // (the lab's include rules, as the showcase points them)
    const std::string stub = wb::readFile(stubFile), mine = wb::readFile(solutionFile);
    for (const auto& [id, chunk] : wb::splitChunks(stub)) {
      if (id.empty() || id.find('"') != std::string::npos) continue;  // (08's header quotes "// EXERCISE 08.x")
      const wb::FilledChunks filled = wb::fillMissingChunks(without(mine, id), stub);
      EXPECT_EQ(filled.added, Ids{id}) << lab.path().filename();
      EXPECT_EQ(wb::glslKernelError(filled.text, stubFile), "") << lab.path().filename() << " without " << id;
      ++tried;
    }
  }
  wb::variant::kLabDir = ownLab;
  EXPECT_GE(tried, 40) << "every exercise chunk of the labs' GLSL";
}

}  // namespace
