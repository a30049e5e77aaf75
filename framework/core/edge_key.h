// Undirected edge keys: one 64-bit integer per pair of vertex ids (smaller id in the high half),
// for hash maps and sorted lists of edges.
#pragma once

#include <cstdint>
#include <utility>

namespace voroseal {

/// The key of edge {a, b} (a, b >= 0), the same for (a, b) and (b, a).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// The smaller vertex id of an edge key.
inline int edge_key_first(std::uint64_t key) { return static_cast<int>(key >> 32); }

/// The larger vertex id of an edge key.
inline int edge_key_second(std::uint64_t key) { return static_cast<int>(key & 0xffffffffu); }

}  // namespace voroseal
