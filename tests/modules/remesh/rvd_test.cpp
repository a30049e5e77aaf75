// Restricted Voronoi diagram: partition of the model, cells inside Voronoi cells, exact tags,
// contact segments and corners, degenerate inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <unordered_map>

#include "framework/model/model_builder.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_sampling.h"
#include "modules/remesh/voronoi_clipping.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

// Every property a correct diagram has, checked by brute force.
void expect_valid_diagram(const ModelGeometry& geometry, const std::vector<Vec3>& seeds,
                          const RestrictedVoronoiDiagram& rvd, double area_tolerance = 1e-9) {
  const int n = static_cast<int>(seeds.size());
  ASSERT_EQ(rvd.num_seeds(), n);
  ASSERT_EQ(static_cast<int>(rvd.seed_polygons.size()), n + 1);
  const double h = std::sqrt(geometry.area() / n);

  // Partition: polygon areas add up to the area, triangle by triangle.
  std::vector<double> per_triangle(geometry.triangles().size(), 0.0);
  double total = 0.0;
  for (int p = 0; p < static_cast<int>(rvd.polygons.size()); ++p) {
    const RvdPolygon& poly = rvd.polygons[p];
    ASSERT_GE(poly.size, 3);
    const double a = rvd.polygon_area(p);
    ASSERT_TRUE(std::isfinite(a));
    per_triangle[geometry.record_of(poly.triangle)] += a;
    total += a;
    EXPECT_EQ(poly.part, geometry.triangles()[geometry.record_of(poly.triangle)].part);
  }
  EXPECT_NEAR(total, geometry.area(), area_tolerance * geometry.area());
  for (size_t r = 0; r < per_triangle.size(); ++r)
    EXPECT_NEAR(per_triangle[r], geometry.triangles()[r].area, 1e-9 * geometry.area()) << "triangle record " << r;

  // Each polygon lies in its seed's Voronoi cell (vertices closer to it than to any seed).
  for (int i = 0; i < n; ++i)
    for (int p = rvd.seed_polygons[i]; p < rvd.seed_polygons[i + 1]; ++p) {
      const RvdPolygon& poly = rvd.polygons[p];
      ASSERT_EQ(poly.seed, i);
      for (int k = 0; k < poly.size; ++k) {
        const Vec3& x = rvd.vertex[poly.first + k];
        ASSERT_TRUE(x.allFinite());
        const double di = (x - seeds[i]).squaredNorm();
        for (int q = 0; q < n; ++q) ASSERT_LE(di, (x - seeds[q]).squaredNorm() + 1e-9 * h * h) << "seed " << i;
      }
    }

  // Equal tags are one point; EdgeBisector points are bit-identical wherever they appear.
  std::unordered_map<RvdVertexTag, Vec3, RvdVertexTagHash> where;
  for (size_t v = 0; v < rvd.vertex.size(); ++v) {
    const RvdVertexTag& tag = rvd.vertex_tag[v];
    const auto [it, inserted] = where.emplace(tag, rvd.vertex[v]);
    if (inserted) continue;
    if (tag.kind == RvdVertexTag::TriangleBisectors) {
      EXPECT_LT((it->second - rvd.vertex[v]).norm(), 1e-9 * h);
    } else {
      EXPECT_EQ(it->second, rvd.vertex[v]) << "tag kind " << int(tag.kind);
    }
  }
  // An input-vertex tag sits on that vertex.
  for (size_t v = 0; v < rvd.vertex.size(); ++v) {
    if (rvd.vertex_tag[v].kind == RvdVertexTag::InputVertex) {
      EXPECT_EQ(rvd.vertex[v], geometry.vertices()[rvd.vertex_tag[v].id[0]]);
    }
  }
}

std::vector<Vec3> random_seeds(const ModelGeometry& g, int n, unsigned seed) { return sample_seeds(g, n, seed); }

