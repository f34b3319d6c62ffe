// wb_check: `check` on every OS (supervisor.hpp). ./workbook check NN builds, then runs it; on
// Windows, `cmake --build build --target check_NN` does both.
//   wb_check NN [--root DIR] [--tests EXE] [--judge EXE] [--tape DIR] [--submission DIR] [--html FILE]
//   wb_check --runner TESTS ID TAPE [ARG...] one exercise's runner (the check's first half, and the
//                                            grader's, in its sandbox: ARGs select its tests)
//   wb_check --judge NN JUDGE TAPE SUBMISSION [ARG...]
//                                            the judge (its second half; the grader's ARGs: its
//                                            filter and report, in place of --check)
//   wb_check --fill-missing FILE STUB NAME STUB_NAME check|grader
//                                            an earlier edition's file: the exercises it lacks, from
//                                            the stub (fillMissingChunks), one line each
#include "common/exercise/exercise_chunks.hpp"
#include "common/judge/supervisor.hpp"

#include "common/platform/process.hpp"

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>

namespace fs = std::filesystem;
using wb::check::Limits;

namespace {

constexpr const char* kUsage =
    "usage: wb_check NN [--root DIR] [--tests EXE] [--judge EXE] [--tape DIR] [--submission DIR] [--html FILE]\n"
    "       wb_check --runner TESTS ID TAPE [TEST_ARG...]\n"
    "       wb_check --judge NN JUDGE TAPE SUBMISSION [JUDGE_ARG...]\n"
    "       wb_check --fill-missing FILE STUB NAME STUB_NAME check|grader\n";

int usage(const std::string& why) {
  std::fprintf(stderr, "wb_check: %s\n%s", why.c_str(), kUsage);
  return 2;
}

std::string exe(const std::string& name) {
#if defined(_WIN32)
  return name + ".exe";
#else
  return name;
#endif
}

// labs/NN_name under `root`, or "".
std::string labName(const fs::path& root, const std::string& nn) {
  std::error_code ec;
  for (const auto& d : fs::directory_iterator(root / "labs", ec))
    if (d.is_directory() && d.path().filename().string().rfind(nn + "_", 0) == 0) return d.path().filename().string();
  return "";
}

std::vector<std::string> exerciseIds(const fs::path& manifest) {
  std::ifstream in(manifest);
  const auto json = nlohmann::json::parse(in, nullptr, false);
  std::vector<std::string> ids;
  if (json.is_discarded() || !json.contains("exercises")) return ids;
  for (const auto& e : json["exercises"])
    if (e.contains("id") && e["id"].is_string()) ids.push_back(e["id"].get<std::string>());
  return ids;
}

// The whole check of lab `nn`: every exercise's runner, then the judge.
int checkLab(const std::string& nn, std::map<std::string, std::string> opt) {
  const fs::path root = opt.count("--root") ? opt["--root"] : ".";
  const std::string lab = labName(root, nn);
  if (lab.empty()) return usage("there is no lab " + nn + " in " + (root / "labs").string());
  const std::vector<std::string> ids = exerciseIds(root / "labs" / lab / "exercises.json");
  if (ids.empty()) return usage("labs/" + lab + "/exercises.json lists no exercise");
  const fs::path tests = opt.count("--tests") ? fs::path(opt["--tests"]) : root / "build" / exe("lab" + nn + "_tests");
  fs::path judge =
      opt.count("--judge") ? fs::path(opt["--judge"]) : root / "build" / exe("lab" + nn + "_solution_tests");
  if (!fs::exists(judge)) judge = tests;  // (the student edition: your own build judges)
  const fs::path tape = opt.count("--tape") ? fs::path(opt["--tape"]) : root / "build" / "check" / ("lab" + nn);
  if (!fs::exists(tests)) return usage(tests.string() + " is not built");
  std::error_code ec;
  fs::remove_all(tape, ec);
  fs::create_directories(tape / "all");
  // The runs that record the C++ exercises draw with other shaders than the student's, as the
  // grader's do, so a GLSL mistake never stops them: the solution's, or the stubs as handed out.
  std::string shaders;
  for (const fs::path& d : {root / "solutions" / lab / "shaders", root / "tests" / "stubs" / lab / "shaders"})
    if (shaders.empty() && fs::is_directory(d)) shaders = fs::absolute(d).string();
  const Limits limits = Limits::fromEnvironment();
  for (const std::string& id : ids) wb::check::runExerciseRunner(tests, id, tape, limits, shaders);
  if (opt.count("--html")) {
    fs::remove(opt["--html"], ec);
    wb::setEnv("WB_CHECK_HTML", opt["--html"].c_str());
  }
  // (--submission: another lab folder than the checkout's, such as a check case's, tests/check_cases)
  const fs::path submission = opt.count("--submission") ? fs::path(opt["--submission"]) : root / "labs" / lab;
  const int rc = wb::check::runJudge(nn, judge, tape, submission, limits);
  if (opt.count("--html") && fs::exists(opt["--html"]))
    std::printf("workbook: the check as one page, pictures included: %s\n", opt["--html"].c_str());
  return rc;
}

// FILE with the exercises it lacks filled in from STUB, written back when any were; one line each on
// stdout, naming the files as NAME and STUB_NAME (what the student sees).
int fillMissing(const std::vector<std::string>& a) {
  if (a.size() != 6 || (a[5] != "check" && a[5] != "grader"))
    return usage("--fill-missing takes FILE STUB NAME STUB_NAME check|grader");
  std::string text[2];
  for (int k : {0, 1}) {
    std::ifstream in(a[size_t(k) + 1], std::ios::binary);
    if (!in) return usage("--fill-missing: cannot read " + a[size_t(k) + 1]);
    text[k].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const wb::FilledChunks filled = wb::fillMissingChunks(text[0], text[1]);
  if (filled.added.empty()) return 0;
  std::ofstream(a[1], std::ios::binary | std::ios::trunc) << filled.text;
  for (const std::string& id : filled.added)
    std::printf("%s\n", wb::filledChunkLine(a[3], id, a[4], a[5] == "check").c_str());
  return 0;
}

void onSignal(int) { wb::check::requestStop(); }

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  std::vector<std::string> a(argv + 1, argv + argc);
  if (a.empty()) return usage("which lab?");
  const Limits limits = Limits::fromEnvironment();
  if (a[0] == "--runner") {
    if (a.size() < 4) return usage("--runner takes TESTS ID TAPE [TEST_ARG...]");
    const char* shaders = std::getenv("WB_RECORD_SHADERS");  // (the grader's: the stubs as handed out)
    wb::check::runExerciseRunner(a[1], a[2], a[3], limits, shaders ? shaders : "", {a.begin() + 4, a.end()});
    return 0;
  }
  if (a[0] == "--fill-missing") return fillMissing(a);
  if (a[0] == "--judge") {
    if (a.size() < 5) return usage("--judge takes NN JUDGE TAPE SUBMISSION [JUDGE_ARG...]");
    return wb::check::runJudge(a[1], a[2], a[3], a[4], limits, {a.begin() + 5, a.end()});
  }
  if (a[0].size() != 2 || a[0].find_first_not_of("0123456789") != std::string::npos)
    return usage("expected a two-digit lab number such as 01, got '" + a[0] + "'");
  std::map<std::string, std::string> opt;
  for (size_t k = 1; k < a.size(); k += 2) {
    const bool known = a[k] == "--root" || a[k] == "--tests" || a[k] == "--judge" || a[k] == "--tape" ||
                       a[k] == "--html" || a[k] == "--submission";
    if (!known) return usage("unknown option '" + a[k] + "'");
    if (k + 1 >= a.size()) return usage(a[k] + " needs a value");
    opt[a[k]] = a[k + 1];
  }
  return checkLab(a[0], opt);
}
