// A map from 64-bit keys to ints that is filled once, then only read: a sorted vector of pairs.
// A third of an unordered_map's memory for millions of keys (no nodes, no buckets) and as fast
// to look up in bulk; the mesh builder keys its polygon edges this way.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace voroseal {

class SortedKeyMap {
 public:
  /// Adds (key, value); the first value added for a key wins, as unordered_map::emplace.
  /// Only before seal().
  void add(std::uint64_t key, int value) { entries_.emplace_back(key, order_++, value); }

  /// Sorts the entries and keeps the first value of every key: find() works from here on.
  void seal() {
    std::sort(entries_.begin(), entries_.end());
    entries_.erase(std::unique(entries_.begin(), entries_.end(),
                               [](const Entry& a, const Entry& b) { return a.key == b.key; }),
                   entries_.end());
    entries_.shrink_to_fit();
  }

  /// The value of `key`, or nullptr when it was not added. Only after seal().
  const int* find(std::uint64_t key) const {
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                     [](const Entry& e, std::uint64_t k) { return e.key < k; });
    return it != entries_.end() && it->key == key ? &it->value : nullptr;
  }

  void reserve(size_t n) { entries_.reserve(n); }
  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    std::uint64_t key;
    std::uint32_t order;  // insertion order: the first added sorts first among equal keys
    int value;
    Entry(std::uint64_t k, std::uint32_t o, int v) : key(k), order(o), value(v) {}
    bool operator<(const Entry& o) const { return key != o.key ? key < o.key : order < o.order; }
  };
  std::vector<Entry> entries_;
  std::uint32_t order_ = 0;
};

}  // namespace voroseal
