// A hunt's symptom in the window is measured once the view holds still after a change (the view,
// a setting, a shader reload), once per change, and never while the view keeps moving: each
// measurement costs a frame's ray casting.
#include "common/shell/symptom_watch.hpp"
#include "common/base/settings.hpp"
#include "common/shell/presenter.hpp"
#include "common/truth/measurement.hpp"

#include <gtest/gtest.h>

namespace {

constexpr int kSettle = wb::SymptomWatch::kSettleFrames;

struct Frames {
  wb::SymptomWatch watch;
  wb::Settings settings;
  float bias = 0.5f;
  glm::mat4 view{1};
  int reloads = 0;
  Frames() { settings.add("bias.constant", bias, 0, 1, "test"); }
  // How many of the next `n` frames measure.
  int measured(int n) {
    int count = 0;
    for (int k = 0; k < n; ++k) count += watch.due(settings, view, {960, 540}, reloads) ? 1 : 0;
    return count;
  }
};

TEST(SymptomWatch, MeasuresOnceTheFirstViewHoldsStill) {
  Frames f;
  EXPECT_EQ(f.measured(kSettle - 1), 0);
  EXPECT_EQ(f.measured(1), 1);
  EXPECT_EQ(f.measured(200), 0);  // the same view is not measured again
}

TEST(SymptomWatch, MeasuresAgainAfterEachKindOfChange) {
  Frames f;
  EXPECT_EQ(f.measured(kSettle), 1);
  f.bias = 0.25f;  // a setting
  EXPECT_EQ(f.measured(kSettle), 1);
  f.view[3][0] = 1;  // the camera
  EXPECT_EQ(f.measured(kSettle), 1);
  ++f.reloads;  // the student's edit of a shader
  EXPECT_EQ(f.measured(kSettle), 1);
}

TEST(SymptomWatch, NeverWhileTheViewMoves) {
  Frames f;
  int count = 0;
  for (int k = 0; k < 300; ++k) f.view[3][0] = float(k), count += f.measured(1);
  EXPECT_EQ(count, 0);
  EXPECT_EQ(f.measured(kSettle), 1);  // and once it stops
}

TEST(SymptomWatch, BackToAViewMeasuredBeforeIsMeasuredAgain) {
  Frames f;
  EXPECT_EQ(f.measured(kSettle), 1);
  f.bias = 0.25f;
  EXPECT_EQ(f.measured(kSettle), 1);
  f.bias = 0.5f;  // (the code may have changed meanwhile: a C++ hunt's rebuild restarts the app, a shader reloads)
  EXPECT_EQ(f.measured(kSettle), 1);
}

TEST(SymptomWatch, TheLineGivesTheMeasuredAcneAndLeak) {
  wb::SymptomWatch watch;
  EXPECT_NE(watch.line().find("measuring"), std::string::npos);
  wb::MeasureResult r;
  r.metrics.litPixels = 1000, r.metrics.acnePixels = 5;
  r.metrics.shadowedPixels = 200, r.metrics.leakPixels = 50;
  watch.record(r);
  EXPECT_EQ(watch.line(), "now: acne 0.50%, leak 25.00% (this view)");
}

// A frame that shows a stub's pattern (WB_TODO) has no acne or leak to give: counting the pattern as
// shadow made the student edition's line read "acne 100.00%".
TEST(SymptomWatch, AFrameWithAStubSaysNotMeasured) {
  wb::SymptomWatch watch;
  wb::MeasureResult r;
  r.metrics.litPixels = 1000, r.metrics.acnePixels = 1000;
  r.todoPixels = 3;
  watch.record(r);
  EXPECT_EQ(watch.line(), "now: not measured (the frame shows the not-implemented pattern)");
  EXPECT_EQ(wb::Presenter::numbersLine(r), "not measured: an exercise this frame needs is unfinished");
}

}  // namespace
