#include "common/judge/check_page.hpp"

#include "common/base/variant.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;

namespace wb::test {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= unsigned(static_cast<unsigned char>(bytes[i + 2]));
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

// A detail line as HTML: a picture inside the page (or its path, where it cannot be read), else text.
std::string detail(const std::string& line) {
  if (line.rfind("picture: ", 0) != 0) return "<div class=d>" + escaped(line) + "</div>\n";
  // "picture: PATH" or "picture: PATH (caption)": a path may hold spaces, so the caption is what the
  // last " (" starts, where the line ends with ")"
  const std::string rest = line.substr(9);
  const size_t open = rest.size() && rest.back() == ')' ? rest.rfind(" (") : std::string::npos;
  const std::string path = rest.substr(0, open), caption = open == std::string::npos ? "" : rest.substr(open + 1);
  // (check shows paths under the checkout as relative ones: they are read from there)
  const fs::path file = fs::path(path).is_absolute() ? fs::path(path) : fs::path(variant::kSourceDir) / path;
  std::ifstream in(file, std::ios::binary);
  const std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (png.empty()) return "<div class=d>picture not found: " + escaped(path) + "</div>\n";
  return "<figure><img src=\"data:image/png;base64," + base64(png) + "\" alt=\"" + escaped(path) + "\"><figcaption>" +
         escaped(caption) + " <span class=p>" + escaped(path) + "</span></figcaption></figure>\n";
}

const char* kStyle =
    "body{font-family:DejaVu Sans,Helvetica,Arial,sans-serif;margin:2em;max-width:70em;color:#222}"
    "table{border-collapse:collapse;width:100%}td{vertical-align:top;padding:.5em;border-top:1px solid #ddd}"
    ".s{font-weight:bold;white-space:nowrap}.wrong,.error{color:#b00}.ok{color:#070}.wait{color:#a60}"
    ".h{margin-bottom:.3em}.d{font-family:DejaVu Sans Mono,monospace;font-size:90%;white-space:pre-wrap}"
    "figure{margin:.5em 0}figcaption{font-size:80%}img{max-width:100%;border:1px solid "
    "#ccc}.p{color:#888;font-size:80%}";

}  // namespace

bool writeCheckPage(const fs::path& file, const std::string& heading, const std::vector<PageRow>& rows,
                    const std::string& summary) {
  std::ostringstream page;
  page << "<!doctype html>\n<html><head><meta charset=utf-8><title>" << escaped(heading) << "</title><style>" << kStyle
       << "</style></head><body>\n<h1>" << escaped(heading) << "</h1>\n<p>" << escaped(summary) << "</p>\n<table>\n";
  for (const auto& r : rows) {
    const std::string css = r.status == "wrong" || r.status == "error" ? r.status
                            : r.status == "passes its tests"           ? "ok"
                                                                       : "wait";
    page << "<tr><td class=s>" << escaped(r.id) << "</td><td class=\"s " << css << "\">" << escaped(r.status)
         << "</td><td><div class=h><b>" << escaped(r.title) << "</b></div>\n";
    if (!r.headline.empty()) page << "<div class=d>" << escaped(r.headline) << "</div>\n";
    for (const auto& line : r.details) page << detail(line);
    if (!r.where.empty()) page << "<div class=d>your code: " << escaped(r.where) << "</div>\n";
    page << "</td></tr>\n";
  }
  page << "</table>\n</body></html>\n";
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  std::ofstream out(file);
  out << page.str();
  return bool(out);
}

}  // namespace wb::test
