#include "common/judge/tape.hpp"

#include "common/exercise/exercise_tape.hpp"

#include "common/platform/shader.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>

namespace fs = std::filesystem;
using nlohmann::json;

namespace wb::test {
namespace {

TapeMode g_mode = TapeMode::Direct;
fs::path g_dir;
std::map<std::string, json> g_entries;       // replay: what the runner recorded
std::map<std::string, std::string> g_stops;  // replay: why the runner of an exercise stopped (check)
std::map<std::string, int> g_counters;       // observations so far per test
std::mutex g_mutex;
constexpr size_t kMaxMessage = 2000;  // a recorded exception's text is the student's: keep it short

std::string sanitize(const std::string& key) {
  std::string s;
  for (char c : key) s += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ? c : '-';
  return s;
}

}  // namespace

TapeMode tapeMode() { return g_mode; }
const fs::path& tapeDir() { return g_dir; }
const std::map<std::string, std::string>& stoppedRuns() { return g_stops; }

void openTape(TapeMode mode, const fs::path& dir) {
  g_mode = mode, g_dir = dir;
  if (mode == TapeMode::Record) {
    fs::create_directories(dir);
    std::ofstream(dir / "tape.jsonl", std::ios::trunc);
  }
  if (mode != TapeMode::Replay) return;
  // Why a runner stopped early, by exercise ("Ex09_2<tab>reason"): written by ./workbook check, which
  // runs each exercise's runner alone with a time limit (the grader keeps its own account of that).
  std::ifstream stops(dir / "stopped.txt");
  for (std::string line; std::getline(stops, line);)
    if (const auto tab = line.find('\t'); tab != std::string::npos)  // (the first reason: the runner's)
      g_stops.emplace(line.substr(0, tab), line.substr(tab + 1));
  std::ifstream in(dir / "tape.jsonl");  // a missing or damaged tape replays as "nothing recorded"
  for (std::string line; std::getline(in, line);) {
    try {
      json e = parseShallowJson(line);
      if (e.is_object() && e.contains("key") && e["key"].is_string()) g_entries[e["key"].get<std::string>()] = e;
    } catch (const std::exception&) {  // malformed, or nested too deep: nothing recorded there
    }
  }
}

std::string nextObservationKey() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "global";
  std::lock_guard<std::mutex> lock(g_mutex);
  return test + "#" + std::to_string(g_counters[test]++);
}

json observeJson(const std::string& key, const std::function<json()>& produce) {
  if (g_mode == TapeMode::Replay) {
    const auto it = g_entries.find(key);
    if (it == g_entries.end()) {
      for (const auto& [tag, reason] : g_stops)
        if (key.find("." + tag + "_") != std::string::npos) throw RunnerStopped(reason);
      throw Error("the student's build recorded no result here (it crashed, timed out or stopped before it)");
    }
    const json& e = it->second;
    // Judging held-out tests, the runner's own words are never quoted: they could carry the inputs.
    const bool quiet = heldOutJudging();
    if (e.contains("not_implemented"))
      throw NotImplemented(quiet ? "(held-out test)" : e["not_implemented"].get<std::string>());
    if (e.contains("error"))
      throw Error(quiet ? "the exercise failed in a held-out test" : e["error"].get<std::string>());
    return e.value("value", json());
  }
  json entry = {{"key", key}};
  try {
    entry["value"] = produce();
  } catch (const NotImplemented& e) {
    std::string what = e.what();  // without the prefix NotImplemented's constructor adds again in replay
    const std::string prefix = NotImplemented("").what();
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    entry["not_implemented"] = what.substr(0, kMaxMessage);
  } catch (const std::exception& e) {
    entry["error"] = std::string(e.what()).substr(0, kMaxMessage);
  }
  if (g_mode == TapeMode::Record) {
    std::lock_guard<std::mutex> lock(g_mutex);
    std::ofstream(g_dir / "tape.jsonl", std::ios::app)
        << entry.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
  }
  if (entry.contains("not_implemented")) throw NotImplemented(entry["not_implemented"].get<std::string>());
  if (entry.contains("error")) throw Error(entry["error"].get<std::string>());
  return entry["value"];
}

bool heldOutJudging() {
  const char* held = std::getenv("WB_HELD_OUT");
  return held && *held && g_mode == TapeMode::Replay;
}

bool planning() {
  const char* plan = std::getenv("WB_PLAN");
  return plan && *plan && g_mode == TapeMode::Replay;
}

void planRequest(const json& request) {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::ofstream(std::getenv("WB_PLAN"), std::ios::app) << request.dump() << "\n";
}

namespace {
std::map<std::string, Callable>& callables() {
  static std::map<std::string, Callable> all;
  return all;
}
}  // namespace

bool registerCallable(const std::string& name, Callable call) {
  callables()[name] = std::move(call);
  return true;
}

json callRegistered(const std::string& name, const json& inputs) {
  const auto it = callables().find(name);
  if (it == callables().end()) throw Error("no exercise " + name + " can be called by name (WB_CALLABLE)");
  return it->second(inputs);
}

bool observeFile(const std::string& name, const fs::path& path) {
  const fs::path kept = g_dir / ("file-" + sanitize(name));
  std::error_code ec;
  if (g_mode == TapeMode::Record && fs::exists(path))
    fs::copy_file(path, kept, fs::copy_options::overwrite_existing, ec);
  if (g_mode != TapeMode::Replay) return fs::exists(path);
  fs::remove(path, ec);
  if (!fs::is_regular_file(kept) || fs::is_symlink(kept)) return false;
  fs::create_directories(path.parent_path());
  return fs::copy_file(kept, path, fs::copy_options::overwrite_existing, ec) && !ec;
}

}  // namespace wb::test