TEST(RestrictedVoronoiDiagram, PartitionsAClosedSurface) {
  const StructuralModel model = build_model(test::bumpy_sphere(10));
  const ModelGeometry geometry(model);
  EXPECT_EQ(geometry.triangles().size(), 1200u);
  EXPECT_NEAR(geometry.area(), model.area(), 1e-12 * model.area());
  for (int n : {1, 2, 7, 150, 2000}) {
    SCOPED_TRACE(n);
    const std::vector<Vec3> seeds = random_seeds(geometry, n, 3);
    const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds, {2});
    expect_valid_diagram(geometry, seeds, rvd);
    // A closed surface has no contact.
    EXPECT_TRUE(rvd.segments.empty());
  }
}

TEST(RestrictedVoronoiDiagram, PartitionsAModelWithContactsCornersAndFreeBorders) {
  SurfaceSoup soup = test::box_with_crossing_planes(8);
  test::append(soup, test::floating_fault(4, 0.25, 0.6, 0.9));  // free borders, above the horizon
  const StructuralModel model = build_model(soup);
  ASSERT_GT(model.contacts.size(), 10u);
  ASSERT_GT(model.corners.size(), 8u);
  const ModelGeometry geometry(model);
  for (int n : {5, 60, 400}) {
    SCOPED_TRACE(n);
    const std::vector<Vec3> seeds = random_seeds(geometry, n, 11);
    const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
    expect_valid_diagram(geometry, seeds, rvd);

    // Contact segments cover every line edge once: their lengths add up to the contact lengths.
    double contact_length = 0.0;
    for (const Contact& c : model.contacts)
      for (size_t k = 0; k + 1 < c.vertices.size(); ++k)
        contact_length += (model.vertices[c.vertices[k + 1]] - model.vertices[c.vertices[k]]).norm();
    double segment_length = 0.0;
    for (const RvdContactSegment& s : rvd.segments) {
      segment_length += (s.end[1] - s.end[0]).norm();
      EXPECT_GE(s.contact, 0);
      EXPECT_LT(s.a, s.b);
      // Ends lie on the line edge, end[0] nearer a.
      const Vec3 A = model.vertices[s.a], B = model.vertices[s.b];
      for (int e = 0; e < 2; ++e) EXPECT_LT((s.end[e] - A).cross(B - A).norm(), 1e-12);
      EXPECT_LE((s.end[0] - A).norm(), (s.end[1] - A).norm() + 1e-15);
      // And in the seed's cell.
      for (int e = 0; e < 2; ++e) {
        const double d = (s.end[e] - seeds[s.seed]).squaredNorm();
        for (const Vec3& q : seeds) EXPECT_LE(d, (s.end[e] - q).squaredNorm() + 1e-12);
        EXPECT_NE(s.end_tag[e].kind, RvdVertexTag::TriangleBisectors);
      }
    }
    EXPECT_NEAR(segment_length, contact_length, 1e-9 * contact_length);

    // Every corner is in exactly one cell: that of its nearest seed.
    std::vector<int> owner(model.corners.size(), -1);
    for (int i = 0; i < n; ++i)
      for (int k = rvd.seed_corners[i]; k < rvd.seed_corners[i + 1]; ++k) {
        EXPECT_EQ(owner[rvd.corners[k]], -1) << "corner in two cells";
        owner[rvd.corners[k]] = i;
      }
    for (size_t c = 0; c < model.corners.size(); ++c) {
      ASSERT_GE(owner[c], 0) << "corner " << c << " in no cell";
      const Vec3& x = model.vertices[model.corners[c].vertex];
      for (const Vec3& q : seeds) EXPECT_LE((x - seeds[owner[c]]).squaredNorm(), (x - q).squaredNorm());
    }
  }
}

