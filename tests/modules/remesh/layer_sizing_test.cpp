#include "modules/remesh/layer_sizing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// Vertices of the parts of one group (the soup's group name).
std::vector<int> vertices_of(const StructuralModel& model, const std::string& group) {
  std::vector<int> out;
  for (const SurfacePart& part : model.parts)
    if (part.name == group || part.name.rfind(group + ".", 0) == 0)
      out.insert(out.end(), part.model_vertex.begin(), part.model_vertex.end());
  return out;
}

TEST(LayerSizing, ThinLayerGetsCellsInProportionToItsThicknessGradedAway) {
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.03));
  const double h = 0.5;
  const LayerSizingOptions options;  // ratio 6, sizes >= h / 4, gradation 0.4
  const LayerSizing sizing = thin_layer_sizing(model, h, options);
  ASSERT_TRUE(sizing.refines());
  EXPECT_NEAR(sizing.thinnest, 0.03, 1e-12);
  ASSERT_EQ(sizing.size.size(), model.vertices.size());
  // On both horizons: 6 × 0.03.
  for (const char* horizon : {"lower", "upper"})
    for (int v : vertices_of(model, horizon)) EXPECT_NEAR(sizing.size[v], 0.18, 1e-9) << horizon << " vertex " << v;
  // Away from the layer the size grows at the gradation rate at most, up to h.
  for (double s : sizing.size) {
    EXPECT_GE(s, 0.18 - 1e-12);
    EXPECT_LE(s, h);
  }
  for (int v : vertices_of(model, "zmin")) EXPECT_GT(sizing.size[v], 0.18 + options.gradation * 0.485 - 1e-9);
  // Graded: no two vertices differ by more than the gradation times their distance.
  for (size_t a = 0; a < model.vertices.size(); ++a)
    for (size_t b = a + 1; b < model.vertices.size(); ++b)
      ASSERT_LE(std::abs(sizing.size[a] - sizing.size[b]),
                options.gradation * (model.vertices[a] - model.vertices[b]).norm() + 1e-9);
  // The density makes cells of that size: rho = (h / size)^4.
  const std::vector<double> rho = density_from_sizing(sizing.size, h);
  const int v = vertices_of(model, "lower").front();
  EXPECT_NEAR(rho[v], std::pow(h / 0.18, 4), 1e-6);
}

TEST(LayerSizing, NoLayerThinnerThanTheCellsKeepsTheSize) {
  // Horizon at mid-height of a unit box: 0.5 from the top and bottom, cells of 0.5 want no
  // layer under 0.5 / 6.
  const StructuralModel model = build_model(test::lattice_box(8, true));
  const LayerSizing sizing = thin_layer_sizing(model, 0.5);
  EXPECT_FALSE(sizing.refines());
  for (double s : sizing.size) EXPECT_EQ(s, 0.5);
  // Cells of 0.05 see no thin layer either; cells of 3.5 see the layers 0.5 thick as thin
  // (0.5 < 3.5 / 6).
  EXPECT_FALSE(thin_layer_sizing(model, 0.05).refines());
  const LayerSizing coarse = thin_layer_sizing(model, 3.5);
  EXPECT_TRUE(coarse.refines());
  EXPECT_NEAR(coarse.thinnest, 0.5, 1e-12);
}

TEST(LayerSizing, ContactShorterThanACellGetsCellsOfItsLength) {
  // A layer 0.2 thick in a unit box: each vertical box edge runs 0.4, 0.2 and 0.4 between the
  // corners where the horizons meet it. Cells of 0.5 see no thin layer (0.2 > 0.5 / 6) but would
  // put the two horizons' corners on an edge into one cell, which the mesh building merges.
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.2));
  const double h = 0.5;
  LayerSizingOptions options;
  const LayerSizing sizing = thin_layer_sizing(model, h, options);
  EXPECT_EQ(sizing.thin_samples, 0);
  EXPECT_EQ(sizing.short_contacts, 12);  // 3 on each of the 4 vertical edges
  ASSERT_TRUE(sizing.refines());
  int at_horizons = 0;
  for (const Corner& corner : model.corners) {
    const double z = (model.vertices[corner.vertex] + model.frame.origin).z();
    if (std::abs(z - 0.4) < 1e-9 || std::abs(z - 0.6) < 1e-9) {
      EXPECT_NEAR(sizing.size[corner.vertex], 0.2, 1e-9);  // corner_ratio 1 × 0.2
      ++at_horizons;
    } else {
      EXPECT_LE(sizing.size[corner.vertex], 0.4 + 1e-9);  // the 0.4 contact ending there
    }
  }
  EXPECT_EQ(at_horizons, 8);
  for (size_t a = 0; a < model.vertices.size(); ++a) {
    EXPECT_GE(sizing.size[a], 0.2 - 1e-12);
    EXPECT_LE(sizing.size[a], h);
    for (size_t b = a + 1; b < model.vertices.size(); ++b)
      ASSERT_LE(std::abs(sizing.size[a] - sizing.size[b]),
                options.gradation * (model.vertices[a] - model.vertices[b]).norm() + 1e-9);
  }
  // Off: nothing to refine. Contacts shorter than the finest cells (h / 4) are left to merge.
  options.corner_ratio = 0.0;
  EXPECT_FALSE(thin_layer_sizing(model, h, options).refines());
  EXPECT_EQ(thin_layer_sizing(model, 1.0).short_contacts, 8);  // the 0.2 ones are under 1.0 / 4
}

