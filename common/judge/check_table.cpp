#include "common/judge/check_table.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/crash_report.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/attribution.hpp"
#include "common/judge/check_page.hpp"
#include "common/judge/diagnosis.hpp"
#include "common/judge/harness.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace wb::test {

std::vector<ManifestEntry> readManifest() {
  std::ifstream in(fs::path(wb::variant::kLabDir) / "exercises.json");
  std::vector<ManifestEntry> out;
  const auto manifest = nlohmann::json::parse(in);  // keep it alive while iterating
  for (const auto& e : manifest.at("exercises"))
    out.push_back({e.at("id").get<std::string>(), e.at("title").get<std::string>(), e.at("file").get<std::string>()});
  return out;
}

// "Ex01_3_WorldToShadow" -> "01.3"; a hunt\'s "Ex07_H1_..." -> "07.H1"
std::string exerciseOf(const std::string& testName) {
  static const std::regex re(R"(^Ex(\d\d)_(\d+|x|H\d+)_)");
  std::smatch m;
  return std::regex_search(testName, m, re) ? m[1].str() + "." + m[2].str() : "";
}

namespace {

// The grader's convention (tools/grading/outcomes.py): a test that draws a scene has Scene or Measured
// in its name, and no other test has (framework.Grading.TestsThatRunTheAppSaySceneOrMeasured keeps it so).
bool drawsScene(const std::string& test) {
  return test.find("Scene") != std::string::npos || test.find("Measured") != std::string::npos;
}

// A line of a diagnosis that names a known mistake (diagnosis.cpp).
bool namesKnownMistake(const std::string& line) { return line.rfind("looks like a known mistake", 0) == 0; }

// One test's value can fit several known mistakes ("one of these: - A - B"), and another test's only
// one of them ("A"): the second narrows the first, which is then left out, so that no hint is shown twice.
void narrowHints(std::vector<std::string>& details) {
  const std::string one = "looks like a known mistake: ", several = "looks like a known mistake, one of these:";
  std::vector<std::string> named;
  for (const auto& line : details)
    if (line.rfind(one, 0) == 0) named.push_back(line.substr(one.size()));
  details.erase(std::remove_if(details.begin(), details.end(),
                               [&](const std::string& line) {
                                 return line.rfind(several, 0) == 0 &&
                                        std::any_of(named.begin(), named.end(), [&](const std::string& n) {
                                          return line.find("- " + n) != std::string::npos;
                                        });
                               }),
                details.end());
}

// The table's last line: how many exercises pass, counted as the grader will count them. Those that
// pass their own tests while their scene waits on another count (the grader draws their scenes with
// the reference for the others); those blocked by another are not known before it passes.
std::string summaryLine(int done, size_t total, int waiting, const std::vector<std::string>& pending,
                        const std::vector<std::string>& blocked) {
  std::string line = std::to_string(done) + " of " + std::to_string(total) + " exercises pass their tests";
  if (waiting)
    line += " (" + std::to_string(waiting) + " by their own tests: the grader draws their scenes with the " +
            "reference for the others, and gives them their points if those pass)";
  auto joined = [](const std::vector<std::string>& ids) {
    std::string all;
    for (const auto& id : ids) all += (all.empty() ? "" : ", ") + id;
    return all;
  };
  if (!pending.empty())
    line += "; " + joined(pending) + (pending.size() == 1 ? " is" : " are") +
            " measured by scenes alone, which wait on other exercises: neither passed nor failed yet";
  if (!blocked.empty()) {
    const std::string ids = joined(blocked);
    const bool one = blocked.size() == 1;
    line += std::string("; ") + ids + (one ? " is" : " are") + " blocked by another exercise and cannot be " +
            "checked before that one passes (the grader checks " + (one ? "it" : "them") + " with the reference " +
            "for the others, so " + (one ? "it" : "they") + " may still earn " + (one ? "its" : "their") + " points)";
  }
  return line + ".";
}

// Where exercise `e` starts in the file being judged ("labs/02_bias/shaders/exercise.glsl:16"): the
// line of its marker, so that a WRONG verdict says where to look; "" when the file has none.
std::string exerciseLine(const ManifestEntry& e) {
  const char* submission = std::getenv("WB_SUBMISSION_DIR");
  const fs::path dir = submission && *submission ? fs::path(submission) : fs::path(wb::variant::kLabDir);
  std::ifstream in(dir / e.file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = wb::findMarker(text, e.id);
  if (at == std::string::npos) return "";
  const int line = 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
  return "labs/" + std::string(wb::variant::kLab) + "/" + e.file + ":" + std::to_string(line);
}

// Collects the first failure of each test and prints the per-exercise table at the end.
class CheckListener : public ::testing::EmptyTestEventListener {
 public:
  CheckListener(bool expectStubs, std::string signatures, int& exitCode)
      : exitCode(exitCode), expectStubs_(expectStubs), signatures_(std::move(signatures)) {}
  int& exitCode;
  std::string expectMistake;  // --expect-mistake ID: a mutant of exercise ID runs (ctest's mutant tests)
  std::string expectHint;     // --expect-hint TEXT: the hint it must get ("": none, and no other)

  void OnTestStart(const ::testing::TestInfo& info) override {
    current_ = exerciseOf(info.name());
    ran_.insert(current_);
    test_ = std::string(info.test_suite_name()) + "." + info.name();
    if (!drawsScene(test_)) withOwnTests_.insert(current_);
  }
  void OnTestPartResult(const ::testing::TestPartResult& r) override {
    if (!r.failed()) return;
    auto d = diagnose(test_, r.message());
    if (!signatures_.empty() && d.got && !signed_.count(test_)) {
      signed_.insert(test_);
      std::ofstream(signatures_, std::ios::app) << nlohmann::json{{"test", test_}, {"value", *d.got}}.dump() << "\n";
    }
    // Keep the most serious diagnosis of the exercise: ERROR > WRONG > NOT IMPLEMENTED > blocked. A test
    // that finds it WRONG, or still the stub, says more than a scene blocked by another exercise, and
    // is what the grader, drawing the others with the reference, finds too.
    auto rank = [](const Diagnosis& x) {
      if (x.headline.rfind("ERROR: blocked by", 0) == 0) return 1.0;
      return x.verdict == "ERROR" ? 3.0 : x.verdict == "NOT IMPLEMENTED" ? 1.5 : 2.0;
    };
    static const std::regex blockedRe(R"(^ERROR: blocked by ([0-9.xH, ]+):)"), kListSeparator(", ");
    std::smatch by;
    if (!drawsScene(test_)) {
      ownFailed_.insert(current_);
    } else if (std::regex_search(d.headline, by, blockedRe)) {
      std::string& list = blockers_[current_];
      for (std::sregex_token_iterator k(by[1].first, by[1].second, kListSeparator, -1), end; k != end; ++k)
        if ((", " + list + ",").find(", " + k->str() + ",") == std::string::npos)
          list += (list.empty() ? "" : ", ") + k->str();
    } else {
      unblocked_.insert(current_);
    }
    if (current_.empty()) {  // a test of the lab as a whole (its files, markers, manifest), not of one exercise
      if (others_.empty() || others_.back().first != test_) others_.emplace_back(test_, std::move(d));
      return;
    }
    // A known mistake recognised by any of the exercise's tests is named, and a picture any of them left
    // is shown, whichever test's failure is shown.
    for (const auto& line : d.details)
      if ((namesKnownMistake(line) || line.rfind("picture: ", 0) == 0) &&
          std::find(hints_[current_].begin(), hints_[current_].end(), line) == hints_[current_].end())
        hints_[current_].push_back(line);
    auto& slot = first_[current_];
    if (slot.verdict.empty() || rank(d) > rank(slot)) slot = std::move(d);
  }
  void OnTestProgramEnd(const ::testing::UnitTest&) override {
    const auto manifest = readManifest();
    attribute(manifest, {first_, ownFailed_, blockers_, unblocked_, withOwnTests_});
    for (auto& [id, lines] : hints_)
      for (const auto& line : lines)
        if (auto& d = first_[id];
            d.verdict == "WRONG" && std::find(d.details.begin(), d.details.end(), line) == d.details.end())
          d.details.push_back(line);
    for (auto& [id, d] : first_) narrowHints(d.details);
    if (tapeMode() == TapeMode::Replay)
      std::printf("\nLab %s: judged from what your build produced (%s)\n", wb::variant::kLab,
                  tapeDir().string().c_str());
    else
      std::printf("\nLab %s: %s build\n", wb::variant::kLab, wb::variant::kName);
    std::printf("  %-5s %-16s %s\n", "ID", "status", "exercise (then what was found)");
    int done = 0, waiting = 0;
    std::vector<std::string> pending;  // measured by their scenes alone, which wait on other exercises
    std::vector<PageRow> page;         // WB_CHECK_HTML: the same table as a page (check --html)
    nlohmann::json verdicts = nlohmann::json::object();  // WB_CHECK_JSON: for the app's live checks
    for (const auto& e : manifest) {
      const Diagnosis d = first_.count(e.id) ? first_[e.id] : Diagnosis{};
      const std::string status = d.verdict.empty()                ? "passes its tests"
                                 : d.verdict == "WAITS"           ? "passes own tests"
                                 : d.verdict == "WAITING"         ? "waiting"
                                 : d.verdict == "NOT IMPLEMENTED" ? "not implemented"
                                 : d.verdict == "ERROR"           ? "error"
                                                                  : "wrong";
      done += d.verdict.empty() || d.verdict == "WAITS";
      waiting += d.verdict == "WAITS";
      if (d.verdict == "WAITING") pending.push_back(e.id);
      if (expectStubs_ && status != "not implemented") exitCode = 1;
      // The whole title on the verdict's line; what was found below it, where it has room.
      std::printf("  %-5s %-16s %s\n", e.id.c_str(), status.c_str(), e.title.c_str());
      const std::string where = d.verdict == "WRONG" ? exerciseLine(e) : "";
      // What is printed under the row, line by line: the grader shows the same (WB_CHECK_JSON's "lines").
      std::vector<std::string> lines;
      if (!d.headline.empty()) lines.push_back(d.headline);
      for (const auto& line : d.details) lines.push_back("  " + line);
      if (!where.empty()) lines.push_back("  your code: " + where);
      for (const auto& line : lines) std::printf("        %s\n", line.c_str());
      if (ran_.count(e.id)) verdicts[e.id] = {{"status", status}, {"headline", d.headline}, {"lines", lines}};
      page.push_back({e.id, status, e.title, d.headline, d.details, where});
    }
    for (const auto& [test, d] : others_) {  // they fail the whole check: say so, and why
      std::printf("  also failing, for the lab as a whole: %s\n        %s\n", test.c_str(), d.headline.c_str());
      exitCode = 1;
    }
    if (const char* file = std::getenv("WB_CHECK_JSON"); file && *file) std::ofstream(file) << verdicts.dump();
    if (!expectMistake.empty()) {
      exitCode = judgeMutant(first_.count(expectMistake) ? first_[expectMistake] : Diagnosis{});
      return;
    }
    if (!expectStubs_ && done != int(manifest.size())) exitCode = 1;
    std::vector<std::string> blocked;  // (their points are not known before their blockers pass)
    for (const auto& e : manifest)
      if (first_.count(e.id) && first_[e.id].headline.rfind("ERROR: blocked by", 0) == 0) blocked.push_back(e.id);
    const std::string summary = summaryLine(done, manifest.size(), waiting, pending, blocked);
    std::printf("  %s%s\n", summary.c_str(),
                expectStubs_ ? (exitCode ? " Some stubs are not reported as NOT IMPLEMENTED."
                                         : " Every stub reports NOT IMPLEMENTED.")
                             : "");
    if (const char* file = std::getenv("WB_CHECK_HTML"); file && *file) {
      if (!writeCheckPage(file, "Lab " + std::string(wb::variant::kLab) + ": check", page, summary))
        std::printf("  (the page %s could not be written)\n", file);
    }
  }

 private:
  // A mutant of exercise expectMistake must be caught as WRONG, with its own hint or none, never another's:
  // every hint shown names it (alone, or among the "one of these" that give the same value).
  int judgeMutant(const Diagnosis& d) const {
    std::vector<std::string> hints;
    for (const auto& line : d.details)
      if (namesKnownMistake(line)) hints.push_back(line);
    const bool caught = d.verdict == "WRONG";
    const auto other = std::find_if(hints.begin(), hints.end(),
                                    [&](const std::string& h) { return h.find(expectHint) == std::string::npos; });
    const bool hintRight = expectHint.empty() ? hints.empty() : !hints.empty() && other == hints.end();
    const std::string verdict =
        caught ? "caught as WRONG" : "NOT CAUGHT (" + (d.verdict.empty() ? "passes" : d.verdict) + ")";
    const std::string hint = hintRight       ? (hints.empty() ? "none (none expected)" : "right")
                             : hints.empty() ? "MISSING: " + expectHint
                                             : "WRONG: " + (other != hints.end() ? *other : hints[0]);
    // Attribution, where other exercises' tests ran too (the whole lab, tools/authoring/mutant_matrix.py
    // --whole-lab): no other exercise may be marked wrong; "blocked by" (an ERROR) is allowed.
    std::string blamed;
    for (const auto& [id, diagnosis] : first_)
      if (id != expectMistake && diagnosis.verdict == "WRONG") blamed += (blamed.empty() ? "" : ", ") + id;
    std::printf("mutant of %s: %s; hint %s; %s\n", expectMistake.c_str(), verdict.c_str(), hint.c_str(),
                blamed.empty() ? "no other exercise marked wrong" : ("ALSO MARKED WRONG: " + blamed).c_str());
    return caught && hintRight && blamed.empty() ? 0 : 1;
  }

  bool expectStubs_;
  std::string signatures_;  // --signatures F: each failing test's value, for tools/authoring/make_hints.py
  std::set<std::string> signed_;
  std::set<std::string> ran_;  // the exercises that had a test run
  std::string current_;        // the exercise of the running test
  std::string test_;           // and the test ("Suite.Name")
  std::map<std::string, Diagnosis> first_;
  std::set<std::string> ownFailed_;              // the exercises that fail a test that draws no scene
  std::set<std::string> withOwnTests_;           // the exercises that ran a test that draws no scene
  std::map<std::string, std::string> blockers_;  // what blocks each exercise's scene tests ("07.4", "09.2, 09.3")
  std::set<std::string> unblocked_;              // the exercises with a scene test that fails on its own
  std::map<std::string, std::vector<std::string>> hints_;  // the known mistakes and pictures of each exercise's tests
  std::vector<std::pair<std::string, Diagnosis>> others_;  // failing tests of no one exercise
};

}  // namespace

::testing::TestEventListener* makeCheckListener(bool expectStubs, const std::string& signatures,
                                                const std::string& expectMistake, const std::string& expectHint,
                                                int& exitCode) {
  auto* listener = new CheckListener(expectStubs, signatures, exitCode);
  listener->expectMistake = expectMistake, listener->expectHint = expectHint;
  return listener;
}

}  // namespace wb::test
