// Independent classes of vertices for the clean-up's vertex moves: no two vertices of a class
// share a triangle, so each one moves against neighbours that stay where they are. The moves of
// a class are found in parallel and applied in order: one sweep over the class in that order,
// the same mesh whatever the number of threads.
#pragma once

#include <vector>

#include "modules/remesh/cleanup_editor.h"

namespace voroseal::cleanup {

/// `vertices` split greedily, in order, into independent classes. Their stars are tidied, so
/// that the proposals of sweep_classes() may read them from several threads.
std::vector<std::vector<int>> independent_classes(Editor& e, const std::vector<int>& vertices);

/// For each class in turn: `propose(v, x)` on its vertices in parallel (reading only v's ring;
/// true with a position x), then `apply(v, x)` in class order on those that proposed one.
template <class Propose, class Apply>
void sweep_classes(const std::vector<std::vector<int>>& classes, const Propose& propose,
                   const Apply& apply) {
  std::vector<Vec3> to;
  std::vector<char> proposed;
  for (const std::vector<int>& members : classes) {
    const long n = static_cast<long>(members.size());
    to.assign(members.size(), Vec3::Zero());
    proposed.assign(members.size(), 0);
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = 0; i < n; ++i) proposed[i] = propose(members[i], to[i]) ? 1 : 0;
    for (long i = 0; i < n; ++i)
      if (proposed[i]) apply(members[i], to[i]);
  }
}

}  // namespace voroseal::cleanup
