#include "common/platform/shader_log.hpp"

#include "common/base/variant.hpp"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace wb {

std::string firstErrorLine(const std::string& message) {
  std::string line = message.substr(0, message.find('\n'));
  if (const auto at = message.find(": error"); at != std::string::npos) {
    const size_t begin = message.rfind('\n', at) == std::string::npos ? 0 : message.rfind('\n', at) + 1;
    line = message.substr(begin, message.find('\n', at) - begin);
  }
  // labs/03_pcf/shaders/exercise.glsl:14, not the checkout's absolute path: short enough to read.
  if (const std::string root = std::string(variant::kSourceDir) + "/"; line.rfind(root, 0) == 0)
    line = line.substr(root.size());
  return line;
}

namespace {

// Line `line` (1-based) of `file`, or "" when it cannot be read.
std::string lineOf(const fs::path& file, int line) {
  std::ifstream in(file);
  std::string s;
  for (int k = 0; k < line && std::getline(in, s);) ++k;
  return in ? s : "";
}

// Mesa names some errors inside an included file by the top file's source number, with the right
// line ("0:26(10): error: `zReceiverr' undeclared" for exercise.glsl:26). When a message quotes a
// name that the named file's line does not hold, and exactly one other file's same line does, that
// file is meant.
size_t fileQuoted(const std::string& message, size_t file, int line, const std::vector<fs::path>& files) {
  static const std::regex quoted(R"([`'"]([A-Za-z_]\w*)['"])");
  std::smatch m;
  if (!std::regex_search(message, m, quoted) || lineOf(files[file], line).find(m[1].str()) != std::string::npos)
    return file;
  size_t found = file, count = 0;
  for (size_t k = 0; k < files.size(); ++k)
    if (k != file && lineOf(files[k], line).find(m[1].str()) != std::string::npos) found = k, ++count;
  return count == 1 ? found : file;
}

}  // namespace

std::string mapShaderLog(const std::string& log, const std::vector<fs::path>& files,
                         const std::map<int, std::string>& unquoted) {
  // Where a line names a position, by vendor: Mesa "2:14(3): error: ...", NVIDIA "2(14) : error C0000:
  // ...", and glslang's form, which AMD, Intel on Windows and Apple print too, "ERROR: 2:14: ...". Each
  // becomes "file:14: error...", so that every reader sees one form (tests/framework/fixtures/
  // compiler_logs/ holds each vendor's lines).
  static const std::regex posRe(R"(^\s*(?:(ERROR|WARNING):\s*(\d+):(\d+)|(\d+):(\d+)\(\d+\)|(\d+)\((\d+)\))\s*:\s*)");
  std::map<std::pair<size_t, int>, size_t> meant;  // (source, line) -> the file a quoted name showed
  std::string out;
  std::istringstream in(log);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_search(s, m, posRe)) {
      const int at = m[2].matched ? 2 : m[4].matched ? 4 : 6;  // the source number's group; the line's next
      size_t file = std::stoul(m[at].str());
      const std::string line = m[at + 1].str();
      const std::string rest =
          (m[1].matched ? (m[1].str() == "ERROR" ? "error: " : "warning: ") : "") + m.suffix().str();
      if (const auto said = file < (1u << 30) ? unquoted.find(int(file)) : unquoted.end(); said != unquoted.end()) {
        s = said->second;
      } else if (file < files.size()) {
        const auto key = std::make_pair(file, std::stoi(line));
        if (!meant.count(key)) meant[key] = fileQuoted(rest, file, key.second, files);
        file = meant[key];
        s = files[file].string() + ":" + line + ": " + rest;
      }
    }
    out += s + "\n";
  }
  return out;
}

std::string logAsVendor(const std::string& log) {
  const char* as = std::getenv("WB_SHADER_LOG_AS");
  if (!as || (std::string(as) != "nvidia" && std::string(as) != "glslang")) return log;
  const bool nvidia = std::string(as) == "nvidia";
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\): (error|warning): (.*)$)");
  std::set<std::string> sources;
  std::string body, lead;
  std::istringstream in(log);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_match(s, m, mesa)) {
      sources.insert(m[1].str());
      s = nvidia ? m[1].str() + "(" + m[2].str() + ") : " + m[3].str() + " C0000: " + m[4].str()
                 : std::string(m[3].str() == "error" ? "ERROR: " : "WARNING: ") + m[1].str() + ":" + m[2].str() + ": " +
                       m[4].str();
    }
    body += s + "\n";
  }
  for (const auto& source : sources)
    lead += nvidia ? source + "(1) : error C1108: function has no statements\n"
                   : "ERROR: " + source + ":1: '' : compilation terminated\n";
  return lead + body;
}

}  // namespace wb
