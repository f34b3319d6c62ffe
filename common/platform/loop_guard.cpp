#include "common/platform/loop_guard.hpp"

#include <cctype>

namespace wb {
namespace {

bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Skips a comment starting at `k`, if one does: the index after it.
size_t skipComment(const std::string& t, size_t k) {
  if (t.compare(k, 2, "//") == 0) {
    const size_t end = t.find('\n', k);
    return end == std::string::npos ? t.size() : end;
  }
  if (t.compare(k, 2, "/*") == 0) {
    const size_t end = t.find("*/", k + 2);
    return end == std::string::npos ? t.size() : end + 2;
  }
  return k;
}

// The index of the ')' that closes the '(' at `open`, or npos.
size_t closingParen(const std::string& t, size_t open) {
  int depth = 0;
  for (size_t k = open; k < t.size(); ++k) {
    if (const size_t after = skipComment(t, k); after != k) {
      k = after - 1;
      continue;
    }
    if (t[k] == '(') ++depth;
    if (t[k] == ')' && --depth == 0) return k;
  }
  return std::string::npos;
}

std::string wrapped(const std::string& condition) {
  const bool blank = condition.find_first_not_of(" \t\n") == std::string::npos;
  return "wb_loop(" + (blank ? std::string("true") : condition) + ")" + (blank ? condition : "");
}

// The header of a `for` (between its parentheses) with its condition wrapped.
std::string guardedFor(const std::string& header) {
  int depth = 0;
  size_t first = std::string::npos, second = std::string::npos;
  for (size_t k = 0; k < header.size(); ++k) {
    if (header[k] == '(') ++depth;
    if (header[k] == ')') --depth;
    if (header[k] == ';' && depth == 0) (first == std::string::npos ? first : second) = k;
    if (second != std::string::npos) break;
  }
  if (second == std::string::npos) return header;  // (not a loop the compiler would take: its error stays)
  return header.substr(0, first + 1) + wrapped(header.substr(first + 1, second - first - 1)) + header.substr(second);
}

}  // namespace

std::string guardLoops(const std::string& text) {
  std::string out;
  out.reserve(text.size() + 256);
  bool lineStart = true;
  for (size_t k = 0; k < text.size();) {
    const char c = text[k];
    if (lineStart && c == '#') {  // a preprocessor line, as it is
      const size_t end = text.find('\n', k);
      out += text.substr(k, end == std::string::npos ? std::string::npos : end - k);
      k = end == std::string::npos ? text.size() : end;
      continue;
    }
    if (const size_t after = skipComment(text, k); after != k) {
      out += text.substr(k, after - k);
      k = after;
      continue;
    }
    if (c == '\n') lineStart = true;
    if (c != ' ' && c != '\t' && c != '\n') lineStart = false;
    const bool wordStart = k == 0 || !identChar(text[k - 1]);
    const size_t word = text.compare(k, 3, "for") == 0 ? 3 : text.compare(k, 5, "while") == 0 ? 5 : 0;
    if (wordStart && word && (k + word >= text.size() || !identChar(text[k + word]))) {
      const size_t open = text.find_first_not_of(" \t\n", k + word);
      const size_t close =
          open != std::string::npos && text[open] == '(' ? closingParen(text, open) : std::string::npos;
      if (close != std::string::npos) {
        const std::string inside = text.substr(open + 1, close - open - 1);
        out += text.substr(k, open + 1 - k) + (word == 3 ? guardedFor(inside) : wrapped(inside)) + ")";
        k = close + 1;
        continue;
      }
    }
    out += c;
    ++k;
  }
  return out;
}

std::string loopGuardPrelude() {
  return "#ifndef WB_LOOP_GUARD\n#define WB_LOOP_GUARD\nint wb_loopSteps = 0;\n"
         "bool wb_loop(bool go) { return go && ++wb_loopSteps <= " +
         std::to_string(kLoopGuardSteps) + "; }\n#endif\n";
}

}  // namespace wb
