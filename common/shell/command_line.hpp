/// @file command_line.hpp
/// The lab command line every lab shares. One table of options feeds the parser, the usage text
/// and the error messages, so the three cannot disagree.
#pragma once
#include <glm/vec2.hpp>

#include <string>
#include <utility>
#include <vector>

namespace wb {

/// One setting's two values shown side by side (--compare key=a,b, or the Settings window).
struct CompareChoice {
  bool on = false;  ///< split screen on
  std::string key;  ///< the setting compared
  std::string a;    ///< its value in the left half
  std::string b;    ///< its value in the right half
};

/// Everything the command line can ask for.
struct Options {
  bool help = false;              ///< --help: print the usage and exit
  bool headless = false;          ///< --headless: EGL, no window
  bool fullscreen = false;        ///< --fullscreen: the window fills the primary monitor (F11 toggles)
  bool listSettings = false;      ///< --list-settings: print the settings and exit
  bool metrics = false;           ///< --metrics: measure against exact visibility
  bool quiet = false;             ///< --quiet: no human-readable text on stdout
  std::string scene;              ///< --scene FILE ("" = the lab's default)
  std::string screenshot;         ///< --screenshot F.png
  std::string visibility;         ///< --dump-visibility F.pfm
  std::string bench;              ///< --bench F.csv
  std::string heatmap;            ///< --heatmap F.png (implies --metrics)
  std::string record;             ///< --record F.json: the machine-readable result of the run
  std::string recordExercises;    ///< --record-exercises F.json: what the C++ exercises returned
  std::string replayExercises;    ///< --replay-exercises F.json: use those results instead
  long long vary = -1;            ///< --vary SEED: perturb the scene's lights and cameras (-1: no)
  std::string sweepCsv;           ///< --sweep-csv F.csv
  int rounds = 5;                 ///< --rounds N: a sweep times every row N times, interleaved
  std::string video;              ///< --record-video F.mp4|.webm|.gif
  std::string animate;            ///< --animate key=a:b: a setting from a to b over the frames
  int fps = 30;                   ///< --fps N: the video's frame rate
  bool showFlips = false;         ///< --show-flips: each frame says how much of its shadow changed
  glm::ivec2 size{960, 540};      ///< --size WxH
  int frames = -1;                ///< --frames N (-1: until the window closes; headless 1, bench 60)
  int demoStep = 0;               ///< --demo-step N: presenter step N of demo.json (0: none)
  std::string demo;               ///< --demo FILE: the presenter's steps instead of the lab's demo.json
  std::vector<std::string> sets;  ///< --set key=value, in order
  std::vector<std::pair<std::string, std::vector<std::string>>> sweeps;  ///< --sweep key=a,b,...
  CompareChoice compare;                                                 ///< --compare key=a,b
  /// True if --set, --sweep or --compare names setting `key`.
  bool names(const std::string& key) const;
};

/// Parses the arguments after argv[0]; throws wb::UsageError naming the bad argument and what is
/// accepted.
Options parseCommandLine(int argc, const char* const* argv);

/// The usage text, one line per option, from the same table the parser reads.
std::string usageText(const std::string& exe, const std::string& defaultScene);

}  // namespace wb
