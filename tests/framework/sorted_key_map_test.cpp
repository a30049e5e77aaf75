#include "framework/core/sorted_key_map.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

namespace voroseal {
namespace {

// Against unordered_map::emplace on random keys with repeats: the same value for every key
// added (the first one), and nothing for the others.
TEST(SortedKeyMap, AgreesWithEmplaceOnRandomKeys) {
  std::mt19937_64 random(7);
  SortedKeyMap map;
  std::unordered_map<std::uint64_t, int> reference;
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t key = random() % 5000;  // about four values per key
    map.add(key, i);
    reference.emplace(key, i);
  }
  map.seal();
  EXPECT_EQ(map.size(), reference.size());
  for (std::uint64_t key = 0; key < 6000; ++key) {
    const int* value = map.find(key);
    const auto it = reference.find(key);
    ASSERT_EQ(value != nullptr, it != reference.end()) << key;
    if (value) {
      EXPECT_EQ(*value, it->second) << key;
    }
  }
}

TEST(SortedKeyMap, EmptyFindsNothing) {
  SortedKeyMap map;
  map.seal();
  EXPECT_EQ(map.find(0), nullptr);
  EXPECT_EQ(map.size(), 0u);
}

}  // namespace
}  // namespace voroseal
