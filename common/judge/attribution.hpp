/// @file attribution.hpp
/// Which exercise a failure belongs to, where the edition cannot isolate one exercise from another.
/// The grader (and the instructor edition's check) draws every scene, and runs every GLSL kernel,
/// with the reference for the other exercises, so one mistake costs one exercise. The student
/// edition has no reference: there a scene draws the student's own code for every exercise, and a
/// GLSL function calls the student's own helpers. check then says what is true: an exercise that
/// fails only because another does is "blocked by" it (an error, without a hint), and one that passes
/// its own tests while its scene waits on another "passes its own tests", as the grader will count it;
/// one with no test of its own but its scenes (a bug hunt) is "waiting" on the others: neither passed
/// nor failed, with no number. A stub shows its pattern, which a scene test names itself: only an
/// exercise that is wrong or an error can be what spoils another's scene.
#pragma once
#include "common/judge/diagnosis.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace wb::test {

/// One exercise of the lab's manifest (labs/NN/exercises.json).
struct ManifestEntry {
  std::string id;     ///< "07.2"
  std::string title;  ///< the handout's title
  std::string file;   ///< "exercise.cpp" or "shaders/exercise.glsl"
};

/// What check found, exercise by exercise, that attribute() revises.
struct Findings {
  std::map<std::string, Diagnosis>& first;       ///< the most serious diagnosis of each exercise
  const std::set<std::string>& ownFailed;        ///< exercises failing a test that draws no scene
  std::map<std::string, std::string>& blockers;  ///< what blocks each exercise's scene tests ("07.4")
  std::set<std::string>& unblocked;              ///< exercises with a scene test that fails on its own
  const std::set<std::string>& withOwnTests;     ///< exercises that ran a test that draws no scene
};

/// Revises the verdicts as above (the student edition only), then marks every exercise whose run
/// was stopped (stopped.txt: a runner, or a judge's test that check stopped) as an error.
void attribute(const std::vector<ManifestEntry>& manifest, Findings f);

/// The GLSL exercises (other than `id`) whose functions exercise `id`'s chunk of `text` calls.
std::vector<std::string> glslExercisesCalled(const std::string& text, const std::string& id,
                                             const std::vector<ManifestEntry>& manifest);

}  // namespace wb::test
