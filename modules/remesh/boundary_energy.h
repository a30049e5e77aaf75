// The boundary energy F_B that pulls seeds onto contacts and free borders (paper eq. 3–5).
//
// The restriction of the Voronoi cell of seed p to the contact lines is a set of segments
// E = [C1, C2], one per line edge it meets. As in the paper, each segment contributes
//
//   F_B^E = ½ ‖N‖²,   N = (C1 − p) × (C2 − p)   (‖N‖ = twice the area of triangle p C1 C2),
//
// so F_B^E = ½ L² d² with L the segment length and d the distance from p to its line: it is
// zero when the seed lies on the contact. F_B = Σ_seeds Σ_segments F_B^E, over every contact
// (free borders included). With a density ρ, each segment is weighted by ρ at the middle of
// its line edge (a constant for the seeds, so the gradient below only scales): a cell's F_CVT
// grows like ρ·size⁴ and its F_B like size⁴, and without the weight the contacts would lose
// their pull where the density is high (measured: twice the F_B at the optimum on
// CloudSpin_fixed with a 16× density near close contacts, and seeds left off them).
//
// Gradient (eq. 4): dF/dp_s = ∂E/∂p + ∂E/∂C1 · dC1/dS + ∂E/∂C2 · dC2/dS with
//   ∂E/∂p  = (C1 − C2) × N,   ∂E/∂C1 = (C2 − p) × N,   ∂E/∂C2 = N × (C1 − p).
// A segment end C is either an input vertex (fixed) or the point where the bisector of seeds
// i (the cell's seed) and j crosses the line edge from A to B. Instead of eq. 5's 3×3 system we
// use its closed form: C = A + t D with D = B − A and ‖C − p_i‖² = ‖C − p_j‖², hence
//   dt = [(C − p_i)·dp_i − (C − p_j)·dp_j] / (D·(p_j − p_i)),   dC = D dt,
// so a gradient G = ∂E/∂C adds (G·D)/(D·(p_j − p_i)) (C − p_i) to seed i and
// −(G·D)/(D·(p_j − p_i)) (C − p_j) to seed j. (When the bisector is parallel to the edge the
// end point is not a differentiable function of the seeds; that term is then left out.)
#pragma once

#include "framework/core/types.h"

namespace voroseal {

/// Energy of one contact segment [C1, C2] of the cell of seed p, with its partial derivatives.
struct SegmentEnergy {
  double energy = 0.0;
  Vec3 d_seed = Vec3::Zero();  // ∂E/∂p
  Vec3 d_c1 = Vec3::Zero();    // ∂E/∂C1
  Vec3 d_c2 = Vec3::Zero();    // ∂E/∂C2
};

/// u1 = C1 − p, u2 = C2 − p.
inline SegmentEnergy boundary_segment_energy(const Vec3& u1, const Vec3& u2) {
  SegmentEnergy e;
  const Vec3 n = u1.cross(u2);
  e.energy = 0.5 * n.squaredNorm();
  e.d_seed = (u1 - u2).cross(n);
  e.d_c1 = u2.cross(n);
  e.d_c2 = n.cross(u1);
  return e;
}

/// Chain rule through a segment end C = bisector(p_i, p_j) ∩ line edge of direction D.
/// Adds G·dC/dp_i to grad_i and G·dC/dp_j to grad_j.
inline void add_bisector_end_gradient(const Vec3& g, const Vec3& c, const Vec3& d, const Vec3& pi, const Vec3& pj,
                                      Vec3& grad_i, Vec3& grad_j) {
  const double denominator = d.dot(pj - pi);
  if (denominator == 0.0) return;
  const double f = g.dot(d) / denominator;
  grad_i += f * (c - pi);
  grad_j -= f * (c - pj);
}

}  // namespace voroseal
