/// @file isolation.hpp
/// Inside the harness: how a test runs the lab with one exercise isolated (the others drawn with the
/// reference, or with their recorded inputs), through the tape in a runner and from it in a judge.
/// harness.hpp's scene and metric checks are built on these.
#pragma once
#include "common/exercise/run_record.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wb::test {

/// The seed of grading-time variations (WB_VARY_SEED, set by the grader), or -1.
long long varySeed();

/// True when the grader replays exercise `id`'s recorded results in this test's runs (WB_REPLAY_USES,
/// under variations): `id` failed its own tests, so a property measured on the lab's whole pipeline
/// is partly its doing, and a test of another exercise that measures one should skip (its scene tests,
/// drawn beside the reference on the same inputs, still judge it).
bool replaysFailedUse(const std::string& id);

/// Variables set for a lab run, over the test's own environment.
using Env = std::vector<std::pair<std::string, std::string>>;

/// Runs `exe --headless args` (plus the variation, if any) from `out` with a time limit, its output
/// in `log`: the exit status (124 past the limit, 128 + a crash's signal) and the command.
std::pair<int, std::string> runApp(const std::filesystem::path& out, const Env& env, const std::string& exe,
                                   const std::vector<std::string>& args, const std::filesystem::path& log);

/// The app a judge trusts: the solution's (this build's in the student edition, which has none).
std::string trustedExe();

/// Draws exercise `id` with `args` and a record, and reads it (into `result`, if given). Fails with
/// ERROR / NOT IMPLEMENTED when it did not run, and always in a runner (which decides nothing).
::testing::AssertionResult runIsolated(const std::string& id, const std::filesystem::path& out,
                                       const std::vector<std::string>& args, std::string& logText,
                                       RunResult* result = nullptr);

}  // namespace wb::test
