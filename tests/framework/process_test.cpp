// process.hpp, the one way check and the tests start a program: exit codes, crashes, the time limit
// with the processes it started, the cap on what it writes, its folder and environment, a program
// that does not exist.
#include "common/platform/process.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using wb::ProcessResult;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("wb-process-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readAll(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

wb::ProcessSpec shell(const std::string& script, const fs::path& dir) {
  wb::ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", script};
  spec.cwd = dir, spec.log = dir / "log.txt";
  return spec;
}

TEST(Process, ReportsItsExitCodeFolderEnvironmentAndOutput) {
  const fs::path dir = scratch("exit");
  auto spec = shell("echo \"$WB_PROCESS_TEST in $(pwd)\"; exit 3", dir);
  spec.env = {{"WB_PROCESS_TEST", "it's set"}};
  const auto r = wb::runProcess(spec);
  EXPECT_EQ(r.end, ProcessResult::End::Exited);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(readAll(dir / "log.txt"), "it's set in " + fs::canonical(dir).string() + "\n");
}

TEST(Process, NamesACrashBySignal) {
  const auto r = wb::runProcess(shell("kill -SEGV $$", scratch("crash")));
  EXPECT_EQ(r.end, ProcessResult::End::Crashed);
  EXPECT_EQ(r.code, 128 + SIGSEGV);
}

TEST(Process, StopsAtItsTimeLimitWithWhatItStarted) {
  const fs::path dir = scratch("timeout");
  auto spec = shell("sleep 100 & echo $! > child.pid; while :; do :; done", dir);
  spec.timeoutSeconds = 1;
  const double start = wb::steadySeconds();
  const auto r = wb::runProcess(spec);
  EXPECT_EQ(r.end, ProcessResult::End::TimedOut);
  EXPECT_EQ(r.code, 124);
  EXPECT_LT(wb::steadySeconds() - start, 5.0);
  const std::string child = readAll(dir / "child.pid");
  ASSERT_FALSE(child.empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  std::ifstream stat("/proc/" + std::to_string(std::stol(child)) + "/stat");
  std::string line;
  std::getline(stat, line);
  EXPECT_TRUE(line.empty() || line.find(") Z ") != std::string::npos) << "still running: " << line;
}

TEST(Process, StopsAtTheCapOnWhatItWrites) {
  const fs::path dir = scratch("flood");
  auto spec = shell("exec yes flood", dir);
  spec.maxWriteBytes = 100000;
  const auto r = wb::runProcess(spec);
  EXPECT_EQ(r.end, ProcessResult::End::WroteTooMuch);
  EXPECT_LE(fs::file_size(dir / "log.txt"), 100000u);
}

TEST(Process, SaysWhyAProgramDidNotStart) {
  wb::ProcessSpec spec;
  spec.argv = {"/nonexistent/wb-no-such-program"};
  const auto r = wb::runProcess(spec);
  EXPECT_EQ(r.end, ProcessResult::End::NotStarted);
  EXPECT_NE(r.detail.find("wb-no-such-program"), std::string::npos) << r.detail;
}

}  // namespace
