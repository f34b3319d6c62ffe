/// @file live_checks.hpp
/// The lab's fast checks, run in the background while a window is open: the tests of the lab's own
/// test binary that draw no scene (each exercise's layer-1 cases), started when the window opens
/// and again whenever an exercise file changes. The info panel shows their verdict, so "implemented"
/// never reads as "correct": an exercise is "passes its checks", "wrong" with the first failing
/// case, or "not implemented", and "implemented, not checked" while they run.
#pragma once
#include <atomic>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace wb {

/// One exercise's verdict from the checks.
struct CheckVerdict {
  std::string status;    ///< "passes its tests", "wrong", "not implemented" or "error" (check's words)
  std::string headline;  ///< the first failing case, as `./workbook check` says it
};

/// Runs the checks on a thread of its own; at most one run at a time.
class LiveChecks {
 public:
  /// `testExe`: the lab's test binary (this build's app name + "_tests"); without it, or when it is
  /// older than `exerciseCpp` (the C++ exercise file, which it may then not hold), nothing runs.
  /// `appExe`: the running app; an `exerciseCpp` edited after it was built is noted (note()).
  LiveChecks(std::string testExe, const std::string& appExe, std::string exerciseCpp);
  ~LiveChecks();
  LiveChecks(const LiveChecks&) = delete;
  LiveChecks& operator=(const LiveChecks&) = delete;

  /// Starts a run (or, while one runs, another right after it).
  void start();
  /// False when the test binary is not built, or older than the app (./workbook check NN builds it).
  bool available() const { return available_; }
  /// Why the checks do not run, or why their verdicts may not be those of the running code (the C++
  /// exercise file was edited after the app was built, as last polled); empty when they are.
  std::string note() const;
  /// Looks again at the C++ exercise file's time (the app polls with its shader reloads, not per frame).
  void pollEdits();
  /// True while a run is under way (the verdicts are then those of the file before the change).
  bool running() const { return running_; }
  /// The verdicts of the last finished run, by exercise id.
  std::map<std::string, CheckVerdict> verdicts() const;

 private:
  void runOnce();
  std::string exe_, cpp_;
  bool available_ = false;
  std::string missing_;                    // why nothing runs
  std::filesystem::file_time_type built_;  // the app's build time
  bool edited_ = false;                    // exercise.cpp is newer than the app (pollEdits())
  std::atomic<bool> running_{false}, again_{false}, quit_{false};
  std::thread thread_;
  mutable std::mutex mutex_;
  std::map<std::string, CheckVerdict> verdicts_;
};

}  // namespace wb