// A layer pinching out at `angle_deg`: bottom z = 0 and top z = x tan(angle) over the unit
// square, on n × n lattices, closed by the plates x = 1, y = 0 and y = 1. One region.
SurfaceSoup lattice_pinch_out(int n, double angle_deg) {
  SurfaceSoup soup;
  soup.source = "lattice_pinch_out";
  const double slope = std::tan(angle_deg * M_PI / 180.0);
  soup.groups = {{"bottom", "bottom", SurfaceKind::Horizon, ""},
                 {"top", "top", SurfaceKind::Horizon, ""},
                 {"end", "end", SurfaceKind::Boundary, ""},
                 {"south", "south", SurfaceKind::Boundary, ""},
                 {"north", "north", SurfaceKind::Boundary, ""}};
  auto add = [&](int g, int a, int b, int c) {
    soup.triangles.push_back({a, b, c});
    soup.triangle_group.push_back(g);
  };
  // Lattice points (i, j) of the bottom, then of the top (the tip line i = 0 shared).
  auto bottom = [&](int i, int j) { return j * (n + 1) + i; };
  auto top = [&](int i, int j) { return i == 0 ? bottom(0, j) : (n + 1) * (n + 1) + j * (n + 1) + i; };
  for (int top_plate = 0; top_plate < 2; ++top_plate)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
        soup.points.push_back(Vec3(x, y, top_plate ? slope * x : 0.0));
      }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      add(0, bottom(i, j), bottom(i + 1, j + 1), bottom(i + 1, j));
      add(0, bottom(i, j), bottom(i, j + 1), bottom(i + 1, j + 1));
      add(1, top(i, j), top(i + 1, j), top(i + 1, j + 1));
      add(1, top(i, j), top(i + 1, j + 1), top(i, j + 1));
    }
  for (int j = 0; j < n; ++j) {
    add(2, bottom(n, j), bottom(n, j + 1), top(n, j + 1));
    add(2, bottom(n, j), top(n, j + 1), top(n, j));
  }
  for (int i = 0; i < n; ++i) {
    for (int side = 0; side < 2; ++side) {
      const int j = side ? n : 0, g = side ? 4 : 3;
      if (i == 0) {
        side ? add(g, bottom(0, j), top(1, j), bottom(1, j)) : add(g, bottom(0, j), bottom(1, j), top(1, j));
        continue;
      }
      if (side) {
        add(g, bottom(i, j), top(i + 1, j), bottom(i + 1, j));
        add(g, bottom(i, j), top(i, j), top(i + 1, j));
      } else {
        add(g, bottom(i, j), bottom(i + 1, j), top(i + 1, j));
        add(g, bottom(i, j), top(i + 1, j), top(i, j));
      }
    }
  }
  return soup;
}

TEST(LayerSizing, PinchOutTipKeepsTheCellSize) {
  // A wedge of 10 deg: the layer thins to nothing at x = 0. The tip keeps the size h (finer
  // cells would only resolve thinner wedges there), and the size falls off from it at the
  // gradation rate; without the pinch-out rule the tip is refined to about h / 4.
  const StructuralModel model = build_model(lattice_pinch_out(10, 10.0));
  ASSERT_EQ(model.regions.size(), 1u);
  const double h = 0.5;
  LayerSizingOptions options;
  const LayerSizing sizing = thin_layer_sizing(model, h, options);
  ASSERT_TRUE(sizing.refines());
  EXPECT_GT(sizing.pinch_vertices, 0);
  // Layers thinner than h / 6 only within h of the tip: no thinnest layer away from it.
  EXPECT_TRUE(std::isinf(sizing.thinnest));
  options.pinch_angle_deg = 0.0;
  const LayerSizing unanchored = thin_layer_sizing(model, h, options);
  EXPECT_EQ(unanchored.pinch_vertices, 0);
  std::vector<int> tips;
  for (size_t v = 0; v < model.vertices.size(); ++v)
    if ((model.vertices[v] + model.frame.origin).x() < 1e-12) tips.push_back(static_cast<int>(v));
  ASSERT_FALSE(tips.empty());
  for (int v : tips) {
    EXPECT_EQ(sizing.size[v], h);
    // h / 4 at the nearest thin samples (the centroids of the tip triangles), graded.
    EXPECT_LT(unanchored.size[v], h / options.max_refinement + options.gradation * 0.2);
  }
  for (size_t v = 0; v < model.vertices.size(); ++v) {
    double to_tip = 1e300;
    for (int t : tips) to_tip = std::min(to_tip, (model.vertices[v] - model.vertices[t]).norm());
    EXPECT_GE(sizing.size[v], h - options.gradation * to_tip - 1e-9);
    EXPECT_GE(sizing.size[v], unanchored.size[v]);
  }
}

TEST(LayerSizing, RejectsBadOptions) {
  const StructuralModel model = build_model(test::lattice_box(4, true));
  EXPECT_THROW(thin_layer_sizing(model, 0.0), ParameterError);
  EXPECT_THROW(thin_layer_sizing(model, std::nan("")), ParameterError);
  LayerSizingOptions options;
  options.max_refinement = 0.5;
  EXPECT_THROW(thin_layer_sizing(model, 1.0, options), ParameterError);
  options = {};
  options.facing_angle_deg = 90.0;
  EXPECT_THROW(thin_layer_sizing(model, 1.0, options), ParameterError);
  options = {};
  options.corner_ratio = -1.0;
  EXPECT_THROW(thin_layer_sizing(model, 1.0, options), ParameterError);
}

}  // namespace
}  // namespace voroseal
