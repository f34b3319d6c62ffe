#include "common/exercise/exercise_chunks.hpp"

#include "common/base/error.hpp"
#include "common/platform/shader.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

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

bool isExerciseId(const std::string& id) {
  return !id.empty() && id.find_first_not_of("0123456789.xH") == std::string::npos;
}

// The names of the functions `chunk` defines: a name, its parameters, then a body's "{".
std::vector<std::string> definedFunctions(const std::string& chunk) {
  static const std::regex definition(R"(\b([A-Za-z_]\w*)\s*\([^;{}()]*(\([^;{}()]*\)[^;{}()]*)*\)\s*(const\s*)?\{)");
  std::vector<std::string> names;
  for (auto m = std::sregex_iterator(chunk.begin(), chunk.end(), definition); m != std::sregex_iterator(); ++m)
    if (const std::string name = (*m)[1]; name != "if" && name != "for" && name != "while" && name != "switch")
      names.push_back(name);
  return names;
}

// Where the file's last non-blank line begins when it closes a namespace ("}  // namespace lab01"), or
// npos. (No std::regex over a student's file: libstdc++'s recursion overflows the stack on long text.)
size_t namespaceClose(const std::string& text) {
  const size_t last = text.find_last_not_of(" \t\r\n");
  if (last == std::string::npos) return std::string::npos;
  const size_t begin = text.rfind('\n', last) == std::string::npos ? 0 : text.rfind('\n', last) + 1;
  const std::string line = text.substr(begin, last + 1 - begin);
  const size_t slashes = line.find("//"), word = line.find_first_not_of(" \t/", slashes);
  const bool closes = line[0] == '}' && slashes != std::string::npos && line.find_first_not_of(" \t", 1) == slashes &&
                      word != std::string::npos && line.compare(word, 9, "namespace") == 0;
  return closes ? begin : std::string::npos;
}

// Whether `text` defines a function `name`: the name, a balanced "(...)", then (after blanks and a
// "const") a body's "{". A scan, not a std::regex (see namespaceClose).
bool definesFunction(const std::string& text, const std::string& name) {
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    if ((at > 0 && word(text[at - 1])) || (at + name.size() < text.size() && word(text[at + name.size()]))) continue;
    size_t p = text.find_first_not_of(" \t\r\n", at + name.size());
    if (p == std::string::npos || text[p] != '(') continue;
    int depth = 0;
    for (; p < text.size(); ++p) {
      if (text[p] == ';' || text[p] == '{' || text[p] == '}') break;
      depth += text[p] == '(' ? 1 : text[p] == ')' ? -1 : 0;
      if (depth == 0) break;
    }
    if (p >= text.size() || depth != 0) continue;
    p = text.find_first_not_of(" \t\r\n", p + 1);
    if (p != std::string::npos && text.compare(p, 5, "const") == 0) p = text.find_first_not_of(" \t\r\n", p + 5);
    if (p != std::string::npos && text[p] == '{') return true;
  }
  return false;
}

}  // namespace

FilledChunks fillMissingChunks(const std::string& mine, const std::string& stub) {
  FilledChunks out{mine, {}};
  const auto stubChunks = splitChunks(stub);
  for (size_t k = 0; k < stubChunks.size(); ++k) {
    const auto& [id, text] = stubChunks[k];
    if (!isExerciseId(id) || findMarker(stub, id) != stub.find("// EXERCISE " + id)) continue;
    if (findMarker(out.text, id) != std::string::npos) continue;
    const std::vector<std::string> names = definedFunctions(text);
    const bool defined = std::any_of(names.begin(), names.end(),
                                     [&](const std::string& name) { return definesFunction(out.text, name); });
    if (defined) continue;     // its marker was deleted, its code kept: not an earlier edition's file
    std::string chunk = text;  // without the stub's own closing of the namespace, if it is the last
    if (const size_t close = namespaceClose(chunk); close != std::string::npos) chunk.erase(close);
    while (chunk.size() > 1 && chunk.back() == '\n' && chunk[chunk.size() - 2] == '\n') chunk.pop_back();
    if (chunk.empty() || chunk.back() != '\n') chunk += "\n";
    size_t at = std::string::npos;
    for (size_t next = k + 1; next < stubChunks.size() && at == std::string::npos; ++next)
      if (isExerciseId(stubChunks[next].first) && findMarker(out.text, stubChunks[next].first) != std::string::npos)
        at = chunkRange(out.text, stubChunks[next].first).first;
    if (at == std::string::npos) at = namespaceClose(out.text);
    if (at == std::string::npos) {
      if (!out.text.empty() && out.text.back() != '\n') out.text += "\n";
      at = out.text.size();
    }
    // (one blank line between it and what it is put beside)
    const bool atEnd = at == out.text.size(), blankBefore = at >= 2 && out.text.compare(at - 2, 2, "\n\n") == 0;
    out.text.insert(at, (atEnd && !blankBefore ? "\n" : "") + chunk + (atEnd ? "" : "\n"));
    out.added.push_back(id);
  }
  return out;
}

std::string filledChunkLine(const std::string& file, const std::string& id, const std::string& stubPath, bool inPlace) {
  const std::string what = file + " predates exercise " + id + " (it has no '// EXERCISE " + id + "' marker): ";
  return what + (inPlace ? "check put its stub into the file, from " + stubPath + "; " + id + " is yours to do"
                         : "its stub was graded in its place (not done yet); copy its chunk from " + stubPath +
                               " into your file to do it");
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
