#include "common/exercise/exercise_chunks.hpp"

#include "common/base/error.hpp"
#include "common/platform/shader.hpp"

#include <algorithm>

namespace wb {

size_t findMarker(const std::string& text, const std::string& id) {
  const std::string marker = "// EXERCISE " + id;
  for (size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + 1)) {
    const size_t after = at + marker.size();
    if (after == text.size() || std::string(" \t\r\n:").find(text[after]) != std::string::npos) return at;
  }
  return std::string::npos;
}

std::pair<size_t, size_t> chunkRange(const std::string& text, const std::string& id) {
  const std::string marker = "// EXERCISE " + id;
  size_t begin = findMarker(text, id);
  if (begin == std::string::npos) throw Error("no '" + marker + "' marker in the exercise file");
  begin = text.rfind('\n', begin) == std::string::npos ? 0 : text.rfind('\n', begin) + 1;
  size_t end = text.find("// EXERCISE ", begin + marker.size());
  end = end == std::string::npos ? text.size() : text.rfind('\n', end) + 1;
  return {begin, end};
}

bool chunkIsStub(const std::string& text, const std::string& id) {
  if (findMarker(text, id) == std::string::npos) return false;
  const auto [begin, end] = chunkRange(text, id);
  return text.find("WB_TODO", begin) < end;
}

std::vector<std::pair<std::string, std::string>> splitChunks(const std::string& text) {
  std::vector<size_t> starts;  // the first character of every marker's line
  for (size_t p = text.find("// EXERCISE "); p != std::string::npos; p = text.find("// EXERCISE ", p + 12)) {
    const size_t start = p == 0 || text.rfind('\n', p) == std::string::npos ? 0 : text.rfind('\n', p) + 1;
    if (starts.empty() || start != starts.back()) starts.push_back(start);
  }
  std::vector<std::pair<std::string, std::string>> chunks;
  const size_t first = starts.empty() ? text.size() : starts[0];
  if (first > 0) chunks.emplace_back("", text.substr(0, first));
  for (size_t k = 0; k < starts.size(); ++k) {
    const size_t end = k + 1 < starts.size() ? starts[k + 1] : text.size();
    const size_t id = text.find("// EXERCISE ", starts[k]) + 12;
    chunks.emplace_back(text.substr(id, text.find_first_of(" \t\r\n:", id) - id),
                        text.substr(starts[k], end - starts[k]));
  }
  return chunks;
}

std::set<std::string> changedChunks(const std::string& before, const std::string& after) {
  const auto a = splitChunks(before), b = splitChunks(after);
  std::set<std::string> changed;
  for (const auto& [id, text] : a) {
    const auto same = std::find_if(b.begin(), b.end(), [&wanted = id](const auto& c) { return c.first == wanted; });
    if (same == b.end() || same->second != text) changed.insert(id);
  }
  for (const auto& [id, text] : b)
    if (std::none_of(a.begin(), a.end(), [&wanted = id](const auto& c) { return c.first == wanted; }))
      changed.insert(id);
  return changed;
}

// The number of lines `text` ends, i.e. its '\n's.
static size_t lineCount(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

std::string withChunksFrom(const std::string& current, const std::string& lastGood, const std::set<std::string>& ids) {
  // "#line N" numbers the line after it: a chunk that has `before` lines above it starts on before + 1.
  auto lineDirective = [](size_t before) {
    return "#line " + std::to_string(before + 1) + " " + std::to_string(kThisFileSource) + "\n";
  };
  const auto good = splitChunks(lastGood);
  std::vector<size_t> goodBefore;  // the lines above each good chunk
  size_t lines = 0;
  for (const auto& chunk : good) goodBefore.push_back(lines), lines += lineCount(chunk.second);
  std::string out;
  size_t before = 0;  // the lines above the current chunk at hand
  bool swapped = false;
  for (const auto& [id, text] : splitChunks(current)) {
    const auto g = std::find_if(good.begin(), good.end(), [&wanted = id](const auto& c) { return c.first == wanted; });
    if (ids.count(id) && g != good.end()) {
      // (None before the preamble: it may hold #version, which must come first, and starts on line 1.)
      if (!id.empty()) out += lineDirective(goodBefore[size_t(g - good.begin())]);
      out += g->second;
      if (out.back() != '\n') out += "\n";
      swapped = true;
    } else {
      if (swapped) out += lineDirective(before);
      out += text;
      swapped = false;
    }
    before += lineCount(text);
  }
  return out;
}

// The exercise chunks of `mine` the stub has too (only those can be swapped), by ids of an exercise's
// shape: "// EXERCISE 08.x" quoted in a comment above the first marker is no exercise.
static std::set<std::string> swappable(const std::string& mine, const std::string& stub) {
  auto isId = [](const std::string& id) { return !id.empty() && id.find_first_not_of("0123456789.xH") == id.npos; };
  std::set<std::string> ids;
  for (const auto& chunk : splitChunks(mine))
    if (isId(chunk.first) && findMarker(stub, chunk.first) != std::string::npos) ids.insert(chunk.first);
  return ids;
}

std::string chunkAlone(const std::string& mine, const std::string& stub, const std::string& id) {
  std::set<std::string> others = swappable(mine, stub);
  others.erase(id);
  return withChunksFrom(mine, stub, others);
}

std::set<std::string> chunksThatDoNotCompile(const std::string& mine, const std::string& stub,
                                             const CompilesFn& compiles) {
  std::set<std::string> broken;
  for (const auto& id : swappable(mine, stub))
    if (!compiles(chunkAlone(mine, stub, id))) broken.insert(id);
  if (broken.empty() || !compiles(withChunksFrom(mine, stub, broken))) return {};
  return broken;
}

namespace {
const char* const kCulpritWords = "GLSL that does not compile (found by compiling each exercise alone): exercise ";
}  // namespace

std::string culpritLine(const std::set<std::string>& ids) {
  std::string line = kCulpritWords;
  for (const auto& id : ids) line += (&id == &*ids.begin() ? "" : ", ") + id;
  return line;
}

std::set<std::string> culpritsIn(const std::string& log) {
  std::set<std::string> ids;
  // Only at a line's start, or after the program's name ("lab01: "): never inside a compiler's
  // message, which may quote a student's text (an #error with these words).
  size_t at = log.find(kCulpritWords);
  for (; at != std::string::npos; at = log.find(kCulpritWords, at + 1)) {
    const size_t line = log.rfind('\n', at) == std::string::npos ? 0 : log.rfind('\n', at) + 1;
    const std::string before = log.substr(line, at - line);
    if (before.empty() || (before.size() > 2 && before.compare(before.size() - 2, 2, ": ") == 0 &&
                           before.find_first_of(" :") == before.size() - 2))
      break;
  }
  if (at == std::string::npos) return ids;
  const size_t from = at + std::string(kCulpritWords).size();
  std::string list = log.substr(from, log.find('\n', from) - from);
  for (size_t p = 0; p < list.size();) {
    const size_t comma = list.find(", ", p);
    ids.insert(list.substr(p, comma == std::string::npos ? std::string::npos : comma - p));
    p = comma == std::string::npos ? list.size() : comma + 2;
  }
  return ids;
}

}  // namespace wb
