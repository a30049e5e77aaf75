// Longest-edge bisection of a model's surface triangles (Rivara): finer triangles where they are
// asked for, on exactly the same surfaces.
#pragma once

#include <array>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

/// Splits each of `edges` (pairs of model vertex ids; pairs that are no triangle edge are
/// skipped) at its midpoint, in every surface part holding it, by longest-edge bisection: a
/// triangle is only ever split across its longest edge, so one whose longest edge is another is
/// split across that one first (and its neighbours across it, recursively). The triangles' angles
/// stay above half the smallest angle before (Rivara 1984), the surfaces' point sets are unchanged
/// (new vertices are edge midpoints) and the parts stay conformal to each other along contacts.
/// Contacts get the midpoints of their edges; parts, contacts, corners and regions keep their
/// indices. Returns the number of edges split, those split for their neighbours included.
int bisect_edges(StructuralModel& model, const std::vector<std::array<int, 2>>& edges);

}  // namespace voroseal
