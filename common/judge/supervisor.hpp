/// @file supervisor.hpp
/// `check`'s supervisor, the same on every OS (wb_check): the student's build records each
/// exercise alone (the runner), with a time limit, a cap on its output and every process it starts
/// stopped with it; then the judge decides from that record, each of its tests bounded too. Whatever
/// a runner or a judge's test could not finish is written to stopped.txt, which the judge reads as
/// that exercise's error (docs/grading-trust.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace wb::check {

/// The bounds of one check (the environment's WB_CHECK_* variables, or their defaults).
struct Limits {
  int exerciseSeconds = 8;    ///< one exercise's runner (WB_CHECK_TIMEOUT)
  int judgeTestSeconds = 30;  ///< one test of the judge (WB_CHECK_JUDGE_TIMEOUT)
  int logMegabytes = 256;     ///< what one run may write (WB_CHECK_LOG_MB)
  /// Run by the grader, inside its sandbox (WB_CHECK_IN_SANDBOX=1): a runner stays in this process's
  /// session, which the sandbox ends as a whole (its weakest mode stops every process of the run's user
  /// outside a running session), and the limits are the grader's, not the student's to set.
  bool inSandbox = false;
  static Limits fromEnvironment();  ///< the defaults, with the environment's WB_CHECK_* over them
};

/// Runs exercise `id`'s runner (`tests` --runner) into `tape`/ExNN_k, its output in `tape`/ExNN_k.log,
/// and adds its record to `tape`/all; a runner stopped or crashed is written to `tape`/all/stopped.txt,
/// in the words `check` and the grader both show. `recordShaders`: the shaders its lab runs draw with
/// (not the student's; empty: the build's own). `testArgs`: what selects its tests (empty: the
/// exercise's, --gtest_filter=*.ExNN_k_*; the grader's: its filter, or the held-out --requests).
void runExerciseRunner(const std::filesystem::path& tests, const std::string& id, const std::filesystem::path& tape,
                       const Limits& limits, const std::string& recordShaders,
                       const std::vector<std::string>& testArgs = {});

/// Runs the judge (`judge` --judge `tape`/all, then `judgeArgs`, or --check when there are none) on the
/// submission in `submission`; a test that makes no progress for the judge's limit is stopped,
/// written down for its exercise in `tape`/all/stopped.txt, and the judge runs again without it (its
/// --gtest_filter, if `judgeArgs` has one, narrowed). Its exit code (124 when it could not finish).
int runJudge(const std::string& nn, const std::filesystem::path& judge, const std::filesystem::path& tape,
             const std::filesystem::path& submission, const Limits& limits,
             const std::vector<std::string>& judgeArgs = {});

/// Set by a signal handler (Ctrl-C): whatever runs is stopped, and the check ends.
void requestStop();

}  // namespace wb::check
