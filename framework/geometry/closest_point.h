// The point of a triangle closest to a point.
#pragma once

#include "framework/core/types.h"

namespace voroseal {

/// The point of triangle (a, b, c) closest to p, as barycentric weights of a, b and c.
Vec3 closest_weights(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Squared distance from p to triangle (a, b, c).
double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace voroseal
