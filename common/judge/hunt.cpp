#include "common/judge/hunt.hpp"

#include "common/base/strf.hpp"
#include "common/judge/harness.hpp"

#include <gtest/gtest.h>

namespace wb::test {

void expectSymptomGone(const std::string& id, const std::string& name, std::vector<std::string> args,
                       const SymptomBounds& bounds) {
  // (Its own run folder: a golden test of the same scene may run at the same time, under `name`.)
  const std::string run = name + "_symptom", heatmap = (testOutputDir() / (run + "_heatmap.png")).string();
  args.insert(args.end(), {"--heatmap", heatmap});
  const SceneMetrics m = measureScene(id, run, args);
  if (!m.failure.empty()) FAIL() << m.failure;
  EXPECT_LE(m.acnePercent, bounds.acnePercent) << strf(
      "WRONG: in scene '%s', %.2f%% of the pixels the light truly reaches are drawn in shadow (a fix: at "
      "most %.2f%%); they are red in %s",
      name.c_str(), m.acnePercent, bounds.acnePercent, heatmap.c_str());
  EXPECT_LE(m.leakPercent, bounds.leakPercent) << strf(
      "WRONG: in scene '%s', %.2f%% of the truly shadowed pixels are drawn lit (a fix: at most %.2f%%); they "
      "are blue in %s",
      name.c_str(), m.leakPercent, bounds.leakPercent, heatmap.c_str());
}

}  // namespace wb::test