TEST(RestrictedVoronoiDiagram, BisectorEdgesMatchAcrossNeighbourCells) {
  const StructuralModel model = build_model(test::box_with_crossing_planes(6));
  const ModelGeometry geometry(model);
  const std::vector<Vec3> seeds = random_seeds(geometry, 120, 5);
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  // (seed, triangle) -> polygon.
  std::map<std::pair<int, int>, int> polygon_of;
  for (int p = 0; p < static_cast<int>(rvd.polygons.size()); ++p)
    polygon_of[{rvd.polygons[p].seed, rvd.polygons[p].triangle}] = p;
  int checked = 0;
  for (const RvdPolygon& poly : rvd.polygons)
    for (int k = 0; k < poly.size; ++k) {
      const RvdEdgeTag& e = rvd.edge_tag[poly.first + k];
      if (!e.on_bisector()) continue;
      const RvdVertexTag a = rvd.vertex_tag[poly.first + k];
      const RvdVertexTag b = rvd.vertex_tag[poly.first + (k + 1) % poly.size];
      const auto it = polygon_of.find({e.neighbour, poly.triangle});
      ASSERT_NE(it, polygon_of.end()) << "no polygon of the neighbour across a bisector edge";
      const RvdPolygon& other = rvd.polygons[it->second];
      bool found = false;
      for (int m = 0; m < other.size && !found; ++m) {
        const RvdEdgeTag& f = rvd.edge_tag[other.first + m];
        found = f.neighbour == poly.seed && rvd.vertex_tag[other.first + m] == b &&
                rvd.vertex_tag[other.first + (m + 1) % other.size] == a;
      }
      EXPECT_TRUE(found) << "bisector edge without its twin";
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

TEST(RestrictedVoronoiDiagram, CellsOfWellSpreadSeedsOnASquareAreConnected) {
  const StructuralModel model = build_model(test::flat_square(20));
  const ModelGeometry geometry(model);
  // A perturbed lattice of seeds: every cell is one convex piece of the square.
  std::vector<Vec3> seeds;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i)
      seeds.push_back(Vec3((i + 0.5) / 8 + jitter(rng), (j + 0.5) / 8 + jitter(rng), 0.0) - model.frame.origin);
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  expect_valid_diagram(geometry, seeds, rvd);
  int count = 0;
  const std::vector<int> component = restricted_cell_components(rvd, &count);
  EXPECT_EQ(count, 64);
  for (int i = 0; i < 64; ++i)
    for (int p = rvd.seed_polygons[i]; p < rvd.seed_polygons[i + 1]; ++p) EXPECT_EQ(component[p], i);
  // The border of the square is a free-border contact: each seed near it has segments.
  EXPECT_FALSE(rvd.segments.empty());
  double border = 0.0;
  for (const RvdContactSegment& s : rvd.segments) border += (s.end[1] - s.end[0]).norm();
  EXPECT_NEAR(border, 4.0, 1e-12);
}

TEST(RestrictedVoronoiDiagram, CellsSplitBySurfacesHaveSeveralComponents) {
  // Two parallel close planes (like a thin layer): seeds between them have one component on
  // each plane.
  SurfaceSoup soup = test::flat_square(10);
  SurfaceSoup top = test::flat_square(10);
  for (Vec3& p : top.points) p[2] = 0.05;
  test::append(soup, top);
  const StructuralModel model = build_model(soup);
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) seeds.push_back(Vec3((i + 0.5) / 4, (j + 0.5) / 4, 0.025) - model.frame.origin);
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  expect_valid_diagram(geometry, seeds, rvd);
  int count = 0;
  restricted_cell_components(rvd, &count);
  EXPECT_EQ(count, 32);
}

