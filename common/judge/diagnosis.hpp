/// @file diagnosis.hpp
/// What `./workbook check` says about a failed test, in words a student can act on: the verdict,
/// the compiler's own file:line for a compile error, the failing case's got and want with the
/// tolerance, the diff image, and a hint when the wrong value is one a known mistake gives (the
/// mutants of tests/mutants, recorded as values in tests/hints/NN_name.json by tools/authoring/make_hints.py).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace wb::test {

/// One failed test, diagnosed.
struct Diagnosis {
  std::string verdict;               ///< "NOT IMPLEMENTED", "WRONG" or "ERROR"
  std::string headline;              ///< our message's first line, from the keyword on
  std::vector<std::string> details;  ///< lines to show under it: compiler lines, got/want, hint, diff
  std::optional<double> got;         ///< the value the failing check saw, when it says one
};

/// Diagnoses gtest's failure message `message` of test `test` ("Suite.Name"). Paths under the
/// repository shrink to repository-relative ones.
Diagnosis diagnose(const std::string& test, const std::string& message);

/// The hint of a known mistake whose recorded value for `test` is `got` (relative difference below
/// 1e-3, or within `slack`), from tests/hints/LAB.json; "" when none matches; "one of these:" and a
/// line per hint when several mistakes give that value. A scene's share of differing pixels gets the
/// slack its own test allows between two renders of the same code ("allowed 0.500%"): the mistake's
/// picture differs that much between one GL implementation and another, as a right one's does.
std::string knownMistake(const std::string& test, double got, double slack = 0);

}  // namespace wb::test
