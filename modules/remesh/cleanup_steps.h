// The steps of the clean-up (mesh_cleanup.h), each a pass of checked edits of the Editor
// (cleanup_editor.h). Internal to the remesh module: the phases (cleanup_phases.h) run them.
#pragma once

#include <map>
#include <vector>

#include "modules/remesh/cleanup_editor.h"
#include "modules/remesh/contact_arcs.h"
#include "modules/remesh/mesh_cleanup.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal::cleanup {

// ---- edits (cleanup_edits.cpp) ----

// Interior (surface) vertex with exactly three triangles of one part around it, closed fan.
int remove_valence3(Editor& e);

// A flip of the edge (x, y) facing v in its triangle t = (v, x, y): t and the triangle
// (y, x, o) of the same part beyond the edge would become (v, x, o) and (v, o, y). False when
// the edge is a contact edge, o is v, or a new triangle would face away from the two it
// replaces. Whether the new edge (v, o) may exist elsewhere is the caller's call.
struct OppositeFlip {
  int out = -1;  // the triangle beyond the edge
  int o = -1;    // its far vertex
  Triangle g1{}, g2{};
  double min_angle = 0.0;  // smallest angle of g1 and g2
};

bool opposite_flip(Editor& e, int v, int t, OppositeFlip& flip);

// Makes the flip: t and flip.out become flip.g1 and flip.g2, whose ids go to `added`.
void apply_flip(Editor& e, int t, const OppositeFlip& flip, std::vector<int>* added = nullptr);

// Vertices on contacts cannot go, but a part that runs on across the contact (a horizon ending
// on a fault: the fault part holds the contact) may close a fan of three triangles around one.
// On a flat part that fan is a dent or a bump that no tet mesh keeping the surface fills
// without a flat tetrahedron (remeshed CloudSpin_fixed: 0.03°). Flipping a side of the fan,
// toward the best-shaped pair, gives the vertex four triangles there.
int raise_valence3_on_contacts(Editor& e);

// Whether u may collapse into v: the features allow it, the link condition holds and no
// triangle folds over or becomes a sliver. No triangle may come out with a smallest angle below
// min(its angle before, `floor_deg`): a collapse never turns good triangles into needles (which
// would let collapses cascade). A bend u goes where bend_may_go(e, u, v, `bend_slack`).
bool collapse_allowed(Editor& e, int u, int v, double merge_below, double floor_deg, bool repairing,
                      double bend_slack = 1.0);

// The collapse itself: the triangles of edge (u, v) go, u becomes v in the others.
void collapse(Editor& e, int u, int v);

// The contact both u and v sample (a contact vertex's contact, or the one a corner ends that the
// other vertex lies on), -1 when none.
int shared_contact(const Editor& e, int u, int v);

// The contact the line edge (u, v) samples: the one whose parts are the edge's. Between two
// corners that both end several contacts (a thin strip pinched at both ends) shared_contact()
// cannot tell which, and after merges an end may carry the feature of the contact it was merged
// into; the edge's parts tell (the nearest of the contacts with those parts). Else
// shared_contact().
int line_contact(Editor& e, const SurfaceProjector& projector,
                 const std::map<std::vector<int>, std::vector<int>>& contacts_by_parts, int u, int v);

// Splits edge (u, v) at vertex w in every triangle that has it, keeping orientations; the new
// triangles are appended to `added`.
void split(Editor& e, int u, int v, int w, std::vector<int>* added = nullptr);

// Collapses u into v when collapse_allowed() and the validity of the surface gets no worse
// (`strict`: better).
bool try_collapse(Editor& e, int u, int v, double merge_below, double floor_deg, bool strict);

// Collapses the shortest possible edge of triangles with an angle below `needle_angle` and of
// the folds along contacts (on_one_contact).
int collapse_needles(Editor& e, double needle_angle, bool strict = false, const std::vector<int>* only = nullptr);

// Flips the edge (u, v) inside one part when it improves the smallest angle of its two
// triangles (or, `strict`, when it repairs a violation).
bool try_flip(Editor& e, int u, int v, double cos_flat, bool strict);

