/// @file exercise_tape.hpp
/// What a lab's C++ exercises did in one run of the app, kept for another run. In grading, the
/// student's app records its exercises (--record-exercises F.json) and the grader's trusted app,
/// built with the solution, replays them (--replay-exercises F.json): for every exercise in the
/// file it takes the recorded result instead of calling its own code. The pixels a grade rests on
/// are then drawn by trusted code, with the student's values in them.
#pragma once
#include "common/exercise/exercise_board.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wb {

/// Records or replays the calls of a lab's C++ exercises, in order per exercise.
class ExerciseTape {
 public:
  /// One call: how it ended and what it produced (a value, the GL state it left, or null).
  struct Call {
    ExerciseState state = ExerciseState::Unknown;  ///< Implemented, NotImplemented or Failed
    std::string message;                           ///< why not
    nlohmann::json value;                          ///< what it produced (value_codec.hpp)
  };

  /// Records every call from now on; save() writes them to `file`.
  void startRecording(const std::filesystem::path& file);
  /// Replays the calls in `file` (what startRecording() saved); throws wb::Error naming the file
  /// when it is missing or malformed.
  void startReplay(const std::filesystem::path& file);
  /// True while recording.
  bool recording() const { return !recordFile_.empty(); }
  /// True when exercise `id` is replayed (the file holds calls of it).
  bool replays(const std::string& id) const { return replaying_ && replayed_.count(id); }
  /// Records a call of `id` (of an exercise that is not replayed: a run may replay some exercises
  /// and record the others, and the file it saves holds only what it recorded).
  void add(const std::string& id, Call call);
  /// The next recorded call of `id` (the last one again when this run calls it more often).
  Call next(const std::string& id);
  /// Writes the recorded calls (when recording); throws wb::Error when the file cannot be written.
  void save() const;

 private:
  std::filesystem::path recordFile_;
  bool replaying_ = false;
  std::map<std::string, std::vector<Call>> replayed_;  // from startReplay()
  std::map<std::string, std::vector<Call>> recorded_;  // for save()
  std::map<std::string, size_t> used_;
};

/// Parses `text` as JSON, refusing nesting deeper than `maxDepth` before it recurses (a tape is
/// written by untrusted code: a line nested a million deep would overflow the stack); throws.
nlohmann::json parseShallowJson(const std::string& text, int maxDepth = 16);

/// The depth pass's rasterizer state that exercises may set (polygon offset, culling), as JSON.
nlohmann::json captureRasterState();
/// Sets the state captureRasterState() returned; throws wb::Error on malformed data.
void applyRasterState(const nlohmann::json& state);

}  // namespace wb
