#include "common/shell/symptom_watch.hpp"

#include "common/base/strf.hpp"
#include "common/truth/measurement.hpp"

namespace wb {
namespace {

// What a frame shows, as bytes: every setting's value, the camera's matrix, the frame's size and
// the number of shader reloads so far.
std::string signature(const Settings& settings, const glm::mat4& viewProj, glm::ivec2 frameSize, int reloads) {
  std::string s;
  auto add = [&s](const void* p, size_t n) { s.append(static_cast<const char*>(p), n); };
  for (const auto& setting : settings.all()) {
    if (setting.kind == Setting::Kind::Float) add(setting.value, sizeof(float));
    if (setting.kind == Setting::Kind::Bool) add(setting.value, sizeof(bool));
    if (setting.kind == Setting::Kind::Int || setting.kind == Setting::Kind::Choice) add(setting.value, sizeof(int));
  }
  add(&viewProj, sizeof viewProj);
  add(&frameSize, sizeof frameSize);
  add(&reloads, sizeof reloads);
  return s;
}

}  // namespace

bool SymptomWatch::due(const Settings& settings, const glm::mat4& viewProj, glm::ivec2 frameSize, int reloads) {
  const std::string now = signature(settings, viewProj, frameSize, reloads);
  if (now != pending_) pending_ = now, still_ = 0;
  if (now == shown_ || ++still_ < kSettleFrames) return false;
  shown_ = now;
  return true;
}

void SymptomWatch::record(const MeasureResult& r) {
  if (!r.ownMeasure.empty()) {  // the view writes a measure, not visibility
    line_ = "now: not measured (this view shows a measure, not the shadows)";
    return;
  }
  if (r.todoPixels > 0) {  // a stub's pattern is on screen: acne and leak would count it as shadow
    line_ = "now: not measured (the frame shows the not-implemented pattern)";
    return;
  }
  line_ = strf("now: acne %.2f%%, leak %.2f%% (this view)", 100 * r.metrics.acneRate(), 100 * r.metrics.leakRate());
  if (!r.halves.empty()) line_ += " (both halves)";
}

}  // namespace wb