// A cap (an angle near 180°) flips its longest edge away, but try_flip() wants an edge of two
// triangles: where a fold over a contact puts the same cap in several parts along it, each cap
// flips with its own part's other triangle on the edge, all in one edit kept when it repairs.
// False for a cap standing in one part alone (try_flip()'s case).
bool flip_cap_in_its_parts(Editor& e, int t);

int flip_edges(Editor& e, double flatness_deg);

// Whether w follows contact vertex v along v's contact: a vertex of that contact, or a corner
// ending it, joined to v by a contact edge.
bool along_contact(Editor& e, int v, int w);

// Moves v to x when the validity of its ring allows it (one checked edit).
bool move_checked(Editor& e, int v, const Vec3& x);

// Vertex v placed at x, to measure a move before making it (v = -1: none).
struct Placement {
  int v = -1;
  Vec3 x = Vec3::Zero();
};

// Whether every triangle of `tris` keeps facing the way it does, and is not flat (its normal
// keeps more than 1e-3 of its length), with the placed vertices at their places.
bool unfolded_with(Editor& e, const std::vector<int>& tris, const Placement& a, const Placement& b = {});

// unfolded_with() for the ring of v, v at x.
bool ring_unfolded_at(Editor& e, int v, const Vec3& x);

// Where a move of v toward `target` (then back onto its feature) ends: the full step, else half,
// else a quarter, the first that folds no triangle of its ring. False when none does.
bool unfolded_move(Editor& e, const SurfaceProjector& projector, int v, const Vec3& target, double step,
                   Vec3& result);

// Moves v toward `target` when the validity allows it (see unfolded_move()).
bool try_move(Editor& e, const SurfaceProjector& projector, int v, const Vec3& target, bool strict);

// Splits edge (u, v) at new vertex x in every triangle that has it, when the validity gets no
// worse.
bool try_split(Editor& e, int u, int v, const Vec3& x, const VertexFeature& feature);

// Splits the longest edge of triangle t between two triangles of its part at its middle, moved
// onto the part; with `along_contacts`, a contact edge too (moved onto the contact, split in
// every part there, so that the contact stays conformal). A border edge off contacts stays.
// True when an edge was split (try_split).
bool split_longest_edge(Editor& e, const SurfaceProjector& projector, int t, bool along_contacts);

// Flips the edges of `part` opposite v whose two triangles get a larger smallest angle by it,
// where a triangle of v has one below `floor_deg` (after v was inserted into the part). The far
// vertices of the flips are added to `touched`.
void flip_around(Editor& e, int v, int part, double floor_deg, std::vector<int>& touched);

// ---- merges (cleanup_merges.cpp) ----

// Features closer than d_min merge (paper Fig. 11c-d), which removes small fault throws and
// joins fault tips to the contact next to them:
//  - a "rung", an edge shorter than d_min between two features (contacts, corners), collapses;
//  - a strip triangle, whose base is an edge of one contact and whose apex samples another feature
//    closer than d_min to the base, is zipped: the base is split at the foot of the apex and the
//    foot collapsed into the apex, so that the two contacts run together there.
// A thin strip between two contacts (a small fault throw) is a chain of strip triangles; zipping
// one alone would pinch the strip at a point (its part would touch itself there), so the
// candidates of a stretch (candidates whose triangles share edges) are merged together, in one
// edit checked as a whole; a stretch whose whole edit is refused is tried candidate by candidate.
// A part loses its last triangles this way only when another part still separates the two
// regions it separates (a fault strip thinner than d_min between the two cut-offs of a horizon,
// CloudSpin's Cyan_ts/3, 2 m wide), so the regions keep their neighbours.
void merge_close_features(Editor& e, const SurfaceProjector& projector, double min_feature,
                          CleanupCounts& report);

