/// @file hunt.hpp
/// Bug hunts (exercises NN.Hk): the lab's own code with a real bug in it, judged by its symptom
/// against exact visibility, never by the line that was changed (docs/adding-a-lab.md, "Bug hunts").
#pragma once
#include <string>
#include <vector>

namespace wb::test {

/// The largest acne and leak (in percent, as `--metrics` measures them) a fixed hunt may show on
/// its scene: measured on the reference, with a margin for the grader's turned variants.
struct SymptomBounds {
  double acnePercent = 100;  ///< truly lit pixels drawn shadowed
  double leakPercent = 100;  ///< truly shadowed pixels drawn lit
};

/// Runs hunt `id`'s scene (`args`, as for measureScene()) with `--metrics` and a heatmap in the
/// test's output folder, and fails (WRONG) where the acne or the leak is beyond `bounds`: the
/// message gives the measured symptom, the bound and where the heatmap shows it.
void expectSymptomGone(const std::string& id, const std::string& name, std::vector<std::string> args,
                       const SymptomBounds& bounds);

}  // namespace wb::test
