#include "common/exercise/include_policy.hpp"

#include "common/base/error.hpp"
#include "common/base/variant.hpp"
#include "common/platform/shader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace fs = std::filesystem;

namespace wb {

std::optional<std::vector<std::string>> exerciseIncludes(const fs::path& file) {
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(readFile(fs::path(variant::kLabDir) / "exercises.json"));
  } catch (const std::exception&) {
    return std::nullopt;  // no lab here (a framework test's own shaders)
  }
  const std::string name = file.filename().string();
  bool isExercise = false;
  for (const auto& e : manifest.value("exercises", nlohmann::json::array()))
    if (e.is_object() && e.value("file", "") == "shaders/" + name) isExercise = true;
  if (!isExercise) return std::nullopt;
  // Fail closed: an exercise file of a manifest without the list may include nothing.
  return manifest.value("glsl_includes", std::vector<std::string>{});
}

fs::path resolveExerciseInclude(const std::string& name, const fs::path& origin, int line,
                                const std::vector<std::string>& allowed) {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  const std::string where = origin.string() + ":" + std::to_string(line) + ": error: ";
  if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
    throw Error(where + "#include \"" + name + "\" is not allowed in an exercise file: it may include only what " +
                "the handed-out file includes (" + (list.empty() ? "nothing" : list) +
                "). Write your helpers in the file itself; the grader sees only this file.");
  // The allowed names are the framework's own, relative and without "..": look only where the
  // public shaders are (the lab's shaders/ holds no solution in any edition).
  for (const fs::path& dir : {fs::path(variant::kLabDir) / "shaders", fs::path(variant::kSourceDir) / "shaders"})
    if (fs::is_regular_file(dir / name)) return dir / name;
  throw Error(where + "shader file '" + name + "' not found in " + variant::kLabDir + "/shaders or " +
              variant::kSourceDir + "/shaders");
}

}  // namespace wb
