#include "tests/harness/tape.hpp"

#include "common/shader.hpp"

#include <gtest/gtest.h>

#include <cctype>
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
std::map<std::string, json> g_entries;  // replay: what the runner recorded
std::map<std::string, int> g_counters;  // observations so far per test
std::mutex g_mutex;
constexpr size_t kMaxMessage = 2000;  // a recorded exception's text is the student's: keep it short

std::string sanitize(const std::string& key) {
  std::string s;
  for (char c : key) s += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ? c : '-';
  return s;
}

uint32_t bits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, 4);
  return b;
}
float fromBits(uint32_t b) {
  float v;
  std::memcpy(&v, &b, 4);
  return v;
}
std::vector<float> floatsOf(const json& j, size_t n) {
  if (!j.is_array() || (n && j.size() != n)) throw Error("a recorded value has the wrong shape");
  std::vector<float> v;
  for (const auto& e : j) v.push_back(fromBits(e.get<uint32_t>()));
  return v;
}

}  // namespace

TapeMode tapeMode() { return g_mode; }
const fs::path& tapeDir() { return g_dir; }

void openTape(TapeMode mode, const fs::path& dir) {
  g_mode = mode, g_dir = dir;
  if (mode == TapeMode::Record) {
    fs::create_directories(dir);
    std::ofstream(dir / "tape.jsonl", std::ios::trunc);
  }
  if (mode != TapeMode::Replay) return;
  std::ifstream in(dir / "tape.jsonl");  // a missing or damaged tape replays as "nothing recorded"
  for (std::string line; std::getline(in, line);) {
    try {
      json e = json::parse(line);
      if (e.is_object() && e.contains("key") && e["key"].is_string()) g_entries[e["key"].get<std::string>()] = e;
    } catch (const json::exception&) {
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
    if (it == g_entries.end())
      throw Error("the student's build recorded no result here (it crashed, timed out or stopped before it)");
    const json& e = it->second;
    if (e.contains("not_implemented")) throw NotImplemented(e["not_implemented"].get<std::string>());
    if (e.contains("error")) throw Error(e["error"].get<std::string>());
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
    std::ofstream(g_dir / "tape.jsonl", std::ios::app) << entry.dump() << "\n";
  }
  if (entry.contains("not_implemented")) throw NotImplemented(entry["not_implemented"].get<std::string>());
  if (entry.contains("error")) throw Error(entry["error"].get<std::string>());
  return entry["value"];
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

json encode(float v) { return bits(v); }
json encode(double v) {
  uint64_t b;
  std::memcpy(&b, &v, 8);
  return std::to_string(b);
}
json encode(bool v) { return v; }
json encode(int v) { return v; }
json encode(const glm::vec2& v) { return {bits(v.x), bits(v.y)}; }
json encode(const glm::vec3& v) { return {bits(v.x), bits(v.y), bits(v.z)}; }
json encode(const glm::vec4& v) { return {bits(v.x), bits(v.y), bits(v.z), bits(v.w)}; }
json encode(const glm::mat4& m) {
  json j = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) j.push_back(bits(m[c][r]));
  return j;
}
json encode(const std::vector<glm::vec4>& v) {
  json j = json::array();
  for (const auto& e : v)
    for (int k = 0; k < 4; ++k) j.push_back(bits(e[k]));
  return j;
}

template <>
float decode<float>(const json& j) {
  return fromBits(j.get<uint32_t>());
}
template <>
double decode<double>(const json& j) {
  const uint64_t b = std::stoull(j.get<std::string>());
  double v;
  std::memcpy(&v, &b, 8);
  return v;
}
template <>
bool decode<bool>(const json& j) {
  return j.get<bool>();
}
template <>
int decode<int>(const json& j) {
  return j.get<int>();
}
template <>
glm::vec2 decode<glm::vec2>(const json& j) {
  const auto f = floatsOf(j, 2);
  return {f[0], f[1]};
}
template <>
glm::vec3 decode<glm::vec3>(const json& j) {
  const auto f = floatsOf(j, 3);
  return {f[0], f[1], f[2]};
}
template <>
glm::vec4 decode<glm::vec4>(const json& j) {
  const auto f = floatsOf(j, 4);
  return {f[0], f[1], f[2], f[3]};
}
template <>
glm::mat4 decode<glm::mat4>(const json& j) {
  const auto f = floatsOf(j, 16);
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = f[size_t(c * 4 + r)];
  return m;
}
template <>
std::vector<glm::vec4> decode<std::vector<glm::vec4>>(const json& j) {
  const auto f = floatsOf(j, 0);
  if (f.size() % 4) throw Error("a recorded kernel output has the wrong shape");
  std::vector<glm::vec4> v;
  for (size_t k = 0; k + 3 < f.size(); k += 4) v.emplace_back(f[k], f[k + 1], f[k + 2], f[k + 3]);
  return v;
}

}  // namespace wb::test