// A free border (a fault tip) that leaves a part at a thin wedge runs a few metres from it, and any
// tet mesh keeping the surfaces fills the gap with tets about as flat as the gap is thin against
// the triangles around it (docs/benchmarks.md, "Figures behind the code"). Closer than d_min, the
// tip joins the part (paper Fig. 11c-d, a fault tip joins the fault next to it): a free border
// vertex v next to a vertex a of the part, whose gap d to the part is less than tan(max_wedge)
// times the larger of |av| and the part's triangle under v, moves to the closest point of the
// part's triangles around a or next to them and is inserted there (pinned), and (a, v) becomes a
// contact edge, made in the part by a flip when v landed next to a's triangles. A join may bring
// the next border vertex in. It is refused when it leaves a needle, a wedge thinner than
// max_wedge at the new contact edge, or a free edge of v leaving the part at less than twice
// max_wedge beyond d_min (the gap would only move on), and when v would keep no free edge
// toward a vertex off the part: a free border never closes entirely (that might cut a region
// in two) and never lies along the part with both ends on it (a gap of no thickness).
int join_close_tips(Editor& e, double min_feature, double max_wedge_deg, CleanupCounts& report);

// ---- shape (cleanup_shape.cpp) ----

// Where smoothing would move vertex v: surface vertices toward the area-weighted centroid of
// their ring within the tangent plane, contact vertices toward the middle of their two contact
// neighbours. With `vertex_size` (a target size per vertex) each triangle weighs area / s^4, the
// density the seeds were placed for, so that the cells keep their grading. False when v stays.
bool smoothing_target(Editor& e, int v, Vec3& target,
                      const std::vector<double>* vertex_size = nullptr);

// One Gauss-Seidel pass of tangential smoothing (see smoothing_target()). Moves that fold no
// triangle of their ring are made, then the moved triangles are checked at once, which is much
// cheaper than checking every move: the vertices of triangles in a violation the pass made are
// put back where they were, until the pass made none.
// Returns the vertices moved.
// `target_size` (null: uniform) gives the size the cells should have around a point.
int smooth(Editor& e, const SurfaceProjector& projector, const std::vector<char>* only = nullptr,
           const SizeField* target_size = nullptr);

// Smallest angle of the triangles around v with v at x.
double ring_min_angle(Editor& e, int v, const Vec3& x);

// The triangles `tris` with the placed vertices at their places: the sum of Q, the sine of the
// smallest angle (every smallest angle is at most 60 degrees, so sines compare as the angles do;
// no atan2 in this innermost loop), and the triangles with an angle below 30 degrees.
struct RingShape {
  double q = 0.0;
  double smallest_sine = 1.0;
  int sharp = 0;
};
RingShape ring_shape(Editor& e, const std::vector<int>& tris, const Placement& a, const Placement& b = {});

// Whether the middles of the triangles around v, v at x, stay within the fidelity tolerance of
// their part, or no farther than with v where it is.
bool stays_close(Editor& e, const SurfaceProjector& projector, int v, const Vec3& x);

// Moves the vertices of triangles with an angle below `angle_deg` to where their ring's smallest
// angle is largest (angle_target()). They are few: each move is checked on its own.
int optimize_angles(Editor& e, const SurfaceProjector& projector, double angle_deg);

// The mean Q of the output is what the smoothing (toward the centroid of the ring) leaves
// furthest from good next to contacts, where the ring is lopsided. The vertices of triangles with
// Q below `q_below` move to where the sum of Q around them is largest among a few candidates on
// their feature (toward and away from each neighbour; along the contact for contact vertices),
// no triangle of theirs getting sharper than 30 degrees nor than the sharpest one there.
// Returns the moves made.
int optimize_quality(Editor& e, const SurfaceProjector& projector, double q_below);

// Collapses an edge of a triangle with an angle below `angle_deg` (its shortest possible one)
// when that leaves fewer such triangles around the edge, or as many with the sharpest one 5 deg
// less sharp. What the angle passes leave is mostly triangles no vertex move fixes: a short
// contact edge between close contact points, a short rung across a thin strip; one vertex less
// there often does. A collapse never makes a triangle sharper than min(its angle, 12 deg)
// (collapse_allowed), nor the surfaces less valid, nor the remesh stray from the input by more
// than the fidelity tolerance (where u was, and at the middles of the triangles around).
int collapse_sharp(Editor& e, const SurfaceProjector& projector, double angle_deg);

