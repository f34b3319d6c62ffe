#include "common/exercise/live_checks.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#if defined(_WIN32)
#include <process.h>
#define getpid _getpid
#else
#include <unistd.h>
#endif

namespace fs = std::filesystem;

namespace wb {

LiveChecks::LiveChecks(std::string testExe, const std::string& appExe, std::string exerciseCpp)
    : exe_(std::move(testExe)), cpp_(std::move(exerciseCpp)) {
  std::error_code ec;
  const std::string name = fs::path(exe_).filename().string();  // "lab09_tests"
  const std::string lab = name.size() >= 5 ? name.substr(3, 2) : "NN";
  built_ = fs::last_write_time(appExe, ec);
  if (ec) built_ = fs::file_time_type::min();
  if (exe_.empty() || !fs::is_regular_file(exe_, ec))
    missing_ = "checks not run: " + name + " is not built (./workbook check " + lab + " builds it)";
  else if (!cpp_.empty() && fs::exists(cpp_, ec) && fs::last_write_time(exe_, ec) < fs::last_write_time(cpp_, ec))
    missing_ =
        "checks not run: " + name + " is older than your exercise.cpp (./workbook check " + lab + " rebuilds it)";
  available_ = missing_.empty();
  pollEdits();
}

void LiveChecks::pollEdits() {
  std::error_code ec;
  const auto edited = cpp_.empty() ? fs::file_time_type::min() : fs::last_write_time(cpp_, ec);
  edited_ = !ec && edited > built_;
}

std::string LiveChecks::note() const {
  if (!missing_.empty()) return missing_;
  if (edited_)
    return "exercise.cpp changed after this build: these are the running build's verdicts; restart the lab to run "
           "your edit";
  return "";
}

LiveChecks::~LiveChecks() {
  quit_ = true;
  if (thread_.joinable()) thread_.join();
}

void LiveChecks::start() {
  if (!available_) return;
  if (running_) {
    again_ = true;
    return;
  }
  if (thread_.joinable()) thread_.join();
  running_ = true;
  thread_ = std::thread([this] {
    do {
      again_ = false;
      runOnce();
    } while (again_ && !quit_);
    running_ = false;
  });
}

void LiveChecks::runOnce() {
  // The layer-1 cases only: no scene (the tests that run the lab app are named Scene or Measured).
  const fs::path json = fs::temp_directory_path() / ("wb-live-checks-" + std::to_string(::getpid()) + ".json");
#if defined(_WIN32)  // cmd.exe: the variable is set for the command that follows it
  const std::string cmd = "set \"WB_CHECK_JSON=" + json.string() + "\" && \"" + exe_ +
                          "\" --check \"--gtest_filter=-*Scene*:*Measured*:Hidden*:Manifest*\" >NUL 2>&1";
#else
  const std::string cmd = "WB_CHECK_JSON='" + json.string() + "' '" + exe_ +
                          "' --check '--gtest_filter=-*Scene*:*Measured*:Hidden*:Manifest*' >/dev/null 2>&1";
#endif
  std::system(cmd.c_str());
  std::map<std::string, CheckVerdict> found;
  try {
    std::ifstream in(json);
    const auto all = nlohmann::json::parse(in);  // (kept alive while iterating)
    for (const auto& [id, v] : all.items())
      found[id] = {v.value("status", std::string()), v.value("headline", std::string())};
  } catch (const std::exception&) {
    return;  // a run that wrote nothing (the binary crashed): keep the last verdicts
  }
  std::error_code ec;
  fs::remove(json, ec);
  std::lock_guard<std::mutex> lock(mutex_);
  verdicts_ = std::move(found);
}

std::map<std::string, CheckVerdict> LiveChecks::verdicts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return verdicts_;
}

}  // namespace wb
