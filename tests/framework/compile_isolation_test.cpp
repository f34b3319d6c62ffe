// Which exercise broke a shader file is decided by compiling, never by reading the driver's log: a
// GPU's compiler words, numbers and cascades its errors its own way (on NVIDIA one missing ';' in
// 02.5 was followed by errors in functions that were fine, and every exercise of lab 02 was called
// an error). The log is only mapped to file:line for people, from every vendor's syntax.
#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/shader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace {

using Ids = std::set<std::string>;

// A file of three exercises; `broken` names the chunks that hold a planted "oops".
std::string threeChunks(const Ids& broken, bool brokenHelpers = false) {
  std::string text = std::string("// helpers\n") + (brokenHelpers ? "oops\n" : "") + "float h() { return 1.0; }\n";
  for (const char* id : {"01.1", "01.2", "01.3"})
    text += std::string("// EXERCISE ") + id + ": one\nfloat f" + id[3] + "() { return " +
            (broken.count(id) ? "oops" : "WB_TODO") + "; }\n";
  return text;
}

// A compiler that fails on "oops" wherever it is: what it would say is not asked.
bool compilesWithoutOops(const std::string& text) { return text.find("oops") == std::string::npos; }

TEST(ChunkIsolation, NamesTheChunksThatFailAloneByCompiling) {
  const std::string stub = threeChunks({});
  int compiles = 0;
  auto counted = [&](const std::string& t) { return ++compiles, compilesWithoutOops(t); };
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({"01.2"}), stub, counted), Ids{"01.2"});
  EXPECT_EQ(compiles, 4) << "a compile per chunk, and one to confirm";
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({"01.1", "01.3"}), stub, compilesWithoutOops),
            (Ids{"01.1", "01.3"}));
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({"01.1", "01.2", "01.3"}), stub, compilesWithoutOops),
            (Ids{"01.1", "01.2", "01.3"}));
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({}), stub, compilesWithoutOops), Ids{}) << "nothing broken";
}

TEST(ChunkIsolation, NamesNoneWhenTheFaultIsOutsideTheChunks) {
  const std::string stub = threeChunks({});
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({"01.2"}, true), stub, compilesWithoutOops), Ids{})
      << "the helpers above the first marker are no exercise's";
  EXPECT_EQ(wb::chunksThatDoNotCompile(threeChunks({"01.2"}), "", compilesWithoutOops), Ids{}) << "no stub";
  // Two chunks that compile alone and not together (both define g): nothing to name.
  std::string clash = stub;
  clash.replace(clash.find("float f1"), 0, "float g() { return 0.0; }\n");
  clash.replace(clash.find("float f3"), 0, "float g() { return 0.0; }\n");
  auto noTwoGs = [](const std::string& t) { return t.find("float g()") == t.rfind("float g()"); };
  EXPECT_EQ(wb::chunksThatDoNotCompile(clash, stub, noTwoGs), Ids{});
}

TEST(ChunkIsolation, TheCulpritLineIsReadOnlyWhereTheAppWritesIt) {
  const std::string line = wb::culpritLine({"02.5", "02.6"});
  EXPECT_EQ(wb::culpritsIn("lab02: " + line + "\nshader x failed to build:\n"), (Ids{"02.5", "02.6"}));
  EXPECT_EQ(wb::culpritsIn("noise\n" + wb::culpritLine({"01.4"}) + "\n"), Ids{"01.4"});
  EXPECT_EQ(wb::culpritsIn("labs/x/shaders/exercise.glsl:12: error: #error " + line + "\n"), Ids{})
      << "a compiler's message quoting a student's #error is not the app's word";
  EXPECT_EQ(wb::culpritsIn("shader x failed to build:\nexercise.glsl:3: error: syntax error\n"), Ids{});
}