// ---- contact spacing (cleanup_contacts.cpp) ----

// A contact crossing the restricted Voronoi cells gets a vertex in every cell it crosses, some
// of them across a cell's corner, and the fidelity splits add bends: contact edges much shorter
// than the triangles around them, whose triangles are squat in every part along the contact.
// The contact edges shorter than `shorter_than` collapse, shortest first, a contact vertex into
// its neighbour along the contact, which then takes the best place between its two new contact
// neighbours; kept when the triangles around are better shaped on average and none more of
// them sharper than 30 degrees, the contact edge left keeps to the input (bend_may_go()) and the
// surfaces are no less valid. Corners and pinned vertices other than bends stay. Returns the
// collapses made.
int space_contacts(Editor& e, const SurfaceProjector& projector, double shorter_than);

// ---- fewer sharp triangles (cleanup_sharp.cpp) ----

// The angle passes raise the smallest angle around one vertex at a time, and the quality passes
// keep every triangle as sharp as it is: what they leave are triangles of 20-30 degrees whose
// vertices each hold another sharp triangle (most of them within 5 degrees of 30). Here a move
// counts the triangles sharper than 30 degrees it leaves around it: it is made when there are
// fewer, none gets sharper than 15 degrees (or than the sharpest one there, when that already is)
// nor by more than 5 degrees sharper than the sharpest one there was, and the sum of Q there loses
// at most 0.3 per triangle fixed. First each vertex of a sharp triangle alone (along its contact,
// or around it in its part), then two of its vertices together (the apex and a base vertex of a
// triangle in a strip between two contacts); edge flips after each pass, up to `passes` passes.
// Returns the moves made.
int reduce_sharp_triangles(Editor& e, const SurfaceProjector& projector, int passes, double flatness_deg,
                           int& flips);

// ---- pinch-outs (cleanup_zip.cpp) ----

// A layer that ends in a pinch-out (parts P and Q bounding a region between them meet along a
// contact where a third part K runs on between the regions beyond them) and stays thinner than
// `max_thickness` (d_min) past it closes there: its two sides zip into K from the contact on,
// edge by edge, while the wedge at the front is thinner than `max_wedge_deg` and the apexes of
// the two sides are closer than `max_thickness`. No tet mesh keeping the surfaces fills a
// layer much thinner than its triangles without flat tets (remeshed modelA6: a tongue 9-25 m
// thick under 250 m triangles, 3.9 deg); closed, the layer ends where it is thick enough.
// Each step pairs the two apexes of the front edge: merged when close, else the nearer one
// inserted into the other side's triangle, else the crossing of their edges inserted into
// both, then the two coincident triangles become one of K (middle of the two sides, so the
// surface moves by at most half the thickness). An apex where the two sides already meet
// (another stretch of their contact, or a side surface where they end together) stays put.
// Zipped vertices are pinned. Where a tongue reaches a side surface (the box, a fault):
//  - the layer's strip on it, when narrower than max_thickness, closes rung by rung;
//  - a step that joins two stretches of the line where P and Q meet closes off a pocket of the
//    layer: when the pocket is thinner than max_thickness all over it goes to the region beyond
//    P (P's triangles there go, the others change part: Q's to K, the strip's to the side
//    surface beyond P; the interface moves by the pocket's thickness at most); otherwise the
//    step is refused;
//  - front edges shorter than max_thickness (notches left by steps that crossed near an end)
//    shrink to their midpoint.
// A front whose sides already lie on each other (P's and Q's triangles on the same vertices,
// left by an earlier merge) closes into one triangle of K, unless they are degenerate or K would
// fold onto a neighbour there (the repair removes such pairs). A notch is not closed where it
// would crease a surface under 10 degrees.
// The whole zip is undone when it leaves more violations than before, folds aside (a front
// that stops in a thin layer is one; the repair opens it).
struct PinchZips {
  int steps = 0;    // front steps and notches closed
  int rungs = 0;    // rungs of strips on side surfaces closed
  int pockets = 0;  // pockets of a layer closed off by a step or a rung, gone to the region beyond
  int edits() const { return steps + rungs; }
};
PinchZips zip_pinch_outs(Editor& e, double max_thickness, double max_wedge_deg);

