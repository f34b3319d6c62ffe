#include "common/shell/presenter.hpp"

#include "common/base/error.hpp"
#include "common/base/settings.hpp"
#include "common/base/strf.hpp"
#include "common/platform/shader.hpp"
#include "common/truth/measurement.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

namespace wb {
namespace {

// A setting's value as demo.json may write it: "5", 5, 0.5 or true all mean what --set means.
std::string valueText(const nlohmann::ordered_json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number()) return v.dump();
  throw std::runtime_error("a setting's value must be a string, a number or true/false, not " + v.dump());
}

DemoStep readStep(const nlohmann::ordered_json& s, const std::vector<std::string>& common) {
  DemoStep d;
  d.title = s.at("title").get<std::string>();
  d.caption = s.at("caption").get<std::string>();
  d.sets = common;
  const nlohmann::ordered_json sets = s.value("settings", nlohmann::ordered_json::object());
  for (const auto& [key, value] : sets.items()) d.sets.push_back(key + "=" + valueText(value));
  d.bookmark = s.value("bookmark", 0);
  if (s.contains("compare")) {
    const auto& c = s.at("compare");
    d.compare = {true, c.at("key").get<std::string>(), valueText(c.at("a")), valueText(c.at("b"))};
  }
  d.measure = s.value("measure", false);
  return d;
}

// The bitmap fallback (no TTF font found) draws ASCII: the few other characters captions use are
// spelled out.
std::string ascii(const std::string& text) {
  static const std::pair<const char*, const char*> kSpelled[] = {
      {"\xC2\xB0", " deg"},   {"\xC3\x97", "x"},      {"\xE2\x80\x94", " - "}, {"\xE2\x80\x93", "-"},
      {"\xE2\x80\x99", "'"},  {"\xCE\xBB", "lambda"}, {"\xE2\x89\x88", "~"},   {"\xE2\x86\x92", "->"},
      {"\xE2\x80\x9C", "\""}, {"\xE2\x80\x9D", "\""}, {"\xC2\xB2", "^2"},      {"\xCF\x83", "sigma"}};
  std::string out;
  for (size_t i = 0; i < text.size();) {
    bool done = false;
    for (const auto& [from, to] : kSpelled)
      if (text.compare(i, std::char_traits<char>::length(from), from) == 0) {
        out += to, i += std::char_traits<char>::length(from), done = true;
        break;
      }
    if (done) continue;
    const unsigned char c = static_cast<unsigned char>(text[i++]);
    if (c < 0x80) {
      out += char(c);
    } else if (c >= 0xC0) {  // the first byte of another character: one '?' for it
      out += '?';
    }
  }
  return out;
}

// Greedy word wrap at `scale` into lines at most `pixels` wide.
std::vector<std::string> wrap(Label& label, const std::string& text, int pixels, float scale) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string line;
  for (std::string w; words >> w;) {
    const std::string longer = line.empty() ? w : line + " " + w;
    if (!line.empty() && label.scaleToFit(longer, pixels, 1e9f) < scale) {
      lines.push_back(line), line = w;
    } else {
      line = longer;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

std::vector<DemoStep> loadDemo(const std::filesystem::path& file) {
  nlohmann::ordered_json j;  // (settings apply in the order written: a technique before its own settings)
  try {
    j = nlohmann::ordered_json::parse(readFile(file));
  } catch (const std::exception& e) {
    throw UsageError("cannot read the demo " + file.string() + ": " + e.what());
  }
  std::vector<DemoStep> steps;
  size_t k = 0;
  try {
    std::vector<std::string> common;
    const nlohmann::ordered_json sets = j.value("settings", nlohmann::ordered_json::object());
    for (const auto& [key, value] : sets.items()) common.push_back(key + "=" + valueText(value));
    for (const auto& s : j.at("steps")) ++k, steps.push_back(readStep(s, common));
  } catch (const std::exception& e) {
    throw UsageError(
        file.string() + (k ? ", step " + std::to_string(k) : std::string()) + ": " + e.what() +
        " (a step has title, caption, settings, bookmark, and optionally compare, measure, clip and same_picture)");
  }
  if (steps.empty()) throw UsageError(file.string() + " has no steps");
  return steps;
}

Presenter::Presenter(const std::filesystem::path& file, const Settings& settings) : steps_(loadDemo(file)) {
  for (const auto& s : settings.all()) start_.emplace_back(s.name, settings.value(s.name));
}

const DemoStep& Presenter::apply(int k, Settings& settings) const {
  if (k < 1 || k > count())
    throw UsageError("--demo-step " + std::to_string(k) + ": the demo has steps 1 to " + std::to_string(count()));
  for (const auto& [name, value] : start_) {
    try {
      settings.assign(name + "=" + value);
    } catch (const UsageError&) {  // (the showcase's list follows its technique: not every name is there)
    }
  }
  const DemoStep& s = step(k);
  for (const auto& a : s.sets) {
    try {
      settings.assign(a);
    } catch (const UsageError& e) {
      throw UsageError("demo step " + std::to_string(k) + " (\"" + s.title + "\"): " + e.what());
    }
  }
  return s;
}

// The band holds the title, two lines of caption and the numbers, at 30-pixel captions for 1080 rows.
int Presenter::bandHeight(glm::ivec2 size, float pixelsPerPoint) {
  return std::max(int(72 * pixelsPerPoint), size.y * 18 / 100);
}

float Presenter::captionPixels(glm::ivec2 size, float pixelsPerPoint) {
  return std::max(10.0f * pixelsPerPoint, 30.0f * float(size.y) / 1080.0f);
}

void Presenter::drawBand(int k, const std::string& numbers, glm::ivec2 size, float pixelsPerPoint) {
  const DemoStep& s = step(k);
  const int band = bandHeight(size, pixelsPerPoint), margin = std::max(int(8 * pixelsPerPoint), size.x / 80);
  glEnable(GL_SCISSOR_TEST);  // the band is dark, whatever was there
  glScissor(0, 0, size.x, band);
  const float dark[4] = {0.08f, 0.08f, 0.09f, 1};
  glClearBufferfv(GL_COLOR, 0, dark);
  glDisable(GL_SCISSOR_TEST);
  // Sizes follow the window's height (captionPixels); a Label's font is 10 pixels at scale 1.
  const float unit = captionPixels(size, pixelsPerPoint) / 30.0f;
  auto text = [&](const std::string& t) { return label_.hasFont() ? t : ascii(t); };
  const int width = size.x - 2 * margin;
  const std::string title = strf("%d/%d  ", k, count()) + text(s.title);
  const float titleScale = std::min(unit * 3.4f, label_.scaleToFit(title, width, 1e9f));
  int y = size.y - band + margin / 2;
  label_.draw(title, {margin, y}, size, titleScale);
  y += int(15 * titleScale);
  const float captionScale = unit * 3.0f;
  for (const auto& line : wrap(label_, text(s.caption), width, captionScale)) {
    label_.draw(line, {margin, y}, size, std::min(captionScale, label_.scaleToFit(line, width, 1e9f)));
    y += int(15 * captionScale);
  }
  if (!numbers.empty())
    label_.draw(numbers, {margin, y}, size, std::min(unit * 2.8f, label_.scaleToFit(numbers, width, 1e9f)));
}

std::string Presenter::numbersLine(const MeasureResult& r) {
  if (!r.ownMeasure.empty()) return "measured: " + r.ownMeasure;  // (a frame that holds a lab's own measure)
  if (r.todoPixels > 0) return "not measured: an exercise this frame needs is unfinished";
  if (!r.halves.empty()) {  // split screen: each half on its own
    std::string out;
    for (size_t side = 0; side < r.halves.size(); ++side) {
      const MeasureResult::Half& h = r.halves[side];
      out += strf("%s%s %s: acne %.2f%%, leak %.2f%%", side ? "   |   " : "", side ? "right" : "left ",
                  h.setting.c_str(), 100 * h.metrics.acneRate(), 100 * h.metrics.leakRate());
      if (h.reference.pixels > 0) out += strf(", lighter than PCF %.2f%%", 100 * h.reference.lighterRate());
    }
    return "measured: " + out;
  }
  std::string out = strf("measured: acne %.2f%%, leak %.2f%%", 100 * r.metrics.acneRate(), 100 * r.metrics.leakRate());
  if (r.gapTexels >= 0) out += strf(", contact gap %.1f texels", r.gapTexels);
  if (r.reference.pixels > 0) out += strf(", lighter than PCF %.1f%%", 100 * r.reference.lighterRate());
  if (r.area.pixels > 0) out += strf(", off the area light %.1f%%", 100 * r.area.meanAbs());
  if (r.seams.seam.pixels > 0)
    out += strf(", error at the seams %.2f%% (elsewhere %.2f%%)", 100 * r.seams.seam.meanAbs(),
                100 * r.seams.rest.meanAbs());
  return out;
}

}  // namespace wb
