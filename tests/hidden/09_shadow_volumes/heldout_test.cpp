// Held-out tests of lab 09 (instructor-only: tests/hidden is never exported). The same exercises in a
// courtyard students have not seen: a directional light, an arch, a flat ring, an open sheet (open
// edges), and a bookmark inside the arch's shadow. Points and visibility: hidden.json beside this file.
#include "tests/harness/harness.hpp"

namespace {
const std::vector<std::string> kOverview = wb::test::labArgs({}, "hidden/heldout.json");
const std::vector<std::string> kInside = wb::test::labArgs({"camera.bookmark=2"}, "hidden/heldout.json");
}  // namespace

TEST(Hidden09, Ex09_1_SceneHeldOut) {
  wb::test::expectSceneMatchesGolden("09.1", "hidden/heldout", kOverview, 0.1f, 0.005);
}

TEST(Hidden09, Ex09_5_SceneHeldOutInsideZFail) {
  wb::test::expectSceneMatchesGolden(
      "09.5", "hidden/heldout_inside",
      wb::test::labArgs({"camera.bookmark=2", "volume.method=zfail"}, "hidden/heldout.json"), 0.1f, 0.005);
}

TEST(Hidden09, Ex09_6_SceneHeldOutInsideAuto) {
  wb::test::expectSceneMatchesGolden("09.6", "hidden/heldout_inside", kInside, 0.1f, 0.005);
}
