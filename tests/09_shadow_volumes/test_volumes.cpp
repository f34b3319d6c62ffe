// Lab 09 tests (in progress).
#include "exercise.hpp"
#include "tests/harness/harness.hpp"

TEST(Lab09, Ex09_1_Placeholder) {
  std::vector<uint32_t> adj;
  WB_TRY_EXERCISE(adj = WB_CALL(lab09::buildAdjacency({0, 1, 2})));
  EXPECT_EQ(adj.size(), 6u);
}
