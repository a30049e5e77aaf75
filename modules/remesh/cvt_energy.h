// The centroidal Voronoi energy of the seeds on the model (paper eq. 2):
//
//   F_CVT(S) = Σ_i ∫_{V_i ∩ Ω} ρ(y) ‖y − p_i‖² dy,
//
// and its gradient dF_CVT/dp_i = 2 m_i (p_i − g_i) with m_i = ∫ρ and g_i = ∫ρ y / m_i over the
// restricted cell (the terms from the motion of the cell borders cancel because the integrand
// is continuous across bisectors; Du et al. 1999, Liu et al. 2009). Written relative to the
// seed, ∇_i = −2 ∫ρ (y − p_i), which keeps full precision far from the origin.
//
// These are the closed-form integrals over one triangle with a linear density (ρ given at its
// three vertices); a restricted polygon is integrated as a fan of such triangles.
#pragma once

#include "framework/core/types.h"

namespace voroseal {

/// Integrals of one restricted cell (or part of it), relative to its seed p.
struct CellIntegrals {
  double mass = 0.0;                 // ∫ρ
  Vec3 moment = Vec3::Zero();        // ∫ρ (y − p)
  double energy = 0.0;               // ∫ρ ‖y − p‖²
};

/// Adds the integrals over triangle (p + u0, p + u1, p + u2) of signed area `area` with
/// density 1. d_k = ‖u_k‖² (already known to the caller).
inline void add_cvt_triangle(CellIntegrals& c, double area, const Vec3& u0, const Vec3& u1, const Vec3& u2, double d0,
                             double d1, double d2) {
  c.mass += area;
  c.moment += (area / 3.0) * (u0 + u1 + u2);
  c.energy += (area / 6.0) * (d0 + d1 + d2 + u0.dot(u1) + u1.dot(u2) + u2.dot(u0));
}

/// Same with a linear density taking values w0, w1, w2 at the three vertices. With barycentric
/// coordinates λ, ∫λ_i λ_j = A(1+δ_ij)/12 and ∫λ_i λ_j λ_k = A/10, A/30, A/60 for 3, 2, 0
/// equal indices.
inline void add_cvt_triangle_weighted(CellIntegrals& c, double area, const Vec3& u0, const Vec3& u1, const Vec3& u2,
                                      double d0, double d1, double d2, double w0, double w1, double w2) {
  const double sum = w0 + w1 + w2;
  c.mass += area * sum / 3.0;
  c.moment += (area / 12.0) * ((sum + w0) * u0 + (sum + w1) * u1 + (sum + w2) * u2);
  const double g01 = u0.dot(u1), g12 = u1.dot(u2), g02 = u0.dot(u2);
  const double t0 = d0 / 10.0 + (d1 + d2) / 30.0 + (g01 + g02) / 15.0 + g12 / 30.0;
  const double t1 = d1 / 10.0 + (d0 + d2) / 30.0 + (g01 + g12) / 15.0 + g02 / 30.0;
  const double t2 = d2 / 10.0 + (d0 + d1) / 30.0 + (g02 + g12) / 15.0 + g01 / 30.0;
  c.energy += area * (w0 * t0 + w1 * t1 + w2 * t2);
}

/// Gradient of F_CVT for one seed from its integrals: 2 m (p − g) = −2 ∫ρ (y − p).
inline Vec3 cvt_gradient(const CellIntegrals& c) { return -2.0 * c.moment; }

}  // namespace voroseal
