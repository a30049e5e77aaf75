#include <gtest/gtest.h>

#include "framework/core/union_find.h"

namespace voroseal {
namespace {

TEST(UnionFind, UniteJoinsSetsOnce) {
  UnionFind sets(5);
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_TRUE(sets.unite(3, 4));
  EXPECT_FALSE(sets.unite(1, 0));
  EXPECT_EQ(sets.find(0), sets.find(1));
  EXPECT_NE(sets.find(0), sets.find(3));
  std::vector<int> labels;
  EXPECT_EQ(sets.labels(labels), 3);
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 1, 2, 2}));
}

// join_into lets the caller choose the representative, whatever the sizes of the sets.
TEST(UnionFind, JoinIntoKeepsTheChosenRoot) {
  UnionFind sets;
  for (int i = 0; i < 4; ++i) EXPECT_EQ(sets.add(), i);
  EXPECT_EQ(sets.size(), 4u);
  EXPECT_TRUE(sets.join_into(1, 2));
  EXPECT_TRUE(sets.join_into(1, 3));
  EXPECT_EQ(sets.find(3), 1);
  // The bigger set goes into the singleton 0: 0 stays the root.
  EXPECT_TRUE(sets.join_into(0, 3));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(sets.find(i), 0);
  EXPECT_FALSE(sets.join_into(2, 1));
  EXPECT_EQ(sets.find(2), 0);
}

}  // namespace
}  // namespace voroseal
