#include "common/judge/attribution.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/tape.hpp"
#include "common/platform/shader.hpp"

#include <algorithm>
#include <regex>

namespace wb::test {
namespace {

// True when exercise `id` is itself blocked by another (then that one is named, not this one).
bool blockedItself(const Findings& f, const std::string& id) {
  const auto d = f.first.find(id);
  return d != f.first.end() && d->second.headline.rfind("ERROR: blocked by", 0) == 0;
}

// True when exercise `id` is still the stub: its pattern, where a scene draws it, makes that scene's
// own test say "blocked by" it; a scene that is wrong without the pattern is not its doing.
bool stillStub(const Findings& f, const std::string& id) {
  const auto d = f.first.find(id);
  return d != f.first.end() && d->second.verdict == "NOT IMPLEMENTED";
}

// Without the solution's shaders (the student edition) a scene draws every GLSL exercise with the
// student's own, so when only an exercise's scene tests fail while a GLSL exercise fails its own
// tests, the mistake may be that one's: the exercise is blocked by it, never wrong. (The grader
// draws the other exercises with the reference, as the instructor edition's check does.)
void blockWhereNoReference(const std::vector<ManifestEntry>& manifest, Findings& f) {
  for (auto& [id, d] : f.first) {
    // (a scene that is wrong, or that timed out or crashed: a GLSL loop elsewhere slows every frame)
    const bool sceneFailed =
        d.verdict == "WRONG" || (d.verdict == "ERROR" && d.headline.rfind("ERROR: blocked", 0) != 0);
    if (!sceneFailed || f.ownFailed.count(id)) continue;
    std::string by;
    for (const auto& e : manifest)
      if (e.id != id && e.file.rfind("shaders/", 0) == 0 && f.ownFailed.count(e.id) && !blockedItself(f, e.id) &&
          !stillStub(f, e.id))
        by += (by.empty() ? "" : ", ") + e.id;
    if (by.empty()) continue;
    f.blockers[id] = by, f.unblocked.erase(id);  // (its scene failures are put down to `by`)
    d.details.insert(d.details.begin(), d.headline);
    d.verdict = "ERROR";
    d.headline = "ERROR: blocked by " + by + ": only " + id + "'s scene tests fail, and " + by +
                 " fails its own tests. Here every scene draws your GLSL exercises as they are (the grader "
                 "draws the others with the reference): fix " +
                 by + " first, then check again.";
  }
}

// In the student edition, an exercise that passes its own tests and whose scene tests fail only
// because another exercise blocks them (drawn with the student's own code for the others) is not an
// error: the grader draws its scenes with the reference for the others, and gives it its points if
// they match. It "passes its own tests", counts in the summary, and says what its scene waits on.
void waitWhereNoReference(Findings& f) {
  for (auto& [id, d] : f.first) {
    const auto by = f.blockers.find(id);
    if (d.verdict != "ERROR" || f.ownFailed.count(id) || f.unblocked.count(id) || by == f.blockers.end()) continue;
    d.details.clear();  // (its scene's failures are the blocker's)
    const bool several = by->second.find(',') != std::string::npos, own = f.withOwnTests.count(id) > 0;
    d.verdict = own ? "WAITS" : "WAITING";
    d.headline = std::string(own ? "passes its own tests; its scene is checked"
                                 : "waiting on " + by->second + ": its scenes are measured") +
                 " once " + by->second + (several ? " pass" : " passes") +
                 " (here every scene draws your other exercises as they are; the grader draws them with the "
                 "reference)";
  }
}

// An exercise whose run was stopped (its runner, or a judge's test that ./workbook check stopped and
// then judged the rest without: stopped.txt says which and why) is an error, whatever its tests
// that did run say.
void markStops(const std::vector<ManifestEntry>& manifest, Findings& f) {
  for (const auto& e : manifest) {
    std::string tag = "Ex" + e.id;
    std::replace(tag.begin(), tag.end(), '.', '_');
    const auto stop = stoppedRuns().find(tag);
    if (stop == stoppedRuns().end()) continue;
    auto& d = f.first[e.id];
    if (d.verdict == "ERROR") continue;
    d.details.clear();
    d.verdict = "ERROR", d.headline = "ERROR: " + stop->second;
  }
}

// Without the reference, a GLSL exercise's kernel runs the student's own code for the exercises it
// calls: when one of those fails its own tests, this one's failure (wrong, or a time-out: the other's
// endless loop) may be that one's. It is blocked by it (no hint: a hint is proved with the
// reference's helpers), unless it is still the stub.
void blockWhereUpstreamFails(const std::vector<ManifestEntry>& manifest, Findings& f) {
  for (const auto& e : manifest) {
    auto d = f.first.find(e.id);
    if (e.file.rfind("shaders/", 0) != 0 || d == f.first.end() || !f.ownFailed.count(e.id)) continue;
    // (an error of its own, such as a time-out, may be the helper's loop too; a compile error is its own)
    const std::string& headline = d->second.headline;
    const bool ownError = headline.rfind("ERROR: blocked", 0) == 0 || headline.find("compile") != std::string::npos;
    if (d->second.verdict != "WRONG" && d->second.verdict != "NOT IMPLEMENTED" &&
        (d->second.verdict != "ERROR" || ownError))
      continue;
    std::string text;
    try {
      text = readFile(submittedShaderFile(e.file.substr(8)));
    } catch (const std::exception&) {
      continue;
    }
    if (chunkIsStub(text, e.id)) continue;
    std::string by;
    for (const auto& other : glslExercisesCalled(text, e.id, manifest))
      if (f.ownFailed.count(other)) by += (by.empty() ? "" : ", ") + other;
    if (by.empty()) continue;
    d->second.details.clear();
    d->second.verdict = "ERROR";
    d->second.headline = "ERROR: blocked by " + by + ": " + e.id + " calls " + by +
                         ", which fails its own tests, and here that is your own code (the grader tests " + e.id +
                         " with the reference for the others): fix " + by + " first, then check again.";
  }
}

}  // namespace

std::vector<std::string> glslExercisesCalled(const std::string& text, const std::string& id,
                                             const std::vector<ManifestEntry>& manifest) {
  static const std::regex definition(R"(\b([A-Za-z_]\w*)\s*\([^;{)]*\)\s*\{)");
  static const std::set<std::string> keywords = {"if", "for", "while", "switch", "return"};
  if (findMarker(text, id) == std::string::npos) return {};
  const auto [mine0, mine1] = chunkRange(text, id);
  const std::string mine = text.substr(mine0, mine1 - mine0);
  std::vector<std::string> out;
  for (const auto& e : manifest) {
    if (e.id == id || findMarker(text, e.id) == std::string::npos) continue;
    const auto [b, end] = chunkRange(text, e.id);
    const std::string theirs = text.substr(b, end - b);
    for (std::sregex_iterator m(theirs.begin(), theirs.end(), definition), last; m != last; ++m) {
      const std::string name = (*m)[1].str();
      if (keywords.count(name) || !std::regex_search(mine, std::regex("\\b" + name + "\\s*\\("))) continue;
      out.push_back(e.id);
      break;
    }
  }
  return out;
}

void attribute(const std::vector<ManifestEntry>& manifest, Findings f) {
  if (!*variant::kSolutionDir) {  // (with the reference, every exercise is judged on its own already)
    blockWhereUpstreamFails(manifest, f);
    blockWhereNoReference(manifest, f);
    waitWhereNoReference(f);
  }
  markStops(manifest, f);
}

}  // namespace wb::test
