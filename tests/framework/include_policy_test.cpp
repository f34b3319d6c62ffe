// What a student's GLSL may include (common/exercise/include_policy.hpp): a red-team submission once
// included the reference's exercise.glsl through the judge's shader path and scored full marks.
#include "common/base/error.hpp"
#include "common/base/variant.hpp"
#include "common/exercise/exercise_source_rules.hpp"
#include "common/platform/shader.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) {
  const fs::path dir = fs::path(wb::variant::kOutputDir) / name;
  fs::create_directories(dir);
  return dir;
}

// The error preprocessing `text` as the exercise file `origin` gives ("" when it expands).
std::string includeError(const std::string& text, const fs::path& origin, const std::vector<fs::path>& path) {
  try {
    wb::preprocessShader(text, origin, "", path, {}, &wb::exerciseSourceRules());
    return "";
  } catch (const wb::Error& e) {
    return e.what();
  }
}

}  // namespace

// One source of truth: a manifest's "glsl_includes" is exactly what its lab's GLSL stubs include.
TEST(IncludePolicy, ManifestListsTheStubsIncludes) {
  const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\")");
  int labs = 0;
  for (const auto& dir : fs::directory_iterator(fs::path(wb::variant::kSourceDir) / "labs")) {
    if (!fs::exists(dir.path() / "exercises.json")) continue;
    const auto manifest = nlohmann::json::parse(wb::readFile(dir.path() / "exercises.json"));
    std::set<std::string> files, stubIncludes;
    for (const auto& e : manifest.at("exercises"))
      if (e.at("file").get<std::string>().rfind("shaders/", 0) == 0) files.insert(e.at("file").get<std::string>());
    for (const auto& f : files) {
      std::ifstream in(dir.path() / f);
      std::smatch m;
      for (std::string line; std::getline(in, line);)
        if (std::regex_search(line, m, includeRe)) stubIncludes.insert(m[1].str());
    }
    const auto listed = manifest.value("glsl_includes", std::vector<std::string>{});
    EXPECT_EQ(std::set<std::string>(listed.begin(), listed.end()), stubIncludes) << dir.path() / "exercises.json";
    ++labs;
  }
  EXPECT_GE(labs, 10);
}

// A relative, a deeper, an absolute and a self include of the reference are refused, with the file
// and line and what is allowed; nothing is read from the solutions.
TEST(IncludePolicy, AnExerciseFileCannotIncludeTheReference) {
  const fs::path dir = scratchDir("include_policy");
  const fs::path origin = dir / "exercise.glsl";
  const std::string lab = fs::path(wb::variant::kLabDir).filename().string();
  const fs::path solution = fs::path(wb::variant::kSourceDir) / "solutions" / lab / "shaders/exercise.glsl";
  const std::vector<fs::path> path = {dir, fs::path(wb::variant::kSourceDir) / "solutions" / lab / "shaders",
                                      fs::path(wb::variant::kSourceDir) / "shaders"};
  const std::vector<std::string> names = {
      "../../solutions/" + lab + "/shaders/exercise.glsl", "../../../../../solutions/" + lab + "/shaders/exercise.glsl",
      solution.string(), "exercise.glsl", "wb/../../solutions/" + lab + "/shaders/exercise.glsl"};
  for (const std::string& name : names) {
    const std::string error = includeError("#version 410 core\n\n#include \"" + name + "\"\n", origin, path);
    EXPECT_NE(error.find(origin.string() + ":3: error: #include \"" + name + "\" is not allowed"), std::string::npos)
        << name << "\n"
        << error;
    EXPECT_NE(error.find("wb/exercise.glsl"), std::string::npos) << "names what is allowed: " << error;
  }
}

// An allowed include comes from the public shaders/, whatever sits next to the file or on the path.
TEST(IncludePolicy, AnAllowedIncludeIsThePublicOne) {
  const fs::path dir = scratchDir("include_policy_decoy");
  fs::create_directories(dir / "wb");
  std::ofstream(dir / "wb/exercise.glsl") << "float decoy() { return 1.0; }\n";
  const wb::ShaderSource src = wb::preprocessShader("#version 410 core\n#include \"wb/exercise.glsl\"\n",
                                                    dir / "exercise.glsl", "", {dir}, {}, &wb::exerciseSourceRules());
  ASSERT_GE(src.files.size(), 2u);
  EXPECT_EQ(src.files[1], fs::path(wb::variant::kSourceDir) / "shaders/wb/exercise.glsl");
  EXPECT_EQ(src.text.find("decoy"), std::string::npos);
}

// Other files (the labs' own shaders) include as before: next to the file, then on the path.
TEST(IncludePolicy, OtherFilesIncludeFreely) {
  const fs::path dir = scratchDir("include_policy_other");
  std::ofstream(dir / "helper.glsl") << "float helper() { return 1.0; }\n";
  const wb::ShaderSource src =
      wb::preprocessShader("#include \"helper.glsl\"\n", dir / "depth.frag", "", {}, {}, &wb::exerciseSourceRules());
  EXPECT_NE(src.text.find("helper()"), std::string::npos);
}
