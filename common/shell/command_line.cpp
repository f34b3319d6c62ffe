#include "common/shell/command_line.hpp"

#include "common/base/error.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace wb {
namespace {

// The one table: name, the value's placeholder (nullptr for a flag), help, and what it does.
struct OptionSpec {
  const char* name;
  const char* value;
  const char* help;
  void (*apply)(Options&, const std::string&);
};

glm::ivec2 parseSize(const std::string& v) {
  glm::ivec2 s{0};
  char x = 0, extra = 0;
  std::istringstream in(v);
  if (!(in >> s.x >> x >> s.y) || x != 'x' || in >> extra || s.x < 16 || s.y < 16 || s.x > 8192 || s.y > 8192)
    throw UsageError("bad --size '" + v + "': expected WxH between 16x16 and 8192x8192, e.g. 960x540");
  return s;
}

int parseCount(const char* option, const std::string& v) {
  try {
    size_t used = 0;
    const int n = std::stoi(v, &used);
    if (used == v.size() && n >= 1) return n;
  } catch (...) {
  }
  throw UsageError(std::string("bad ") + option + " '" + v + "': expected a whole number of at least 1");
}

long long parseSeed(const std::string& v) {
  try {
    size_t used = 0;
    const long long n = std::stoll(v, &used);
    if (used == v.size() && n >= 0 && n <= 0xFFFFFFFFll) return n;
  } catch (...) {
  }
  throw UsageError("bad --vary '" + v + "': expected a whole number from 0 to 4294967295");
}

std::string imagePath(const char* option, const std::string& v) {
  std::string ext = v.size() >= 4 ? v.substr(v.size() - 4) : "";
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png" && ext != ".jpg" && (v.size() < 5 || v.substr(v.size() - 5) != ".jpeg"))
    throw UsageError(std::string("bad ") + option + " '" + v + "': name a .png or .jpg file, e.g. shot.png");
  return v;
}

std::pair<std::string, std::vector<std::string>> parseSweep(const std::string& v) {
  const auto eq = v.find('=');
  if (eq == std::string::npos || eq + 1 >= v.size()) throw UsageError("--sweep expects key=v1,v2,..., got '" + v + "'");
  std::vector<std::string> values;
  std::stringstream list(v.substr(eq + 1));
  for (std::string item; std::getline(list, item, ',');) values.push_back(item);
  return {v.substr(0, eq), values};
}

CompareChoice parseCompare(const std::string& v) {
  const auto eq = v.find('='), comma = v.find(',', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || comma == std::string::npos || v.find(',', comma + 1) != std::string::npos)
    throw UsageError("--compare expects key=a,b (two values of one setting), got '" + v + "'");
  return {true, v.substr(0, eq), v.substr(eq + 1, comma - eq - 1), v.substr(comma + 1)};
}

const OptionSpec kOptions[] = {
    {"--headless", nullptr, "render without a window (EGL, Mesa llvmpipe); writes a PNG if no output is named",
     [](Options& o, const std::string&) { o.headless = true; }},
    {"--fullscreen", nullptr, "the window fills the primary monitor, at its resolution (F11 toggles it)",
     [](Options& o, const std::string&) { o.fullscreen = true; }},
    {"--scene", "FILE", "scene file (default %SCENE%)", [](Options& o, const std::string& v) { o.scene = v; }},
    {"--size", "WxH", "frame size in pixels (default 960x540)",
     [](Options& o, const std::string& v) { o.size = parseSize(v); }},
    {"--set", "key=value", "change a setting; --list-settings shows them all",
     [](Options& o, const std::string& v) { o.sets.push_back(v); }},
    {"--frames", "N", "frames to render before writing outputs and exiting",
     [](Options& o, const std::string& v) { o.frames = parseCount("--frames", v); }},
    {"--screenshot", "F.png", "write the final frame as PNG (or JPEG, for a name ending in .jpg)",
     [](Options& o, const std::string& v) { o.screenshot = imagePath("--screenshot", v); }},
    {"--dump-visibility", "F.pfm", "write per-pixel light visibility (1 lit, 0 shadowed) as a float PFM",
     [](Options& o, const std::string& v) { o.visibility = v; }},
    {"--bench", "F.csv", "time every pass (GPU ms) and the frame (wall ms) over the frames",
     [](Options& o, const std::string& v) { o.bench = v; }},
    {"--metrics", nullptr, "compare with exact (ray-cast) visibility: acne rate and light leak",
     [](Options& o, const std::string&) { o.metrics = true; }},
    {"--heatmap", "F.png", "with --metrics: write acne (red) and leaks (blue) as a picture",
     [](Options& o, const std::string& v) { o.heatmap = imagePath("--heatmap", v), o.metrics = true; }},
    {"--sweep", "key=a,b,...",
     "time every combination of the listed settings (repeatable; with --metrics also measure it)",
     [](Options& o, const std::string& v) { o.sweeps.push_back(parseSweep(v)); }},
    {"--sweep-csv", "F.csv", "with --sweep: also write the table as CSV",
     [](Options& o, const std::string& v) { o.sweepCsv = v; }},
    {"--record-video", "F.mp4",
     "render --frames frames (default 90) one by one into a video (.mp4, .webm or .gif; "
     "ffmpeg); with --animate and a split screen, motion side by side",
     [](Options& o, const std::string& v) { o.video = v; }},
    {"--animate", "key=a:b", "with --record-video: the setting goes from a to b over the frames (e.g. path.step=1:90)",
     [](Options& o, const std::string& v) { o.animate = v; }},
    {"--fps", "N", "with --record-video: frames per second (default 30)",
     [](Options& o, const std::string& v) { o.fps = parseCount("--fps", v); }},
    {"--show-flips", nullptr,
     "with --record-video: each frame (each half of a split screen) says the share of its pixels whose shadow "
     "changed since the frame before",
     [](Options& o, const std::string&) { o.showFlips = true; }},
    {"--rounds", "N", "with --sweep: time every row N times, in interleaved rounds (A B C A B C ...; default 5)",
     [](Options& o, const std::string& v) { o.rounds = parseCount("--rounds", v); }},
    {"--demo-step", "N",
     "presenter step N of the lab's demo.json: its settings, camera and split screen (in a window, Page Down/Up "
     "step on)",
     [](Options& o, const std::string& v) { o.demoStep = parseCount("--demo-step", v); }},
    {"--demo", "FILE", "the presenter's steps from FILE instead of the lab's demo.json (try an edited demo)",
     [](Options& o, const std::string& v) { o.demo = v; }},
    {"--compare", "key=a,b", "split screen: the left half with key=a, the right half with key=b",
     [](Options& o, const std::string& v) { o.compare = parseCompare(v); }},
    {"--record", "F.json", "write the run's result as JSON: exercise states, measurements, files written",
     [](Options& o, const std::string& v) { o.record = v; }},
    {"--record-exercises", "F.json", "write what each C++ exercise returned (the grader's runner)",
     [](Options& o, const std::string& v) { o.recordExercises = v; }},
    {"--replay-exercises", "F.json", "use the C++ exercise results in F instead of calling them (the grader's judge)",
     [](Options& o, const std::string& v) { o.replayExercises = v; }},
    {"--vary", "SEED", "turn the scene's lights and cameras a little, by a seed (grading-time variations)",
     [](Options& o, const std::string& v) { o.vary = parseSeed(v); }},
    {"--quiet", nullptr, "print nothing for people on stdout (warnings and errors still go to stderr)",
     [](Options& o, const std::string&) { o.quiet = true; }},
    {"--list-settings", nullptr, "print every setting with its value, range and help, and exit",
     [](Options& o, const std::string&) { o.listSettings = true; }},
    {"--help", nullptr, "print this text and exit", [](Options& o, const std::string&) { o.help = true; }},
};

std::string acceptedNames() {
  std::string names;
  for (const auto& o : kOptions) names += std::string(names.empty() ? "" : " ") + o.name;
  return names;
}

}  // namespace

