/// @file lab_stage.hpp
/// LabStage: what a host lends the lab it hosts, and keeps for it. The lab draws into the host's
/// frame target and times its passes with the host's timers; what it builds and reports (its
/// programs, its exercises' states, its warnings, the tape of its C++ exercises) is kept here, where
/// the host reloads, shows and records it. The host owns the stage (LabHost, or EmbeddedLab for a lab
/// inside another), so a lab holds none of the host's state, and the host reads none of the lab's.
#pragma once
#include "common/exercise/exercise_board.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/platform/frame_target.hpp"
#include "common/platform/gpu_timers.hpp"
#include "common/platform/shader.hpp"
#include "common/shell/command_line.hpp"

#include <filesystem>
#include <list>
#include <string>
#include <vector>

namespace wb {

/// What a host lends a lab and keeps for it; see the file comment.
struct LabStage {
  /// A stage on the host's `target` and `timers`, with the exercise list of the lab that wb::variant
  /// names (exercisesFile()).
  LabStage(FrameTarget& target, GpuTimers& timers);
  LabStage(const LabStage&) = delete;
  LabStage& operator=(const LabStage&) = delete;

  /// The exercises.json of the lab that wb::variant names: the one list shared with the tests and
  /// grading (the lab's number and title too).
  static std::filesystem::path exercisesFile();
  /// A warning for the info panel and the record, kept once (and printed once on stderr).
  void warn(const std::string& message);

  FrameTarget& target;                ///< where the lab draws (the host's)
  GpuTimers& timers;                  ///< its passes' GPU times (the host's)
  CompareChoice comparison;           ///< this frame's split screen (the host sets it every frame)
  ExerciseBoard board;                ///< the lab's exercises and their states
  ExerciseTape tape;                  ///< its C++ exercises' results (--record-exercises, --replay-exercises)
  std::list<Program> programs;        ///< built by Lab::loadProgram(), reloaded by the host
  std::vector<std::string> warnings;  ///< shown in the info panel, written to the record
};

}  // namespace wb
