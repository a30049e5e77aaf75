// Disjoint sets with path halving and union by size.
#pragma once

#include <numeric>
#include <vector>

namespace voroseal {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  size_t size() const { return parent_.size(); }
  /// Adds an element in a set of its own; returns it.
  int add() {
    parent_.push_back(static_cast<int>(parent_.size()));
    size_.push_back(1);
    return parent_.back();
  }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// Returns true when a and b were in different sets.
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }
  /// Joins the set of `absorbed` into the set of `kept`, whose root stays the root: for callers
  /// that choose the representative. Returns true when they were in different sets.
  bool join_into(int kept, int absorbed) {
    kept = find(kept);
    absorbed = find(absorbed);
    if (kept == absorbed) return false;
    parent_[absorbed] = kept;
    size_[kept] += size_[absorbed];
    return true;
  }
  /// Dense labels 0..k-1 in order of first appearance; returns k.
  int labels(std::vector<int>& out) {
    out.assign(parent_.size(), -1);
    std::vector<int> id(parent_.size(), -1);
    int k = 0;
    for (size_t i = 0; i < parent_.size(); ++i) {
      const int r = find(static_cast<int>(i));
      if (id[r] < 0) id[r] = k++;
      out[i] = id[r];
    }
    return k;
  }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

}  // namespace voroseal