// ---- wedges (cleanup_wedges.cpp) ----

// Moves the vertices of wedge tets flatter than `bound_deg` (their edge's and apexes') to where
// the flattest wedge tet around them is least flat, among the candidates of angle_target(),
// when their triangles keep a smallest angle of min(theirs, 20°). Where that is not enough (the
// wedge itself thinner than the bound, or staggered apexes), an apex on a part may leave it by up
// to `max_lift` (0: never), away from the other side. Each move is checked on its own.
int open_wedge_tets(Editor& e, const SurfaceProjector& projector, double bound_deg, double max_lift);

// ---- fidelity (cleanup_fidelity.cpp) ----

// Splits contact edges whose chord leaves the input contact by more than `tolerance` (at the
// farthest input vertex, kept in place), and surface edges of triangles whose middle lies
// farther than `tolerance` from their input part (at the edge middle, projected). The input
// contacts' arc lengths are the Editor's (arcs_). The farthest first, at most `max_splits`.
int refine_for_fidelity(Editor& e, const SurfaceProjector& projector, double tolerance,
                        int max_splits);

// The other half of the fidelity check: input vertices inside a part (a fold, a bump between the
// output vertices) farther than `tolerance` from the remesh are inserted into the nearest
// triangle of their part, where they stay (pinned): the remesh then passes through them. The
// farthest first, at most `max_splits`.
int refine_toward_input(Editor& e, double tolerance, int max_splits);

// Grading (cleanup_grading.cpp): where two triangles sharing an edge have mean edge lengths more
// than `max_ratio` apart, the longest edge of the larger one inside its part or along a contact
// is split at its middle, moved onto the part or the contact. Returns the splits.
int grade_neighbours(Editor& e, const SurfaceProjector& projector, double max_ratio);

// Where a contact vertex may move: its contact edges then stray from the input contact by no
// more than the fidelity tolerance (or than they did), so that the moves after the fidelity
// refinement do not undo it (a chord sliding over a bend). The vertices the refinement put at
// bends (pinned) move under this rule too. Any position is allowed for other vertices and
// without a tolerance.
class FidelityGuard {
 public:
  /// v's neighbours (Editor::neighbours()).
  FidelityGuard(Editor& e, int v, const std::vector<int>& neighbours);
  bool allows(const Vec3& x) const;

 private:
  struct Side {
    Vec3 end = Vec3::Zero();  // the neighbour along the contact
    double at = 0.0;          // its arc length
    double bound = 0.0;       // the farthest the chord may stray
  };
  const ContactArcs* arcs_;
  int contact_ = -1;
  bool refuse_ = false;
  Side sides_[2];
  int count_ = 0;
};

// Whether bend u may go by its collapse into v, its neighbour along the contact: the contact
// edge from v to u's other neighbour then strays from the input contact by no more than `slack`
// times the fidelity tolerance (or than u's two edges did). Without a tolerance a bend stays.
bool bend_may_go(Editor& e, int u, int v, double slack = 1.0);

// ---- repair (cleanup_repair.cpp) ----

// Repairs what the mesh building left invalid (paper §3.3: intersections "resolved by vertex
// displacements or edge flipping"): around every triangle involved in a violation, edits that
// make the validity strictly better are kept: moving a vertex to its smoothed position, flipping
// an edge, collapsing an edge (a needle, a fold along a contact).
// What is left is the census after it (see clean_up()).
void repair(Editor& e, const SurfaceProjector& projector, const CleanupThresholds& thresholds,
            CleanupCounts& report);

}  // namespace voroseal::cleanup