TEST(RestrictedVoronoiDiagram, DegenerateTrianglesAndCoincidentSeeds) {
  const StructuralModel model = build_model(test::degenerate_square(6));
  const ModelGeometry geometry(model);
  int zero = 0, needle = 0;
  for (const TriangleRecord& t : geometry.triangles()) {
    if (t.area == 0.0) ++zero;
    if (t.area > 0.0 && t.area < 1e-6) ++needle;
  }
  ASSERT_EQ(zero, 1);
  ASSERT_EQ(needle, 1);
  std::vector<Vec3> seeds = random_seeds(geometry, 40, 8);
  // Seeds on the degenerate triangles, and coincident seeds.
  for (const TriangleRecord& t : geometry.triangles())
    if (t.area < 1e-6) seeds.push_back((t.p[0] + t.p[1] + t.p[2]) / 3.0);
  seeds.push_back(seeds[3]);
  seeds.push_back(seeds[3]);
  seeds.push_back(seeds[10]);
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  expect_valid_diagram(geometry, seeds, rvd);
  // Of coincident seeds only the lowest index has a cell.
  const int n = static_cast<int>(seeds.size());
  for (int i : {n - 3, n - 2, n - 1}) EXPECT_EQ(rvd.seed_polygons[i + 1] - rvd.seed_polygons[i], 0) << i;
  EXPECT_GT(rvd.seed_polygons[4] - rvd.seed_polygons[3], 0);

  // The energy path agrees, and nothing is NaN.
  SeedEnergy energy(geometry);
  EnergyEvaluation e;
  energy.evaluate(seeds, e);
  EXPECT_TRUE(std::isfinite(e.cvt));
  EXPECT_TRUE(std::isfinite(e.boundary));
  double mass = 0.0;
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(e.cvt_gradient[i].allFinite());
    EXPECT_TRUE(e.boundary_gradient[i].allFinite());
    EXPECT_TRUE(e.centroid[i].allFinite());
    mass += e.mass[i];
  }
  EXPECT_NEAR(mass, geometry.area(), 1e-9 * geometry.area());
  for (int i : {n - 3, n - 2, n - 1}) {
    EXPECT_EQ(e.mass[i], 0.0);
    EXPECT_EQ(e.cvt_gradient[i], Vec3::Zero());
  }
}

// Sums the area of the polygons of every triangle record.
struct AreaVisitor {
  std::vector<double>* area = nullptr;
  const TriangleRecord* first = nullptr;
  void begin_chunk(int) {}
  void end_chunk(int) {}
  void polygon(int, const TriangleRecord& rec, const rvd_detail::ClipVertex* poly, int n) {
    Vec3 twice = Vec3::Zero();
    for (int i = 1; i + 1 < n; ++i)
      twice += (poly[i].x - poly[0].x).cross(poly[i + 1].x - poly[0].x);
    (*area)[&rec - first] += 0.5 * twice.norm();
  }
};

TEST(RestrictedVoronoiDiagram, EveryStartFloodsTheWholeTriangleAlsoBesideCoincidentSeeds) {
  // The flood through a triangle must reach every cell meeting it from whichever cell it starts.
  // Beside a seed and its copy, both bisectors are one plane: the edge there must name the seed
  // that owns the cell beyond, not its copy (an empty cell, where the flood would stop).
  const StructuralModel model = build_model(test::degenerate_square(6));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds = random_seeds(geometry, 40, 8);
  for (int copy : {3, 3, 10, 17}) seeds.push_back(seeds[copy]);
  const int n = static_cast<int>(seeds.size());
  const std::vector<TriangleRecord>& records = geometry.triangles();
  SeedNeighbours nb;
  nb.build(seeds.data(), n, 16, 1);
  std::vector<rvd_detail::TraversalState> states(1);
  for (int start = 0; start < n; ++start) {
    std::vector<double> area(records.size(), 0.0);
    std::vector<AreaVisitor> visitors{{&area, records.data()}};
    std::vector<int> hint(records.size(), start);
    rvd_detail::traverse_restricted_polygons<false>(geometry, seeds.data(), n, nb, hint, states,
                                                    visitors, 1);
    for (size_t r = 0; r < records.size(); ++r)
      ASSERT_NEAR(area[r], records[r].area, 1e-12) << "record " << r << ", start " << start;
  }
}

