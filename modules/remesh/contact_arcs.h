// Arc-length parametrisation of a model's contacts (the fidelity check of the clean-up).
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

// Arc-length parametrisation of the input contacts, to find the input vertices of a contact
// between two output vertices.
class ContactArcs {
 public:
  explicit ContactArcs(const StructuralModel& m) : m_(m), arc_(m.contacts.size()) {
    for (size_t c = 0; c < m.contacts.size(); ++c) {
      const auto& line = m.contacts[c].vertices;
      arc_[c].assign(line.size(), 0.0);
      for (size_t i = 1; i < line.size(); ++i)
        arc_[c][i] = arc_[c][i - 1] + (m.vertices[line[i]] - m.vertices[line[i - 1]]).norm();
    }
  }
  /// Length of contact c along its vertices.
  double length(int c) const { return arc_[c].empty() ? 0.0 : arc_[c].back(); }
  /// Arc length of the point of contact c nearest to x.
  double position(int c, const Vec3& x) const {
    const auto& line = m_.contacts[c].vertices;
    double best = std::numeric_limits<double>::infinity(), at = 0.0;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec3& a = m_.vertices[line[i]];
      const Vec3 d = m_.vertices[line[i + 1]] - a;
      const double l2 = d.squaredNorm();
      const double t = l2 > 0 ? std::clamp((x - a).dot(d) / l2, 0.0, 1.0) : 0.0;
      const double dist = (a + t * d - x).squaredNorm();
      if (dist < best) {
        best = dist;
        at = arc_[c][i] + t * (arc_[c][i + 1] - arc_[c][i]);
      }
    }
    return at;
  }
  /// The input vertex of contact c strictly between arc positions s0 and s1 (along the shorter
  /// way for a closed contact) farthest from segment [a, b]; -1 when there is none.
  int farthest_between(int c, double s0, double s1, const Vec3& a, const Vec3& b, double* distance) const {
    const auto& line = m_.contacts[c].vertices;
    const auto& arc = arc_[c];
    const double total = arc.back();
    const bool closed = m_.contacts[c].is_closed();
    double lo = std::min(s0, s1), hi = std::max(s0, s1);
    const bool wrap = closed && hi - lo > 0.5 * total;
    int best = -1;
    *distance = 0.0;
    const Vec3 d = b - a;
    const double l2 = d.squaredNorm();
    auto scan = [&](size_t from, size_t to) {
      for (size_t i = from; i < to; ++i) {
        const Vec3& x = m_.vertices[line[i]];
        const double t = l2 > 0 ? std::clamp((x - a).dot(d) / l2, 0.0, 1.0) : 0.0;
        const double dist = (a + t * d - x).norm();
        if (dist > *distance) {
          *distance = dist;
          best = line[i];
        }
      }
    };
    // Bounds included: a contact end merged away (Fig. 11b) lies at a bound; a vertex at an
    // output end is at distance 0 from the chord, never the farthest. Arc lengths increase.
    const auto first = [&](double s) { return static_cast<size_t>(std::lower_bound(arc.begin(), arc.end(), s) - arc.begin()); };
    const auto past = [&](double s) { return static_cast<size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin()); };
    if (wrap) {
      scan(0, past(lo));
      scan(first(hi), arc.size());
    } else {
      scan(first(lo), past(hi));
    }
    return best;
  }

 private:
  const StructuralModel& m_;
  std::vector<std::vector<double>> arc_;
};

}  // namespace voroseal