Options parseCommandLine(int argc, const char* const* argv) {
  Options options;
  for (int a = 1; a < argc; ++a) {
    std::string arg = argv[a];
    if (arg == "-h") arg = "--help";
    const OptionSpec* spec = nullptr;
    for (const auto& o : kOptions)
      if (arg == o.name) spec = &o;
    if (!spec) throw UsageError("unknown option '" + arg + "'; accepted: " + acceptedNames());
    std::string value;
    if (spec->value) {
      if (a + 1 >= argc) throw UsageError(arg + " needs a value (" + spec->value + "); see --help");
      value = argv[++a];
    }
    spec->apply(options, value);
  }
  return options;
}

std::string usageText(const std::string& exe, const std::string& defaultScene) {
  std::string text = "usage: " + exe + " [options]\n";
  for (const auto& o : kOptions) {
    std::string left = std::string("  ") + o.name + (o.value ? std::string(" ") + o.value : "");
    std::string help = o.help;
    if (const auto at = help.find("%SCENE%"); at != std::string::npos) help.replace(at, 7, defaultScene);
    left.resize(std::max<size_t>(left.size() + 2, 30), ' ');
    text += left + help + "\n";
  }
  return text;
}

bool Options::names(const std::string& key) const {
  if (compare.on && compare.key == key) return true;
  for (const auto& s : sets)
    if (s.rfind(key + "=", 0) == 0) return true;
  return std::any_of(sweeps.begin(), sweeps.end(), [&](const auto& sweep) { return sweep.first == key; });
}

}  // namespace wb
