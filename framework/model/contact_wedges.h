// Contact wedges: where surface parts meet along a contact, the angle between two triangles
// consecutive around the contact edge. A tetrahedral mesh that keeps the surface triangles
// fills each wedge inside a region with tets on that edge whose dihedral angles there add up
// to the wedge's angle: the thinnest wedge bounds the smallest dihedral angle of any such
// mesh, whatever its interior points. Pinch-outs make them (modelA6: two layers meeting at
// 1.4 degrees).
#pragma once

#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

struct ContactWedge {
  int a = -1, b = -1;          // the contact edge (model vertex ids, a < b)
  int contact = -1;
  int lower_part = -1;         // parts of the two triangles, in increasing angle about a -> b
  int upper_part = -1;
  int region = -2;             // region filling the wedge; -2 when the model has no regions
  double angle_deg = 0.0;
};

/// Wedges thinner than `max_deg` degrees along the contacts, thinnest first, except those
/// facing the universe (a tet mesh does not fill them).
std::vector<ContactWedge> thin_contact_wedges(const StructuralModel& model, double max_deg);

}  // namespace voroseal
