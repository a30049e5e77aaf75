#include "modules/remesh/contact_arcs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// farthest_between() as its contract says, by scanning every vertex of the contact.
int farthest_by_scan(const StructuralModel& m, int c, double s0, double s1, const Vec3& a, const Vec3& b,
                     double* distance) {
  const auto& line = m.contacts[c].vertices;
  std::vector<double> arc(line.size(), 0.0);
  for (size_t i = 1; i < line.size(); ++i) arc[i] = arc[i - 1] + (m.vertices[line[i]] - m.vertices[line[i - 1]]).norm();
  const double lo = std::min(s0, s1), hi = std::max(s0, s1);
  const bool wrap = m.contacts[c].is_closed() && hi - lo > 0.5 * arc.back();
  int best = -1;
  *distance = 0.0;
  for (size_t i = 0; i < line.size(); ++i) {
    if (wrap ? (arc[i] > lo && arc[i] < hi) : (arc[i] < lo || arc[i] > hi)) continue;
    const Vec3& x = m.vertices[line[i]];
    const Vec3 d = b - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - x).norm();
    if (dist > *distance) {
      *distance = dist;
      best = line[i];
    }
  }
  return best;
}

void check_against_scan(const StructuralModel& m, unsigned seed) {
  const ContactArcs arcs(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t c = 0; c < m.contacts.size(); ++c) {
    const auto& line = m.contacts[c].vertices;
    double total = 0.0;
    for (size_t i = 1; i < line.size(); ++i) total += (m.vertices[line[i]] - m.vertices[line[i - 1]]).norm();
    // Each vertex sits at its own arc length (the first of a closed contact at 0).
    double at = 0.0;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      EXPECT_NEAR(arcs.position(static_cast<int>(c), m.vertices[line[i]]), at, 1e-12);
      at += (m.vertices[line[i + 1]] - m.vertices[line[i]]).norm();
    }
    for (int k = 0; k < 200; ++k) {
      // Bounds at vertices (merged contact ends lie there) or anywhere, chords anywhere nearby.
      double s0 = u(rng) * total, s1 = u(rng) * total;
      if (k % 3 == 0) s0 = arcs.position(static_cast<int>(c), m.vertices[line[k % line.size()]]);
      const Vec3 a = m.vertices[line[0]] + Vec3(u(rng), u(rng), u(rng)) - Vec3::Constant(0.5);
      const Vec3 b = m.vertices[line[line.size() / 2]] + Vec3(u(rng), u(rng), u(rng)) - Vec3::Constant(0.5);
      double fast = 0.0, slow = 0.0;
      const int x = arcs.farthest_between(static_cast<int>(c), s0, s1, a, b, &fast);
      const int y = farthest_by_scan(m, static_cast<int>(c), s0, s1, a, b, &slow);
      ASSERT_EQ(x, y) << "contact " << c << " between " << s0 << " and " << s1;
      ASSERT_EQ(fast, slow);
    }
  }
}

TEST(ContactArcs, FarthestVertexBetweenTwoPositionsOfAnOpenContact) {
  const StructuralModel m = build_model(test::lattice_box(4, true));
  ASSERT_FALSE(m.contacts.empty());
  ASSERT_FALSE(m.contacts[0].is_closed());
  check_against_scan(m, 1);
}

TEST(ContactArcs, FarthestVertexTheShorterWayRoundAClosedContact) {
  // The free border of a floating fault: one closed contact, 32 edges around a unit square.
  const StructuralModel m = build_model(test::floating_fault(8, 0.5, 0.0, 1.0));
  ASSERT_EQ(m.contacts.size(), 1u);
  ASSERT_TRUE(m.contacts[0].is_closed());
  check_against_scan(m, 2);
  // By hand: between the arc positions 0.5 and 3.5 the shorter way passes the start vertex
  // (a corner of the square), 0.5 from the chord joining the two positions.
  const ContactArcs arcs(m);
  const auto& line = m.contacts[0].vertices;
  double distance = 0.0;
  const int x = arcs.farthest_between(0, 0.5, 3.5, m.vertices[line[4]], m.vertices[line[28]], &distance);
  EXPECT_EQ(x, line[0]);
  EXPECT_NEAR(distance, std::sqrt(0.125), 1e-12);
}

}  // namespace
}  // namespace voroseal
