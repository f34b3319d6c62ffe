#include "common/judge/supervisor.hpp"

#include "common/platform/process.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace wb::check {
namespace {

std::atomic<bool> g_stop{false};

int envInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && std::atoi(v) > 0 ? std::atoi(v) : fallback;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The last line of `log` that starts with `prefix` ("crashed (", "timed out ("), or "".
std::string lastLineStarting(const fs::path& log, const std::string& prefix) {
  std::istringstream lines(readAll(log));
  std::string found;
  for (std::string l; std::getline(lines, l);)
    if (l.rfind(prefix, 0) == 0) found = l;
  return found;
}

void appendLine(const fs::path& file, const std::string& line) {
  std::ofstream(file, std::ios::app | std::ios::binary) << line << "\n";
}

// Waits for `p`, stopping it on a requested stop (Ctrl-C); `tick` runs between polls and may stop it.
template <typename Tick>
ProcessResult supervise(Process& p, Tick tick) {
  while (p.running()) {
    if (g_stop) p.stop(ProcessResult::End::Crashed);
    tick();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return p.result();
}

// One exercise's runner has ended: what stopped.txt says of it, if anything.
std::string stoppedReason(const ProcessResult& r, const std::string& id, const fs::path& log, const Limits& limits) {
  if (r.end == ProcessResult::End::TimedOut) {
    // (its crash report, from the SIGTERM, says in which exercise it was: "... in exercise 2.1, at ...")
    std::string where = lastLineStarting(log, "timed out (");
    if (const auto at = where.find(") in exercise"); at != std::string::npos)
      where = "In exercise" + where.substr(at + 13);
    return id + " timed out after " + std::to_string(limits.exerciseSeconds) + " s and was stopped: an endless loop? " +
           (where.empty() ? "" : where + ". ") + (limits.inSandbox ? "" : "(WB_CHECK_TIMEOUT=S sets the limit)");
  }
  if (r.end == ProcessResult::End::WroteTooMuch) {
    std::ofstream(log, std::ios::app | std::ios::binary)
        << "\n[workbook: cut here: the run wrote more than " << limits.logMegabytes << " MB and was stopped]\n";
    return id + " wrote more than " + std::to_string(limits.logMegabytes) +
           " MB of output (a print in a loop?) and was stopped; its log is cut there: " + log.generic_string();
  }
  if (r.end == ProcessResult::End::Crashed) {
    const std::string named = lastLineStarting(log, "crashed (");
    if (!named.empty()) return named;
    return "exercise " + id + " crashed (" + (r.detail.empty() ? "signal " + std::to_string(r.code - 128) : r.detail) +
           ")";
  }
  if (r.end == ProcessResult::End::NotStarted) return "exercise " + id + "'s runner did not start: " + r.detail;
  return "";
}

}  // namespace

Limits Limits::fromEnvironment() {
  Limits l;
  l.exerciseSeconds = envInt("WB_CHECK_TIMEOUT", l.exerciseSeconds);
  l.judgeTestSeconds = envInt("WB_CHECK_JUDGE_TIMEOUT", l.judgeTestSeconds);
  l.logMegabytes = envInt("WB_CHECK_LOG_MB", l.logMegabytes);
  l.inSandbox = envInt("WB_CHECK_IN_SANDBOX", 0) == 1;
  return l;
}

void requestStop() { g_stop = true; }

void runExerciseRunner(const fs::path& tests, const std::string& id, const fs::path& tape, const Limits& limits,
                       const std::string& recordShaders, const std::vector<std::string>& testArgs) {
  const std::string tag = "Ex" + std::regex_replace(id, std::regex("\\."), "_");
  const fs::path part = tape / tag, log = tape / (tag + ".log");
  fs::create_directories(tape / "all");
  ProcessSpec spec;
  spec.argv = {tests.string(), "--runner", part.string()};
  if (testArgs.empty()) spec.argv.push_back("--gtest_filter=*." + tag + "_*");
  spec.argv.insert(spec.argv.end(), testArgs.begin(), testArgs.end());
  // (a lab run a test starts gets a third of the exercise's time, a scene test may run a few; the
  // grader's runs say their own)
  const char* runLimit = std::getenv("WB_RUN_TIMEOUT");
  spec.env = {{"WB_RUN_TIMEOUT", runLimit ? runLimit : std::to_string(std::max(limits.exerciseSeconds / 3, 3))},
              {"WB_RECORD_SHADERS", recordShaders}};
  spec.log = log;
  spec.timeoutSeconds = limits.exerciseSeconds;
  spec.maxWriteBytes = (long long)limits.logMegabytes * 1024 * 1024;
  spec.newSession = !limits.inSandbox;  // (the runner and the lab runs its tests start: all stopped together)
  Process runner(spec);
  std::ofstream(tape / "running.pid") << runner.id() << "\n";  // (./workbook check --watch stops its session)
  const ProcessResult r = supervise(runner, [] {});
  std::error_code ec;
  fs::remove(tape / "running.pid", ec);  // (ended: its id may be another process's soon, which no watch may stop)
  if (const std::string why = stoppedReason(r, id, log, limits); !why.empty())
    appendLine(tape / "all" / "stopped.txt", tag + "\t" + why);
  // Only regular files are read or written, never through a link: the runner's folder and all/ are the
  // student's code's to change too, and a FIFO swapped in would stop this process at open.
  const auto regular = [](const fs::path& p) {
    std::error_code e;
    return fs::symlink_status(p, e).type() == fs::file_type::regular;
  };
  const auto writable = [&](const fs::path& p) { return !fs::exists(fs::symlink_status(p, ec)) || regular(p); };
  if (regular(part / "tape.jsonl") && writable(tape / "all" / "tape.jsonl"))
    std::ofstream(tape / "all" / "tape.jsonl", std::ios::app) << readAll(part / "tape.jsonl");
  for (const auto& f : fs::directory_iterator(part, ec))
    if (f.path().filename().string().rfind("file-", 0) == 0 && regular(f.path()) &&
        writable(tape / "all" / f.path().filename()))
      fs::copy_file(f.path(), tape / "all" / f.path().filename(), fs::copy_options::overwrite_existing, ec);
}

namespace {

// `args` with the tests in `skip` (a:b:c) left out of its --gtest_filter, or one added that leaves them out.
std::vector<std::string> withoutTests(std::vector<std::string> args, const std::string& skip) {
  if (skip.empty()) return args;
  const std::string flag = "--gtest_filter=";
  for (std::string& a : args)
    if (a.rfind(flag, 0) == 0) {
      a += (a.find('-', flag.size()) == std::string::npos ? "-" : ":") + skip;
      return args;
    }
  args.push_back(flag + "-" + skip);
  return args;
}

// One run of the judge: its exit code, or 124 when the test in `progress` made no progress for
// the judge's limit (the process is then stopped, with everything it started).
int judgeOnce(const fs::path& judge, const fs::path& tape, const fs::path& submission, const Limits& limits,
              const std::vector<std::string>& judgeArgs, const std::string& skip) {
  const fs::path progress = tape / "judging.txt";
  std::ofstream(progress, std::ios::trunc).close();
  ProcessSpec spec;
  spec.argv = {judge.string(), "--judge", (tape / "all").string()};
  for (const std::string& a : withoutTests(judgeArgs.empty() ? std::vector<std::string>{"--check"} : judgeArgs, skip))
    spec.argv.push_back(a);
  spec.env = {{"WB_SUBMISSION_DIR", fs::absolute(submission).string()},
              {"WB_RUN_TIMEOUT", std::to_string(std::max(limits.exerciseSeconds, 8))},
              {"WB_PROGRESS_FILE", progress.string()}};
  spec.maxWriteBytes = (long long)limits.logMegabytes * 1024 * 1024;
  spec.newSession = true;
  Process p(spec);
  std::ofstream(tape / "running.pid") << p.id() << "\n";
  std::string last;
  double since = steadySeconds();
  const ProcessResult r = supervise(p, [&] {
    std::string now;
    std::ifstream in(progress);
    std::getline(in, now);
    if (now != last) last = now, since = steadySeconds();
    if (steadySeconds() - since > limits.judgeTestSeconds) p.stop(ProcessResult::End::TimedOut);
  });
  std::error_code ec;
  fs::remove(tape / "running.pid", ec);  // (as the runner's above)
  if (r.end == ProcessResult::End::NotStarted)
    std::fprintf(stderr, "workbook: the judge did not start: %s\n", r.detail.c_str());
  return r.end == ProcessResult::End::TimedOut ? 124 : r.code;
}

}  // namespace

int runJudge(const std::string& nn, const fs::path& judge, const fs::path& tape, const fs::path& submission,
             const Limits& limits, const std::vector<std::string>& judgeArgs) {
  std::string skip;
  for (int tries = 0; tries < 8 && !g_stop; ++tries) {
    const int rc = judgeOnce(judge, tape, submission, limits, judgeArgs, skip);
    if (rc != 124 || g_stop) return rc;
    std::string test;
    std::getline(std::ifstream(tape / "judging.txt") >> std::ws, test);
    const std::string per = std::to_string(limits.judgeTestSeconds);
    if (test.empty()) {
      std::fprintf(stderr, "workbook: judging lab %s stopped after %s s before its first test began\n", nn.c_str(),
                   per.c_str());
      return 124;
    }
    std::smatch m;
    const bool named = std::regex_search(test, m, std::regex("^[^.]*\\.Ex([0-9][0-9])_([0-9xH]*)_"));
    const std::string id = named ? m[1].str() + "." + m[2].str() : "";
    std::fprintf(stderr,
                 "workbook: judging lab %s: the test %s%s ran past %s s and was stopped; judging the rest without it "
                 "(WB_CHECK_JUDGE_TIMEOUT=S sets the limit)\n",
                 nn.c_str(), test.c_str(), named ? (" (exercise " + id + ")").c_str() : "", per.c_str());
    if (named)
      appendLine(tape / "all" / "stopped.txt", "Ex" + m[1].str() + "_" + m[2].str() + "\tthe judge's test " + test +
                                                   " ran past " + per + " s and was stopped: an endless loop in " + id +
                                                   " or an exercise it uses?");
    skip += (skip.empty() ? "" : ":") + test;
  }
  return 124;
}

}  // namespace wb::check
