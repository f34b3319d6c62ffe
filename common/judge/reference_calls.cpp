#include "common/judge/reference_calls.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/platform/shader.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>

namespace fs = std::filesystem;

namespace wb::test {

// The arguments that name a file the run writes or reads calls from: they say nothing about what
// the exercises are asked, and they differ between build folders.
static bool namesAnOutput(const std::string& arg) {
  return arg == "--dump-visibility" || arg == "--screenshot" || arg == "--heatmap" || arg == "--record" ||
         arg == "--record-exercises" || arg == "--replay-exercises";
}

// The arguments as a file name: a scene by its name (its folder is the checkout's), every other
// character that is not plain replaced; a long one cut, with a hash of the whole to keep it unique.
static std::string callsKey(const std::vector<std::string>& args) {
  std::string key;
  for (size_t k = 0; k < args.size(); ++k) {
    if (namesAnOutput(args[k])) {
      ++k;
      continue;
    }
    std::string a = args[k];
    if (k > 0 && args[k - 1] == "--scene") a = fs::path(a).stem().string();
    while (!a.empty() && a[0] == '-') a.erase(0, 1);  // --set a=b: set_a=b
    key += (key.empty() ? "" : "_") + a;
  }
  uint64_t hash = 1469598103934665603ull;  // FNV-1a: the same on every platform, unlike std::hash
  for (char& c : key) {
    hash = (hash ^ uint8_t(c)) * 1099511628211ull;
    if (!std::isalnum(uint8_t(c)) && c != '.' && c != '=' && c != '-') c = '_';
  }
  if (key.empty()) key = "default";
  if (key.size() > 100) {
    char tail[24];
    std::snprintf(tail, sizeof tail, "_%016llx", static_cast<unsigned long long>(hash));
    key = key.substr(0, 100) + tail;
  }
  return key;
}

// True for a held-out test (tests/hidden/) or a run of a held-out scene: their calls stay there.
static bool heldOut(const std::vector<std::string>& args) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  if (test && std::string(test->file()).find("tests/hidden/") != std::string::npos) return true;
  for (const auto& a : args)
    if (a.find("tests/hidden/") != std::string::npos) return true;
  return false;
}

fs::path referenceCallsFile(const std::vector<std::string>& args) {
  const fs::path root(variant::kSourceDir);
  const fs::path dir =
      heldOut(args) ? root / "tests/hidden" / variant::kLab / "calls" : root / "tests/golden" / variant::kLab / "calls";
  return dir / (callsKey(args) + ".json");
}

bool referenceCallsOfOthers(const fs::path& reference, const std::string& id, const fs::path& out) {
  fs::remove(out);
  std::error_code missing;
  if (!fs::is_regular_file(reference, missing)) return false;
  try {
    auto all = parseShallowJson(readFile(reference));
    auto& calls = all.at("calls");
    calls.erase(id);
    if (calls.empty()) return false;
    std::ofstream(out) << all.dump();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

bool keepReferenceCalls(const fs::path& file) {
  bool any = false;
  try {
    any = !parseShallowJson(readFile(file)).at("calls").empty();
  } catch (const std::exception&) {
  }
  std::error_code ignored;
  if (!any) fs::remove(file, ignored);
  return any;
}

}  // namespace wb::test
