#include "common/judge/diagnosis.hpp"

#include "common/platform/loop_guard.hpp"

#include "common/base/variant.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace wb::test {
namespace {

// Paths under the repository (and the build's output) as a student would type them.
std::string shortPaths(std::string text) {
  const std::string root = std::string(variant::kSourceDir) + "/";
  for (size_t at; (at = text.find(root)) != std::string::npos;) text.erase(at, root.size());
  return text;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// A number as gtest prints it ("0.66666666666666663"), shortened to 6 significant digits.
std::string num(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return text;
  char out[32];
  std::snprintf(out, sizeof out, "%.6g", v);
  return out;
}

// Numbers in our own messages as a student would write them: gtest prints a float it is given with
// 17 digits ("0.20000000298023224"), which we shorten to 6 significant ones ("0.2").
std::string shortNumbers(const std::string& text) {
  static const std::regex longNumber(R"(-?\d+\.\d{8,}(?:[eE][-+]?\d+)?)");
  std::string out;
  auto at = text.cbegin();
  for (std::sregex_iterator m(text.begin(), text.end(), longNumber), end; m != end; ++m) {
    out.append(at, (*m)[0].first);
    out += num((*m)[0].str());
    at = (*m)[0].second;
  }
  return out.append(at, text.cend());
}

// gtest's own account of a failed comparison, as "got X, want Y" with the tolerance.
// A printed value as a number: true and false as 1 and 0 (strtod reads both as 0, which made a
// "got true" look like a recorded "got false"), nothing for a value that is not a number.
std::optional<double> valueOf(const std::string& text) {
  if (text == "true") return 1.0;
  if (text == "false") return 0.0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return std::nullopt;
  return v;
}

std::optional<std::string> gotWant(const std::string& gtest, std::optional<double>& got) {
  std::smatch m;
  static const std::regex nearRe(
      R"(The difference between .+ and .+ is (\S+), which exceeds .+, where\n.+ evaluates to (\S+),\n.+ evaluates to (\S+), and\n.+ evaluates to (\S+)\.)");
  static const std::regex cmpRe(R"(Expected: \((.+)\) (<|<=|>|>=|!=) \((.+)\), actual: (\S+) vs (\S+))");
  static const std::regex eqRe(
      R"(Expected equality of these values:\n  (.+)\n(?:    Which is: (.+)\n)?  (.+)\n(?:    Which is: (.+))?)");
  if (std::regex_search(gtest, m, nearRe)) {
    got = valueOf(m[2].str());
    return "got " + num(m[2].str()) + ", want " + num(m[3].str()) + " (allowed difference " + num(m[4].str()) +
           ", off by " + num(m[1].str()) + ")";
  }
  if (std::regex_search(gtest, m, cmpRe)) {
    got = valueOf(m[4].str());
    return "got " + m[1].str() + " = " + num(m[4].str()) + ", want it " + m[2].str() + " " + num(m[5].str());
  }
  if (std::regex_search(gtest, m, eqRe)) {
    const std::string a = m[2].matched ? m[2].str() : m[1].str(), b = m[4].matched ? m[4].str() : m[3].str();
    got = valueOf(a);
    return "got " + num(a) + ", want " + num(b);
  }
  return std::nullopt;
}

// The first number in our own WRONG message ("differs ... on 6.85% of pixels"), as a signature.
std::optional<double> firstNumber(const std::string& text) {
  static const std::regex num(R"([-+]?\d+\.\d+(?:[eE][-+]?\d+)?)");
  std::smatch m;
  if (std::regex_search(text, m, num)) return std::strtod(m[0].str().c_str(), nullptr);
  return std::nullopt;
}

// The share of pixels a scene test lets differ ("differs from the reference on 44.50% of pixels
// (allowed 0.50%)"), in percent; 0 for any other message.
double allowedShare(const std::string& headline) {
  static const std::regex allowed(R"(% of pixels \(allowed ([0-9.]+)%\))");
  std::smatch m;
  return std::regex_search(headline, m, allowed) ? std::strtod(m[1].str().c_str(), nullptr) : 0.0;
}

}  // namespace

std::string knownMistake(const std::string& test, double got, double slack) {
  static const nlohmann::json hints = [] {
    std::ifstream in(fs::path(variant::kSourceDir) / "tests/hints" / (std::string(variant::kLab) + ".json"));
    return in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
  }();
  if (!hints.is_object() || !hints.contains("hints")) return "";
  std::vector<std::string> found;  // several mistakes can give the same value: name them all
  for (const auto& h : hints["hints"]) {
    if (h.value("test", "") != test || !h.contains("value")) continue;
    // Whole numbers (counts, GL enums: GL_INCR is 7682, GL_KEEP 7680) must be equal; other values
    // within 0.1%.
    const double want = h["value"].is_null() ? 0.0 : h["value"].get<double>();
    const bool whole = want == std::round(want) && got == std::round(got);
    const bool same = h["value"].is_null()  // NaN or infinity (JSON has neither): a division by zero
                          ? !std::isfinite(got)
                          : whole && slack == 0
                                ? got == want
                                : std::abs(got - want) <= std::max(slack, 1e-3 * std::max(1e-6, std::abs(want)));
    const std::string hint = h.value("hint", "");
    if (same && std::find(found.begin(), found.end(), hint) == found.end()) found.push_back(hint);
  }
  if (found.size() <= 1) return found.empty() ? "" : found[0];
  std::string all = "one of these:";
  for (const auto& f : found) all += "\n            - " + f;
  return all;
}

Diagnosis diagnose(const std::string& test, const std::string& message) {
  Diagnosis d;
  size_t at = std::string::npos;
  for (const char* k : {"NOT IMPLEMENTED", "WRONG", "ERROR"}) at = std::min(at, message.find(k));
  const std::string ours = shortNumbers(shortPaths(at == std::string::npos ? "WRONG: " + message : message.substr(at)));
  const std::string gtest = at == std::string::npos ? message : message.substr(0, at);
  d.verdict = ours.rfind("ERROR", 0) == 0             ? "ERROR"
              : ours.rfind("NOT IMPLEMENTED", 0) == 0 ? "NOT IMPLEMENTED"
                                                      : "WRONG";
  const auto lines = linesOf(ours);
  d.headline = lines.empty() ? d.verdict : lines[0];
  // A compile error: the compiler's lines that name a file and line (the student's, first).
  for (const auto& l : lines)
    if (l.find(": error") != std::string::npos && d.details.size() < 4 && d.headline.find(l) == std::string::npos)
      d.details.push_back(l);  // (each once: not again when the headline quotes it)
  if (d.verdict == "WRONG") {
    if (const auto gw = gotWant(gtest, d.got)) d.details.push_back(*gw);
    // (a shader's time against the reference's is no signature of a mistake: it varies from run to run)
    if (!d.got && d.headline.find("longer than the reference") == std::string::npos) d.got = firstNumber(d.headline);
    // The loop guard stops an exercise's loops after kLoopGuardSteps steps (a GPU would hang instead):
    // a count of exactly that, where it should be another, is a loop that never ends.
    if (d.got && (*d.got == kLoopGuardSteps || *d.got == kLoopGuardSteps + 1))
      d.details.push_back("looks like an endless loop: it ran " + std::to_string(kLoopGuardSteps) +
                          " steps, the most the workbook lets an exercise's loops run; on a GPU it would hang "
                          "(does the loop's counter change?)");
    if (d.got)
      if (const std::string hint = knownMistake(test, *d.got, allowedShare(d.headline)); !hint.empty())
        d.details.push_back(hint.rfind("one of these:", 0) == 0 ? "looks like a known mistake, " + hint
                                                                : "looks like a known mistake: " + hint);
  }
  for (const auto& l : lines)  // the pictures a failing test left (common/judge/picture.hpp)
    if (const auto at = l.find("picture: "); at != std::string::npos && l.find_first_not_of(' ') == at)
      d.details.push_back(l.substr(at));
  return d;
}

}  // namespace wb::test
