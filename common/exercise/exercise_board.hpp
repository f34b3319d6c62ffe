/// @file exercise_board.hpp
/// A lab's exercises as the running app knows them: the list from the lab's exercises.json (the one
/// list shared with the tests and the grader), each one's last observed state, and the GLSL probes
/// that ask a shader file whether its functions still return the stubs' WB_TODO.
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wb {

/// Where an exercise stands, as far as the running app can tell.
enum class ExerciseState { Unknown, Implemented, NotImplemented, Failed };

/// "unknown", "implemented", "not_implemented" or "failed": the JSON record's words.
const char* stateName(ExerciseState state);

/// One row of the info panel.
struct ExerciseStatus {
  std::string id;                                ///< "01.3"
  std::string title;                             ///< from the lab's exercises.json
  ExerciseState state = ExerciseState::Unknown;  ///< last observed state
  std::string message;                           ///< why it is not implemented or failed
  bool hunt = false;                             ///< a bug hunt ("kind": "hunt"): working code with a bug
};

/// The exercise list of one lab, with states and GLSL probes.
class ExerciseBoard {
 public:
  /// Reads `manifest` (labs/NN_name/exercises.json); a missing or malformed one leaves the list
  /// empty and prints a warning.
  explicit ExerciseBoard(const std::filesystem::path& manifest);
  /// The lab's two-digit number ("01"; "00" for a program that is not a lab, the showcase).
  const std::string& number() const { return number_; }
  /// "Lab 01: <title>", or the title alone for "00" (window titles, the info panel, --list-settings).
  std::string heading() const { return number_ == "00" ? title_ : "Lab " + number_ + ": " + title_; }
  /// The lab's folder name ("01_depth_map").
  const std::string& lab() const { return lab_; }
  /// The lab's title.
  const std::string& title() const { return title_; }
  /// The handout's picture of the finished lab ("picture" in exercises.json), or empty.
  const std::filesystem::path& picture() const { return picture_; }
  /// The first exercise that is not implemented or fails, or nullptr.
  const ExerciseStatus* next() const;
  /// Every exercise in manifest order.
  const std::vector<ExerciseStatus>& exercises() const { return exercises_; }
  /// True when the lab has bug hunts (the window then measures their symptom live).
  bool hasHunts() const;
  /// The state of exercise `id` (ExerciseState::Unknown for an id the manifest does not list).
  ExerciseState stateOf(const std::string& id) const;
  /// Records an exercise's state; unknown ids are ignored.
  void set(const std::string& id, ExerciseState state, const std::string& message);

  /// Registers the GLSL probe of exercise `id`: `expression` is evaluated in a compute shader that
  /// includes `file` and compared with WB_TODO. An empty expression (a stage a kernel cannot
  /// include, such as a geometry shader) reads the exercise's text instead: it is not implemented
  /// while it still holds the word WB_TODO.
  void addProbe(const std::string& id, const std::string& file, const std::string& expression);
  /// Runs every probe now (needs a GL context) and records the results.
  void probe();
  /// True when a file the probes read has changed since they ran.
  bool probedFilesChanged() const;

  /// Prints one line per exercise that is not implemented or failing (stderr, for people).
  void printUnfinished() const;
  /// The exercises as JSON: [{"id", "title", "state", "message"}].
  nlohmann::json toJson() const;

 private:
  struct Probe {
    std::string id, file, expression;
  };
  void probeText(const Probe& p);
  std::string number_, title_;
  std::string lab_, pictureName_;  // "01_depth_map", "images/directional.png"
  std::filesystem::path picture_;
  std::vector<ExerciseStatus> exercises_;
  std::vector<Probe> probes_;
  std::map<std::filesystem::path, std::filesystem::file_time_type> probedFiles_;
  std::map<std::filesystem::path, std::string> lastGood_;  // each probed file's text at its last compile
};

}  // namespace wb
