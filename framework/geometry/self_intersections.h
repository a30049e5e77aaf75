// Self-intersections of a triangulated surface set (a structural model, a remeshed model):
// pairs of triangles that meet where a conformal mesh allows no contact. Exact predicates
// (CGAL Exact_predicates_inexact_constructions_kernel) on the double coordinates: no
// floating-point tolerance decides whether two triangles touch.
#pragma once

#include <utility>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

/// True when triangles `a` and `b` (indices into `vertices`) intersect beyond what they share:
///  - sharing an edge: only when they fold onto each other (coplanar, third vertices on the
///    same side of the edge);
///  - sharing one vertex: when an edge opposite the shared vertex meets the other triangle;
///  - sharing nothing: when they have any point in common (touching counts, so a T-junction or a
///    non-conformal contact is an intersection);
///  - the same three vertices: always.
/// \pre both triangles have three distinct, non-collinear vertices (see is_degenerate()).
bool triangles_intersect(const std::vector<Vec3>& vertices, const Triangle& a, const Triangle& b);

/// True when the triangle has a repeated vertex index or three collinear points (exact test).
bool is_degenerate(const std::vector<Vec3>& vertices, const Triangle& t);

/// All pairs (i, j), i < j, sorted, of triangles that intersect in the sense of
/// triangles_intersect(). Candidate pairs come from CGAL::box_self_intersection_d over the
/// triangles' bounding boxes; the exact tests run in parallel (OpenMP).
/// Degenerate triangles (is_degenerate()) are not tested: report them separately.
/// `max_pairs` >= 0 stops once that many pairs are found (which ones is then not deterministic);
/// -1 finds all.
/// \throws ModelError when a triangle refers to a vertex that does not exist.
std::vector<std::pair<int, int>> find_self_intersections(const std::vector<Vec3>& vertices,
                                                         const std::vector<Triangle>& triangles, int max_pairs = -1);

/// The pairs of find_self_intersections() that involve at least one triangle of `query`
/// (indices into `triangles`): what a local edit (a remesher's clean-up) needs to re-test.
/// Pairs are (i, j), i < j, sorted, unique.
/// \throws ModelError when a triangle or a query index is out of range.
std::vector<std::pair<int, int>> find_intersections_with(const std::vector<Vec3>& vertices,
                                                         const std::vector<Triangle>& triangles,
                                                         const std::vector<int>& query, int max_pairs = -1);

}  // namespace voroseal
