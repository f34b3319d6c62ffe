#include "common/platform/process.hpp"

#include <chrono>
#include <cstdlib>
#include <thread>

#if !defined(_WIN32)
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#endif

namespace fs = std::filesystem;

namespace wb {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string shellCommand(const ProcessSpec& spec) {
  auto quote = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::string cmd = spec.cwd.empty() ? "" : "cd " + quote(spec.cwd.string()) + " && ";
  for (const auto& [name, value] : spec.env) cmd += name + "=" + quote(value) + " ";
  for (size_t k = 0; k < spec.argv.size(); ++k) cmd += (k ? " " : "") + quote(spec.argv[k]);
  return cmd;
}

void setEnv(const std::string& name, const char* value) {
#if defined(_WIN32)
  _putenv_s(name.c_str(), value ? value : "");  // (an empty value removes it there)
#else
  if (value)
    setenv(name.c_str(), value, 1);
  else
    unsetenv(name.c_str());
#endif
}

ProcessResult runProcess(const ProcessSpec& spec) {
  Process process(spec);
  return process.wait();
}

bool Process::running() {
  if (done_ || reap(false)) return false;
  if (spec_.timeoutSeconds > 0 && steadySeconds() - started_ > spec_.timeoutSeconds) {
    stop(ProcessResult::End::TimedOut);
    return false;
  }
  return !stoppedAtWriteCap();
}

ProcessResult Process::wait() {
  while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return result_;
}

Process::~Process() {
  if (!done_) stop(ProcessResult::End::Crashed, 0);
}

#if !defined(_WIN32)

namespace {

// argv[0] as execve wants it: a path (searched on PATH when it names no folder), found before the
// fork, as nothing but async-signal-safe calls may follow a fork in a program with threads.
std::string programPath(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (size_t at = 0; at <= dirs.size();) {
    const size_t end = std::min(dirs.find(':', at), dirs.size());
    const std::string candidate = (end > at ? dirs.substr(at, end - at) : ".") + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    at = end + 1;
  }
  return name;
}

// The environment with `spec.env` over ours.
std::vector<std::string> childEnvironment(const ProcessSpec& spec) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool overridden = false;
    for (const auto& kv : spec.env) overridden |= entry.compare(0, kv.first.size() + 1, kv.first + "=") == 0;
    if (!overridden) env.push_back(entry);
  }
  for (const auto& [name, value] : spec.env) env.push_back(name + "=" + value);
  return env;
}

// In the child: its group (or session), folder, output and bounds, then the program. Reports a failed
// start's errno on `report`.
[[noreturn]] void becomeChild(const ProcessSpec& spec, const char* path, char* const* argv, char* const* envp,
                              int report) {
  if (spec.newSession) {
    setsid();
#if defined(__linux__)
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // (its supervisor gone, nobody would stop it)
#endif
  } else {
    setpgid(0, 0);
  }
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  int err = 0;
  if (!spec.cwd.empty() && chdir(spec.cwd.c_str()) != 0) err = errno;
  if (!err && !spec.log.empty()) {
    const int fd = open(spec.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || dup2(fd, 1) < 0 || dup2(fd, 2) < 0) err = errno;
  }
  if (!err && spec.maxWriteBytes > 0) {
    const rlimit cap{rlim_t(spec.maxWriteBytes), rlim_t(spec.maxWriteBytes)};
    setrlimit(RLIMIT_FSIZE, &cap);
  }
  if (!err) {
    execve(path, argv, envp);
    err = errno;
  }
  [[maybe_unused]] const ssize_t n = write(report, &err, sizeof err);
  _exit(127);
}

