// main() of every lab's test binary. Besides plain GoogleTest it offers:
//   --check          print one line per exercise: passes / NOT IMPLEMENTED / WRONG / ERROR, with a
//                    one-line diagnosis (what `./workbook check NN` shows)
//   --expect-stubs   like --check, but succeed only if every exercise is NOT IMPLEMENTED (CI runs
//                    this on the student build to prove the stubs are stubs)
//   --update-golden  regenerate tests/golden/<lab>/ from this build (solution builds only)
//   --runner DIR     record every value the exercises produce on a tape in DIR; decide nothing
//   --requests F     with --runner: record only the lab runs F asks for (held-out tests; see
//                    recordRequestedRuns in harness.hpp)
//   --signatures F   like --check, and write each failing test's value to F (JSON lines), from
//                    which tools/authoring/make_hints.py records the values the mutants' mistakes give
//   --as-student-edition  run as the student edition does, without the solution's app and shaders
//                    (tests of check's verdicts there: tests/framework/CMakeLists.txt)
//   --judge DIR      replay the tape in DIR instead of running any exercise, and decide
//                    (see tape.hpp: the grader runs the student's build as the runner and the
//                    solution's as the judge; `./workbook check` runs both the same way)
#include "common/base/variant.hpp"
#include "common/exercise/crash_report.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/judge/check_table.hpp"
#include "common/judge/harness.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace wb::test {
extern bool g_updateGolden;
}

// The manifest (labs/NN/exercises.json) is the one list of exercises: every exercise has tests, every
// test belongs to an exercise, and every exercise has its "// EXERCISE NN.k" marker in its file.
TEST(Manifest, EveryExerciseHasTestsAndEveryTestAnExercise) {
  std::set<std::string> ids, tested;
  for (const auto& e : wb::test::readManifest()) ids.insert(e.id);
  const auto* unit = ::testing::UnitTest::GetInstance();
  for (int s = 0; s < unit->total_test_suite_count(); ++s) {
    const auto* suite = unit->GetTestSuite(s);
    if (std::string(suite->name()) == "Manifest") continue;
    for (int t = 0; t < suite->total_test_count(); ++t) {
      const std::string name = suite->GetTestInfo(t)->name(), id = wb::test::exerciseOf(name);
      EXPECT_TRUE(ids.count(id)) << "WRONG: test " << suite->name() << "." << name
                                 << " names no exercise of the manifest";
      tested.insert(id);
    }
  }
  for (const auto& id : ids) EXPECT_TRUE(tested.count(id)) << "WRONG: exercise " << id << " has no tests";
}

