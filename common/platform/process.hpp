/// @file process.hpp
/// Runs another program with a time limit and a cap on what it writes, and stops it with every
/// process it started, on Linux, macOS and Windows alike: the one way `check`, its runner and judge,
/// and the tests' lab runs start a program. POSIX: the child leads a process group of its own
/// (Linux also sweeps its session); Windows: a job object holds it and its children.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// What to run, and its bounds.
struct ProcessSpec {
  std::vector<std::string> argv;                         ///< the program, then its arguments
  std::filesystem::path cwd;                             ///< where it runs; empty: here
  std::vector<std::pair<std::string, std::string>> env;  ///< set (or overridden) for it
  std::filesystem::path log;                             ///< its stdout and stderr; empty: ours
  double timeoutSeconds = 0;                             ///< stopped past it; 0: no limit
  long long maxWriteBytes = 0;                           ///< stopped when a file it writes passes it; 0: none
  bool newSession = false;    ///< POSIX: a session of its own (a supervisor's child), not only a group
  double graceSeconds = 1.0;  ///< POSIX: from SIGTERM at a bound to SIGKILL (time to say where it was)
};

/// How a run ended. `code` is a shell's exit status: the program's own, 124 past the time limit,
/// 128 + the signal of a crash (Windows' exceptions mapped to the nearest signal).
struct ProcessResult {
  /// Why it ended: on its own, a crash, its time limit, its cap on writing, or it never started.
  enum class End { Exited, Crashed, TimedOut, WroteTooMuch, NotStarted };
  End end = End::NotStarted;  ///< why it ended
  int code = 127;             ///< the shell's exit status (see above)
  std::string detail;         ///< a crash's signal or exception, or why it did not start
};

/// A running child with every process it starts; stopped and reaped when destroyed.
class Process {
 public:
  explicit Process(const ProcessSpec& spec);  ///< starts it (a failed start ends as NotStarted)
  ~Process();
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  /// Still running? Checks the spec's bounds too, stopping it at either.
  bool running();
  /// Waits until it ends or its bounds stop it.
  ProcessResult wait();
  /// Stops it and everything it started (POSIX: SIGTERM, so a program can say where it was, then
  /// SIGKILL after `graceSeconds`, the spec's when negative; Windows: the whole job at once). `end`
  /// says why.
  void stop(ProcessResult::End end, double graceSeconds = -1);
  /// How it ended (End::NotStarted while it runs).
  const ProcessResult& result() const { return result_; }
  /// Its process id (POSIX: also its group's, or session's), or -1 when it did not start.
  long long id() const { return pid_; }

 private:
  bool reap(bool block);
  bool stoppedAtWriteCap();  // Windows: the log past maxWriteBytes stops it (POSIX: RLIMIT_FSIZE does)
  ProcessSpec spec_;
  ProcessResult result_;
  bool done_ = false;
  double started_ = 0;
  long long pid_ = -1;
#if defined(_WIN32)
  void* job_ = nullptr;      // the job object
  void* process_ = nullptr;  // the process handle
#endif
};

/// Runs `spec` to its end (or its bounds).
ProcessResult runProcess(const ProcessSpec& spec);

/// The command as a person would type it in a POSIX shell (for messages): cd, the environment, argv.
std::string shellCommand(const ProcessSpec& spec);

/// Sets (or, with `value` null, removes) a variable of this process's environment, on every OS.
void setEnv(const std::string& name, const char* value);

/// Seconds on a steady clock.
double steadySeconds();

}  // namespace wb