// Each fixture line (a vendor's own words, from the address above it) names the source and line
// after its tab; mapped, it starts with that file and line, in the one form every reader takes.
TEST(ShaderLog, EveryVendorsPositionsAreMappedToFileAndLine) {
  const fs::path dir = fs::path(wb::variant::kSourceDir) / "tests/framework/fixtures/compiler_logs";
  std::vector<fs::path> files;
  for (int k = 0; k < 10; ++k) files.push_back("shaders/source" + std::to_string(k) + ".glsl");
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    std::ifstream in(entry.path());
    for (std::string l; std::getline(in, l);) {
      if (l.empty() || l[0] == '#' || l.find('\t') == std::string::npos) continue;
      const std::string raw = l.substr(0, l.find('\t')), want = l.substr(l.find('\t') + 1);
      const std::string mapped = wb::mapShaderLog(raw, files);
      if (want == "-") {
        EXPECT_EQ(mapped, raw + "\n") << entry.path().filename() << ": a line without a position is kept";
        continue;
      }
      const std::string source = want.substr(0, want.rfind(':')), lineNo = want.substr(want.rfind(':') + 1);
      // (glslang run on files names them; a GL driver numbers the strings it was given, as here)
      if (source.find_first_not_of("0123456789") != std::string::npos) continue;
      const std::string expect = "shaders/source" + source + ".glsl:" + lineNo + ": ";
      EXPECT_EQ(mapped.rfind(expect, 0), 0u) << entry.path().filename() << ": " << raw << "\n-> " << mapped;
      EXPECT_EQ(wb::firstErrorLine(mapped).rfind(expect, 0), 0u) << mapped;
      ++checked;
    }
  }
  EXPECT_GE(checked, 12) << "the fixtures in " << dir;
}

// The stand-in for NVIDIA's log (WB_SHADER_LOG_AS=nvidia) really misleads a reader of the log: its
// first error is not where the typo is. The tests run under it too (tests/framework/CMakeLists.txt).
TEST(ShaderLog, TheNvidiaStandInLeadsWithAFollowOnError) {
  setenv("WB_SHADER_LOG_AS", "nvidia", 1);
  const std::string log = wb::logAsVendor("0:17(2): error: syntax error, unexpected ';'\n");
  unsetenv("WB_SHADER_LOG_AS");
  EXPECT_EQ(log, "0(1) : error C1108: function has no statements\n0(17) : error C0000: syntax error, unexpected ';'\n");
  EXPECT_EQ(wb::firstErrorLine(wb::mapShaderLog(log, {"exercise.glsl"})),
            "exercise.glsl:1: error C1108: function has no statements");
}

// A typo planted in each exercise chunk of every lab's GLSL, stub and solution alike, is that
// exercise's alone, decided by compiling in a kernel as the window's board does.
using wb::test::GlTest;
TEST_F(GlTest, ATypoInEachChunkOfEveryLabIsThatExercisesAlone) {
  int planted = 0;
  const char* const ownLab = wb::variant::kLabDir;
  for (const auto& lab : fs::directory_iterator(fs::path(wb::variant::kSourceDir) / "labs")) {
    const fs::path stubFile = lab.path() / "shaders/exercise.glsl";
    if (!fs::exists(stubFile)) continue;
    const std::string labDir = lab.path().string();
    wb::variant::kLabDir = labDir.c_str();  // (the lab's include rules, as the showcase points them)
    const std::string stub = wb::readFile(stubFile);
    const fs::path solutionFile =
        fs::path(wb::variant::kSourceDir) / "solutions" / lab.path().filename() / "shaders/exercise.glsl";
    std::vector<std::string> versions = {stub};
    if (fs::exists(solutionFile)) versions.push_back(wb::readFile(solutionFile));
    auto compiles = [&](const std::string& t) { return wb::glslKernelError(t, stubFile).empty(); };
    for (const std::string& mine : versions) {
      if (const std::string error = wb::glslKernelError(mine, stubFile); !error.empty()) {
        wb::variant::kLabDir = ownLab;
        FAIL() << stubFile << " does not compile as it is: " << error;
      }
      for (const auto& [id, chunk] : wb::splitChunks(mine)) {
        if (id.empty() || id.find('"') != std::string::npos) continue;  // (08's header quotes "// EXERCISE 08.x")
        std::string broken = mine;  // a missing ';' on the first line of the chunk's first function
        const size_t brace = broken.find('{', wb::chunkRange(broken, id).first);
        ASSERT_LT(brace, wb::chunkRange(broken, id).second) << id << " has no function";
        broken.insert(brace + 1, "\n  float oops = 1.0\n");
        EXPECT_EQ(wb::chunksThatDoNotCompile(broken, stub, compiles), Ids{id}) << lab.path().filename();
        ++planted;
      }
    }
  }
  wb::variant::kLabDir = ownLab;
  EXPECT_GE(planted, 60) << "every chunk of ten labs, stubs and solutions";
}

}  // namespace
