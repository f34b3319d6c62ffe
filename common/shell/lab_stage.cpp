#include "common/shell/lab_stage.hpp"

#include "common/base/variant.hpp"

#include <algorithm>
#include <cstdio>

namespace wb {

LabStage::LabStage(FrameTarget& t, GpuTimers& g) : target(t), timers(g), board(exercisesFile()) {}

std::filesystem::path LabStage::exercisesFile() { return std::filesystem::path(variant::kLabDir) / "exercises.json"; }

void LabStage::warn(const std::string& message) {
  if (std::find(warnings.begin(), warnings.end(), message) != warnings.end()) return;
  warnings.push_back(message);
  std::fprintf(stderr, "warning: %s\n", message.c_str());
}

}  // namespace wb
