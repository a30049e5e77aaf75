// Internal to the pinch-out zip (zip_pinch_outs in cleanup_steps.h): the pinch-out front, the
// region helpers and the step rules shared by the front steps (cleanup_zip.cpp) and the edits
// where a zipped tongue meets a side surface, pockets and strip rungs (cleanup_zip_sides.cpp).
#pragma once

#include <utility>
#include <vector>

#include "modules/remesh/cleanup_steps.h"

namespace voroseal::cleanup::zip {

// A pinch-out edge (a, b): exactly three triangles, of parts P and Q bounding a region R between
// them at a thin wedge, and of K, the part that runs on beyond the pinch-out between the regions
// A (beyond P) and B (beyond Q).
struct PinchFront {
  int tp = -1, tq = -1;  // the triangles of P and Q at the edge
  int c1 = -1, c2 = -1;  // their apexes
  int part_k = -1;
  int region = -1;  // R, the layer
  bool p_faces_k_first = false;  // P's triangles, as oriented, face K's first region
  // An apex where P and Q already meet (on another stretch of their contact, or where they end
  // together on a side surface): it stays where it is, the other apex comes to it (-1: none).
  int anchor = -1;
};

// A rung of the layer's strip on a side surface S (a fault, the box): the strip (part R | Z, R
// the layer, Z beyond S) has a triangle (x, u, v) where x is a vertex at which the layer's two
// sides P (R | A) and Q (R | B) already meet, u is on P's contact with S and v on Q's (S goes on
// beyond them as its pieces A | Z and B | Z).
struct StripRung {
  int u = -1, v = -1;
  int part_p = -1, part_q = -1;
  int region = -1;       // R
  PinchFront beyond;     // K (between A and B) and its orientation, for P's and Q's triangles
                         // that the merge makes one; part_k -1 when no part is between A and B
};

// Edges of v with triangles of both parts: the contact where the two sides of the layer meet.
int side_contact_degree(Editor& e, int v, int part_p, int part_q);
// |(x - o) · n|: the distance of x to the plane through o with unit normal n.
double plane_distance(const Vec3& x, const Vec3& o, const Vec3& n);
// Whether a part with these (two) regions lies between regions c and d.
bool joins(std::pair<int, int> regions, int c, int d);
// The region across a part with these regions from c.
int other_region(std::pair<int, int> regions, int c);

// Pins a zipped vertex (corners are held anyway).
void hold(Editor& e, int v);
// P's and Q's triangles around v on the same three vertices become one triangle of K.
void close_coincident(Editor& e, int v, const PinchFront& z, int part_p, int part_q);

// The rules of a step, and of a step that also closed a pocket (see cleanup_zip.cpp).
bool zip_step_acceptable(const Violations& before, const Violations& after);
bool pocket_step_acceptable(Violations before, const Violations& after, const Violations& in_pocket);

// cleanup_zip_sides.cpp
// The pocket of region r closed off at v goes to the region beyond P; false when none.
bool absorb_pocket(Editor& e, int v, int part_p, int r, double max_thickness, std::vector<int>& changed,
                   Violations& there);
// The rung of the layer's strip on a side surface at x; false when none.
bool find_rung(Editor& e, int x, double max_wedge, double max_thickness, StripRung& rung);
// Closes it: returns the merged vertex or -1; `pocket` tells whether a pocket went.
int close_rung(Editor& e, int x, const StripRung& rung, double max_thickness, bool& pocket);

}  // namespace voroseal::cleanup::zip
