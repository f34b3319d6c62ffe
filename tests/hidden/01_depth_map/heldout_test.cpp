// Held-out tests of lab 01 (instructor-only: tests/hidden is never exported). The same exercises on a
// scene students have not seen, so a solution tuned to the public scene does not pass by accident.
// Their points and visibility: hidden.json beside this file.
#include "common/judge/harness.hpp"

namespace {
const std::vector<std::string> kSun = wb::test::labArgs({"light.index=0"}, "hidden/heldout.json");
const std::vector<std::string> kSpot = wb::test::labArgs({"light.index=1"}, "hidden/heldout.json");
}  // namespace

TEST(Hidden01, Ex01_1_SceneHeldOutLowSun) {
  wb::test::expectSceneMatchesGolden("01.1", "hidden/low_sun", kSun, 0.5f, 0.005);
}
TEST(Hidden01, Ex01_2_SceneHeldOutSpot) {
  wb::test::expectSceneMatchesGolden("01.2", "hidden/spot", kSpot, 0.5f, 0.005);
}
TEST(Hidden01, Ex01_4_SceneHeldOutLowSun) {
  wb::test::expectSceneMatchesGolden("01.4", "hidden/low_sun", kSun, 0.5f, 0.005);
}
