/// @file check_table.hpp
/// The per-exercise table of `--check` (what `./workbook check NN` shows): the first failure of each
/// test, one line per exercise (passes / NOT IMPLEMENTED / WRONG / ERROR / waiting / blocked), the
/// hints a mutant proved, and the summary the grader's count agrees with.
#pragma once
#include "common/judge/attribution.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace wb::test {

/// The lab's exercises, from labs/NN/exercises.json: the one list of them.
std::vector<ManifestEntry> readManifest();

/// "Ex01_3_WorldToShadow" -> "01.3"; a hunt's "Ex07_H1_..." -> "07.H1"; "" for another name.
std::string exerciseOf(const std::string& testName);

/// The listener that prints the table at the end of the run: `expectStubs` (--expect-stubs) succeeds
/// only when every exercise is NOT IMPLEMENTED; `signatures` (--signatures F) writes each failing test's
/// value to F; `expectMistake` and `expectHint` (--expect-mistake ID, --expect-hint TEXT) are a mutant's
/// test. `exitCode` receives the run's exit code for main().
::testing::TestEventListener* makeCheckListener(bool expectStubs, const std::string& signatures,
                                                const std::string& expectMistake, const std::string& expectHint,
                                                int& exitCode);

}  // namespace wb::test