TEST(RestrictedVoronoiDiagram, SeedsFarFromTheSurfaceAndHugeCells) {
  // Seeds off the surface and very uneven cells exercise the longer neighbour lists.
  const StructuralModel model = build_model(test::bumpy_sphere(6));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds = random_seeds(geometry, 300, 4);
  for (int k = 0; k < 40; ++k) seeds[k] = 0.05 * seeds[k];          // a cluster at the centre
  for (int k = 40; k < 60; ++k) seeds[k] = 3.0 * seeds[k];          // a few far outside
  for (int k = 60; k < 260; ++k) seeds[k] = seeds[k] * 0.02 + Vec3(0.9, 0, 0);  // dense clump
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds, {1, 4});
  expect_valid_diagram(geometry, seeds, rvd);
}

TEST(RestrictedVoronoiDiagram, LeanPathMatchesFullDiagram) {
  SurfaceSoup soup = test::box_with_crossing_planes(6);
  const StructuralModel model = build_model(soup);
  const ModelGeometry geometry(model);
  const std::vector<Vec3> seeds = random_seeds(geometry, 200, 9);
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  SeedEnergy energy(geometry, 2);
  EnergyEvaluation e;
  energy.evaluate(seeds, e);
  energy.evaluate(seeds, e);  // second call: warm start hints, same result
  for (int i = 0; i < 200; ++i) {
    double area = 0.0;
    Vec3 moment = Vec3::Zero();
    for (int p = rvd.seed_polygons[i]; p < rvd.seed_polygons[i + 1]; ++p) {
      const RvdPolygon& poly = rvd.polygons[p];
      const Vec3& o = rvd.vertex[poly.first];
      for (int k = 1; k + 1 < poly.size; ++k) {
        const Vec3& b = rvd.vertex[poly.first + k];
        const Vec3& c = rvd.vertex[poly.first + k + 1];
        const double a = triangle_area(o, b, c);
        area += a;
        moment += a * (o + b + c) / 3.0;
      }
    }
    EXPECT_NEAR(e.mass[i], area, 1e-12);
    if (area > 0) {
      EXPECT_LT((e.centroid[i] - moment / area).norm(), 1e-9);
    }
  }
}

TEST(RestrictedVoronoiDiagram, ResultsDoNotDependOnThreadsOrHistory) {
  // Large enough for two threads to be used; with contacts so F_B is exercised too.
  const StructuralModel model = build_model(test::box_with_crossing_planes(64));
  const ModelGeometry geometry(model);
  ASSERT_GT(geometry.triangles().size(), 8192u);
  const std::vector<Vec3> seeds = random_seeds(geometry, 2000, 1);
  // Same sequence of evaluations, 1 or 2 threads: bit-identical.
  SeedEnergy one(geometry, 1), two(geometry, 2);
  EnergyEvaluation a, b;
  for (int k = 0; k < 2; ++k) {
    one.evaluate(seeds, a);
    two.evaluate(seeds, b);
    EXPECT_EQ(a.cvt, b.cvt);
    EXPECT_EQ(a.boundary, b.boundary);
    for (int i = 0; i < 2000; ++i) {
      ASSERT_EQ(a.cvt_gradient[i], b.cvt_gradient[i]);
      ASSERT_EQ(a.boundary_gradient[i], b.boundary_gradient[i]);
    }
  }
  // Another history: the same values up to rounding.
  SeedEnergy other(geometry, 2);
  other.evaluate(random_seeds(geometry, 2000, 2), b);
  other.evaluate(seeds, b);
  EXPECT_NEAR(a.cvt, b.cvt, 1e-12 * a.cvt);
  EXPECT_NEAR(a.boundary, b.boundary, 1e-12 * a.boundary);
  for (int i = 0; i < 2000; ++i) EXPECT_NEAR(a.mass[i], b.mass[i], 1e-14);
}

}  // namespace
}  // namespace voroseal
