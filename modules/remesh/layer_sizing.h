// Sizing for thin layers: where two surfaces face each other closer than the cells are wide (a
// layer, or a gap between two faults, thinner than its triangles), a tet mesh that keeps the
// surface triangles can only fill it with flat tets: a prism of height t under triangles of
// side L splits into tets of about atan(t / 0.87 L). Cells about `ratio` times the thickness
// there open those tets.
//
// The size is h where nothing is thin, ratio × t on the sides of a layer of thickness t (t from
// a ray along the vertex normal to the first surface of another part facing it), never under
// h / max_refinement, and graded: it grows by at most `gradation` per unit length away from
// the layer. Next to a thin wedge at a contact (a pinch-out, where a layer ends between two
// surfaces meeting at a few degrees) the size stays h and falls off at the same rate: finer
// cells there would only resolve the input's wiggles at the tip into thinner wedges, and a
// wedge's angle bounds the dihedral angles of the tets in it whatever the size
// (docs/benchmarks.md, "Figures behind the code").
//
// A contact between two corners shorter than h (a layer's stretch of a box edge) gets cells
// corner_ratio times its length along it, graded the same way, unless it is shorter than
// h / max_refinement: with cells of h its corners share a cell and the mesh building merges
// them (see layer_sizing.cpp).
//
// The size becomes the CVT density rho = (h / size)^4 at the model vertices: the cells of a 2D
// CVT have a diameter proportional to rho^(-1/4) (Du, Faber, Gunzburger 1999).
#pragma once

#include <limits>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

struct LayerSizingOptions {
  double ratio = 6.0;            // size at most ratio × thickness (a stacked prism: ~11 deg)
  double max_refinement = 4.0;   // size at least h / max_refinement
  double gradation = 0.4;        // size change per unit length
  double facing_angle_deg = 30.0;  // a surface faces a vertex within this angle of its normal
  double pinch_angle_deg = 30.0;   // contact wedges thinner than this keep the size h
  double corner_ratio = 1.0;       // size at most corner_ratio × the length of a contact shorter than h
};

struct LayerSizing {
  std::vector<double> size;  // target edge length at every model vertex
  /// Thickness samples (part vertices, triangle centroids) on a layer thinner than h / ratio.
  int thin_samples = 0;
  int pinch_vertices = 0;    // contact vertices at a wedge thinner than pinch_angle_deg
  int short_contacts = 0;    // contacts between two corners shorter than h, refined
  /// The thinnest layer farther than h from every pinch-out tip (+inf: none), and where (local
  /// frame).
  double thinnest = std::numeric_limits<double>::infinity();
  Vec3 thinnest_at = Vec3::Zero();
  bool refines() const { return thin_samples > 0 || short_contacts > 0; }
};

/// Target edge lengths for a remesh of mean edge length h.
/// \throws ParameterError when h or an option is out of range.
LayerSizing thin_layer_sizing(const StructuralModel& model, double h, const LayerSizingOptions& options = {});

/// rho = (h / size)^4 at every vertex.
std::vector<double> density_from_sizing(const std::vector<double>& size, double h);

}  // namespace voroseal
