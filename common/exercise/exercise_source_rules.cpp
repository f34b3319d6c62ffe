#include "common/exercise/exercise_source_rules.hpp"

#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/exercise/include_policy.hpp"

#include <map>
#include <set>
#include <utility>

namespace fs = std::filesystem;

namespace wb {

const char* const kReferenceSourceNote =
    "(the reference code of another exercise, which your chunk is compiled with): an error there, caused by your "
    "code (a #define, an unclosed brace?); the message is not shown";

namespace {

// What a fallback build drew, for the panel: `swapped` holds (file, chunk id) pairs.
std::string fallbackNote(const std::vector<std::pair<fs::path, std::string>>& swapped, bool stub) {
  if (swapped.size() != 1) return "the last version that compiled is drawn";
  const std::string& id = swapped[0].second;
  if (id.empty())
    return "drawn with your last helpers that compiled (above the first exercise) and your current exercises";
  return "drawn with your last " + id + " that compiled" + (stub ? " (still the stub: stripes)" : "") +
         " and your current other exercises";
}

class ExerciseSourceRules : public SourceRules {
 public:
  std::optional<fs::path> resolveInclude(const std::string& name, const fs::path& origin, int line) const override {
    const auto allowed = exerciseIncludes(origin);  // a student's file: only its stub's includes
    if (!allowed) return std::nullopt;
    return resolveExerciseInclude(name, origin, line, *allowed);
  }

  bool remembers(const std::string& text) const override { return text.find("// EXERCISE ") != std::string::npos; }
  // (exercise.glsl and exercise_layered.geom: the files students write)
  bool guardsLoops(const fs::path& file) const override { return file.filename().string().rfind("exercise", 0) == 0; }

  std::vector<Fallback> fallbacks(const Substitutes& good, const Substitutes& now) const override {
    auto textNow = [&](const fs::path& f) {
      const auto n = now.find(f);
      return n == now.end() ? std::string() : n->second;
    };
    std::vector<std::pair<fs::path, std::string>> changed;  // (file, chunk id)
    for (const auto& [file, text] : good)
      if (now.count(file))
        for (const auto& chunk : changedChunks(text, textNow(file))) changed.emplace_back(file, chunk);
    // Each changed chunk alone from its last good text (the one that broke is found by trying), then
    // all of them: the whole last good text of every exercise file.
    std::vector<std::vector<std::pair<fs::path, std::string>>> tries;
    for (const auto& c : changed) tries.push_back({c});
    if (changed.size() > 1) tries.push_back(changed);
    std::vector<Fallback> out;
    for (const auto& swap : tries) {
      Fallback& f = out.emplace_back();
      for (const auto& [file, text] : good) {
        std::set<std::string> ids;
        for (const auto& [where, chunk] : swap)
          if (where == file) ids.insert(chunk);
        if (!ids.empty()) f.texts[file] = withChunksFrom(textNow(file), text, ids);
      }
      f.note = fallbackNote(swap, !swap[0].second.empty() && chunkIsStub(good.at(swap[0].first), swap[0].second));
    }
    return out;
  }

  // Each student's file alone (chunksThatDoNotCompile against the file as handed out). One answer
  // per file's text, kept for its latest text: every program that includes the file would be asked
  // the same.
  std::string blame(const std::vector<fs::path>& files, const BuildsFn& builds) const override {
    static std::map<fs::path, std::pair<std::string, std::set<std::string>>> known;  // file -> (text, answer)
    std::set<std::string> all;
    for (const auto& file : files) {
      if (!guardsLoops(file)) continue;
      std::string mine, stub;
      try {
        mine = readFile(file), stub = readFile(handedOutShaderFile(file.filename().string()));
      } catch (const std::exception&) {
        continue;  // (no stub to compare with: nothing to name)
      }
      if (const auto cached = known.find(file); cached == known.end() || cached->second.first != mine)
        known[file] = {mine, chunksThatDoNotCompile(mine, stub, [&](const std::string& t) {
                         return builds({{file, t}});
                       })};
      all.insert(known[file].second.begin(), known[file].second.end());
    }
    return all.empty() ? "" : culpritLine(all);
  }
};

}  // namespace

const SourceRules& exerciseSourceRules() {
  static const ExerciseSourceRules rules;
  return rules;
}

}  // namespace wb
