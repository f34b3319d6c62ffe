/// @file reference_calls.hpp
/// What the reference's C++ exercises returned in each scene run of the tests, kept beside the
/// golden data (./workbook golden writes it). A direct run (ctest, ./workbook check) then draws a
/// scene with one exercise's own code and every other C++ exercise's reference result
/// (--replay-exercises): a mistake in 09.1 is reported in 09.1 alone, not in every scene that its
/// adjacency feeds, and a GLSL exercise can be tried before the C++ ones are done. The grader does
/// not need it: its judge replays the student's results in the solution's app (harness.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace wb::test {

/// The file of the reference's calls for a lab run with `args`: tests/golden/LAB/calls/KEY.json,
/// or tests/hidden/LAB/calls/KEY.json for a held-out test or scene (never handed out). KEY names
/// the arguments that decide what the exercises are asked, not the files the run writes.
std::filesystem::path referenceCallsFile(const std::vector<std::string>& args);

/// Writes to `out` the calls in `reference` of every exercise but `id`, for --replay-exercises.
/// False, with nothing written, when `reference` is missing or unreadable or holds no other call.
bool referenceCallsOfOthers(const std::filesystem::path& reference, const std::string& id,
                            const std::filesystem::path& out);

/// After a golden run recorded `file`: removes it when it holds no call (a lab whose exercises are
/// all GLSL), and says whether it is kept.
bool keepReferenceCalls(const std::filesystem::path& file);

}  // namespace wb::test