TEST(Manifest, EveryExerciseHasItsMarker) {
  for (const auto& e : wb::test::readManifest()) {
    std::ifstream in(fs::path(wb::variant::kLabDir) / e.file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(wb::findMarker(text, e.id), std::string::npos)
        << "WRONG: labs/" << wb::variant::kLab << "/" << e.file << " has no '// EXERCISE " << e.id
        << "' line: keep the comment line above each exercise (the grader finds your exercises by it)";
  }
}

// With WB_PROGRESS_FILE set, the name of the test that runs now is in that file, so that whoever
// stops a run that took too long can say where it was (./workbook check's judge).
class ProgressListener : public ::testing::EmptyTestEventListener {
 public:
  explicit ProgressListener(std::string file) : file_(std::move(file)) {}
  void OnTestStart(const ::testing::TestInfo& info) override {
    std::ofstream(file_, std::ios::trunc) << info.test_suite_name() << "." << info.name() << "\n";
  }

 private:
  std::string file_;
};

// A runner's log (--runner): which test ran, as gtest names it ("[ RUN      ]", which the grader reads to
// say where a crash was), and nothing like a verdict. Its failures are not the student's: a runner
// runs no GLSL (a kernel's results are zeros) and draws no scene; the judge decides.
class RunnerPrinter : public ::testing::EmptyTestEventListener {
 public:
  void OnTestProgramStart(const ::testing::UnitTest&) override {
    std::printf(
        "The runner's log: it runs your C++ exercises and records what they return, for the judge. It runs "
        "no GLSL and decides nothing: the verdicts are check's table.\n");
  }
  void OnTestStart(const ::testing::TestInfo& info) override {
    std::printf("[ RUN      ] %s.%s\n", info.test_suite_name(), info.name());
    std::fflush(stdout);
  }
  void OnTestEnd(const ::testing::TestInfo& info) override {
    std::printf("[ RECORDED ] %s.%s\n", info.test_suite_name(), info.name());
  }
};

namespace {

// The modes and options of the header above.
struct Options {
  bool check = false, expectStubs = false;
  std::string requests, signatures, expectMistake, expectHint;
};

// Reads argv (after GoogleTest took its own); false, with the message printed, for an unknown option.
bool parseOptions(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const bool runner = !std::strcmp(argv[i], "--runner"), judge = !std::strcmp(argv[i], "--judge");
    if ((runner || judge) && i + 1 < argc)
      wb::test::openTape(runner ? wb::test::TapeMode::Record : wb::test::TapeMode::Replay, argv[++i]);
    else if (!std::strcmp(argv[i], "--requests") && i + 1 < argc)
      o.requests = argv[++i];
    else if (!std::strcmp(argv[i], "--signatures") && i + 1 < argc)
      o.check = true, o.signatures = argv[++i];
    else if (!std::strcmp(argv[i], "--check"))
      o.check = true;
    else if (!std::strcmp(argv[i], "--expect-mistake") && i + 1 < argc)
      o.check = true, o.expectMistake = argv[++i];
    else if (!std::strcmp(argv[i], "--expect-hint") && i + 1 < argc)
      o.expectHint = argv[++i];
    else if (!std::strcmp(argv[i], "--expect-stubs"))
      o.check = o.expectStubs = true;
    else if (!std::strcmp(argv[i], "--update-golden"))
      wb::test::g_updateGolden = true;
    else if (!std::strcmp(argv[i], "--as-student-edition"))
      wb::variant::kSolutionDir = wb::variant::kSolutionExe = "";
    else {
      std::fprintf(stderr,
                   "%s: unknown option '%s' (accepted: --check, --expect-stubs, --expect-mistake ID, --expect-hint "
                   "TEXT, --update-golden, --as-student-edition, --runner DIR, "
                   "--requests F, --judge DIR, --signatures F, --gtest_*)\n",
                   argv[0], argv[i]);
      return false;
    }
  }
  return true;
}

// --runner: the tests run and record; the log says which ran, and nothing is claimed.
int runAsRunner(::testing::TestEventListeners& listeners) {
  delete listeners.Release(listeners.default_result_printer());
  listeners.Append(new RunnerPrinter);
  [[maybe_unused]] const int failed = RUN_ALL_TESTS();
  return 0;  // (a runner claims nothing: its failures are no verdict, nor is its exit code)
}

// --check and its kinds: the per-exercise table (check_table.hpp) instead of gtest's printer.
int runWithTable(::testing::TestEventListeners& listeners, const Options& o) {
  delete listeners.Release(listeners.default_result_printer());
  int exitCode = 0;
  listeners.Append(wb::test::makeCheckListener(o.expectStubs, o.signatures, o.expectMistake, o.expectHint, exitCode));
  const int gtest = RUN_ALL_TESTS();
  if (!o.expectMistake.empty()) return exitCode;  // (the mutant's tests fail: that is the point)
  return exitCode ? exitCode : (o.expectStubs ? 0 : gtest);
}

}  // namespace

int main(int argc, char** argv) {
  wb::installCrashReport();  // a crash in an exercise names its file:line
  ::testing::InitGoogleTest(&argc, argv);
  Options o;
  if (!parseOptions(argc, argv, o)) return 2;
  if (wb::test::g_updateGolden && std::string(wb::variant::kName) != "solution") {
    std::fprintf(stderr, "%s: golden data is generated from the solution build only\n", argv[0]);
    return 2;
  }
  if (!o.requests.empty()) {
    if (wb::test::tapeMode() != wb::test::TapeMode::Record) {
      std::fprintf(stderr, "%s: --requests needs --runner DIR\n", argv[0]);
      return 2;
    }
    return wb::test::recordRequestedRuns(o.requests);
  }
  auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
  if (const char* progress = std::getenv("WB_PROGRESS_FILE"); progress && *progress)
    listeners.Append(new ProgressListener(progress));
  if (wb::test::tapeMode() == wb::test::TapeMode::Record && !o.check) return runAsRunner(listeners);
  return o.check ? runWithTable(listeners, o) : RUN_ALL_TESTS();
}