// Signals the child's group, and on Linux every process of its session (a group of its own inside
// it, such as a lab run a test started, included).
void signalTree(long long pid, bool session, int sig) {
  killpg(pid_t(pid), sig);
#if defined(__linux__)
  if (!session) return;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    std::getline(stat, line);
    const size_t close = line.rfind(')');
    if (close == std::string::npos) continue;
    char state = 0;
    long ppid = 0, pgrp = 0, sid = 0;
    if (std::sscanf(line.c_str() + close + 1, " %c %ld %ld %ld", &state, &ppid, &pgrp, &sid) == 4 && sid == pid)
      kill(pid_t(std::atol(name.c_str())), sig);
  }
#else
  (void)session;
#endif
}

}  // namespace

Process::Process(const ProcessSpec& spec) : spec_(spec), started_(steadySeconds()) {
  if (spec.argv.empty()) {
    done_ = true, result_.detail = "nothing to run";
    return;
  }
  const std::string path = programPath(spec.argv[0]);
  std::vector<std::string> envStrings = childEnvironment(spec);
  std::vector<char*> argv, envp;
  for (const auto& a : spec_.argv) argv.push_back(const_cast<char*>(a.c_str()));
  for (auto& e : envStrings) envp.push_back(e.data());
  argv.push_back(nullptr), envp.push_back(nullptr);
  int report[2];
  if (pipe(report) != 0 || fcntl(report[1], F_SETFD, FD_CLOEXEC) != 0) {
    done_ = true, result_.detail = std::strerror(errno);
    return;
  }
  const pid_t pid = fork();
  if (pid == 0) becomeChild(spec_, path.c_str(), argv.data(), envp.data(), report[1]);
  close(report[1]);
  int err = 0;
  const bool failed = pid < 0 || read(report[0], &err, sizeof err) == sizeof err;
  close(report[0]);
  if (pid < 0) err = errno;
  if (failed) {
    if (pid > 0) waitpid(pid, nullptr, 0);
    done_ = true, result_.detail = spec.argv[0] + ": " + std::strerror(err);
    return;
  }
  pid_ = pid;
  if (!spec.newSession) setpgid(pid, pid);  // (set on both sides: no signal may come before it)
}

// Has the child ended? Whatever it left running in its group goes with it; then it is reaped.
bool Process::reap(bool block) {
  siginfo_t info{};
  if (waitid(P_PID, id_t(pid_), &info, WEXITED | WNOWAIT | (block ? 0 : WNOHANG)) != 0 || info.si_pid == 0)
    return false;
  signalTree(pid_, spec_.newSession, SIGKILL);  // (before the reap: its id cannot be taken again yet)
  int status = 0;
  waitpid(pid_t(pid_), &status, 0);
  done_ = true;
  if (result_.end != ProcessResult::End::NotStarted) return true;  // (stopped: stop() says why)
  if (WIFEXITED(status)) {
    result_.end = ProcessResult::End::Exited, result_.code = WEXITSTATUS(status);
  } else if (WTERMSIG(status) == SIGXFSZ) {
    result_.end = ProcessResult::End::WroteTooMuch, result_.code = 128 + SIGXFSZ;
  } else {
    result_.end = ProcessResult::End::Crashed, result_.code = 128 + WTERMSIG(status);
    result_.detail = strsignal(WTERMSIG(status));
  }
  return true;
}

bool Process::stoppedAtWriteCap() { return false; }  // (the kernel's cap: a SIGXFSZ, read by reap())

void Process::stop(ProcessResult::End end, double graceSeconds) {
  if (done_) return;
  signalTree(pid_, spec_.newSession, SIGTERM);
  const double grace = graceSeconds < 0 ? spec_.graceSeconds : graceSeconds;
  for (const double until = steadySeconds() + grace; steadySeconds() < until;) {
    siginfo_t info{};
    if (waitid(P_PID, id_t(pid_), &info, WEXITED | WNOWAIT | WNOHANG) == 0 && info.si_pid != 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  result_.end = end;
  result_.code = end == ProcessResult::End::TimedOut ? 124 : end == ProcessResult::End::WroteTooMuch ? 153 : 137;
  signalTree(pid_, spec_.newSession, SIGKILL);
  reap(true);
}

#endif

}  // namespace wb
