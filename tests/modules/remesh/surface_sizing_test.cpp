#include "modules/remesh/surface_sizing.h"

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

int interface_named(const StructuralModel& model, const std::string& name) {
  for (size_t i = 0; i < model.interfaces.size(); ++i)
    if (model.interfaces[i].name == name) return static_cast<int>(i);
  return -1;
}

// Model vertices are in a local frame; the test models are laid out in file coordinates.
Vec3 file_point(const StructuralModel& model, int v) {
  return model.vertices[v] + model.frame.origin;
}

std::vector<int> vertices_of(const StructuralModel& model, const std::string& name) {
  std::vector<int> out;
  for (int p : model.interfaces.at(interface_named(model, name)).parts)
    out.insert(out.end(), model.parts[p].model_vertex.begin(), model.parts[p].model_vertex.end());
  return out;
}

TEST(SurfaceSizing, RulesAreReadFromCommasAndLinesAndBadOnesRefused) {
  const std::vector<SizeRule> rules =
      parse_size_rules(" horizon=0.1, kind:fault = 5e-2\nF*=3,", "--size");
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0].pattern, "horizon");
  EXPECT_EQ(rules[0].size, 0.1);
  EXPECT_EQ(rules[1].pattern, "kind:fault");
  EXPECT_EQ(rules[1].size, 0.05);
  EXPECT_EQ(rules[2].pattern, "F*");
  for (const char* bad : {"horizon", "=1", "a=-1", "a=0", "a=abc", "a=inf", "a=1x"})
    EXPECT_THROW(parse_size_rules(bad, "--size"), ParameterError) << bad;
}

TEST(SurfaceSizing, NamedSurfaceGetsItsSizeAndTheOthersGradeAwayFromIt) {
  const StructuralModel model = build_model(test::lattice_box(8, true));
  const double h = 0.25, gradation = 1.3, slope = gradation - 1.0;
  const SurfaceSizing s = surface_sizing(model, {{"horizon", 0.05}}, h, gradation);
  ASSERT_EQ(s.size.size(), model.vertices.size());
  for (int v : vertices_of(model, "horizon")) EXPECT_DOUBLE_EQ(s.size[v], 0.05);
  for (double x : s.size) {
    EXPECT_GE(x, 0.05);
    EXPECT_LE(x, h);
  }
  // Graded along the surfaces: a path is never shorter than the straight line, so each vertex
  // is at least 0.05 + slope × its distance to the horizon (z = 0.5), and neighbours differ
  // by at most slope × their distance.
  for (size_t v = 0; v < model.vertices.size(); ++v)
    EXPECT_GE(s.size[v],
              std::min(h, 0.05 + slope * std::abs(file_point(model, v).z() - 0.5)) - 1e-12);
  const ModelTriangles flat = flatten(model);
  for (const Triangle& t : flat.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      EXPECT_LE(std::abs(s.size[a] - s.size[b]),
                slope * (model.vertices[a] - model.vertices[b]).norm() + 1e-12);
    }
  EXPECT_EQ(s.interface_size[interface_named(model, "horizon")], 0.05);
  EXPECT_EQ(s.interface_size[interface_named(model, "zmin")], h);
  EXPECT_EQ(s.rule_matches, std::vector<int>{1});
  // The horizon's cells all want 0.05; the bottom's are between the horizon's and h.
  EXPECT_NEAR(s.interface_target[interface_named(model, "horizon")], 0.05, 1e-12);
  const double bottom = s.interface_target[interface_named(model, "zmin")];
  EXPECT_GT(bottom, 0.05);
  EXPECT_LE(bottom, h);
}

TEST(SurfaceSizing, ACoarserSurfaceKeepsTheFinerSizeWhereItMeetsOthers) {
  // The bottom at 0.5 under cells of 0.25: its border (shared with the sides) stays 0.25 and the
  // size grows inward at the gradation's rate, 0.25 + 0.3 × 0.5 at its centre.
  const StructuralModel model = build_model(test::lattice_box(8, true));
  const SurfaceSizing s = surface_sizing(model, {{"zmin", 0.5}}, 0.25, 1.3);
  double centre = 0.0;
  for (int v : vertices_of(model, "zmin")) {
    const Vec3 x = file_point(model, v);
    EXPECT_LE(s.size[v], 0.5);
    if (x.x() == 0.0 || x.x() == 1.0 || x.y() == 0.0 || x.y() == 1.0) {
      EXPECT_EQ(s.size[v], 0.25);
    }
    if (std::abs(x.x() - 0.5) < 1e-12 && std::abs(x.y() - 0.5) < 1e-12) centre = s.size[v];
  }
  EXPECT_NEAR(centre, 0.25 + 0.3 * 0.5, 1e-12);
}

TEST(SurfaceSizing, ARuleThatNamesNothingIsRefusedWithTheNames) {
  const StructuralModel model = build_model(test::lattice_box(8, true));
  try {
    surface_sizing(model, {{"fault*", 0.1}}, 0.25, 1.3);
    FAIL() << "a rule naming nothing was accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("'fault*' names no surface"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("horizon"), std::string::npos) << e.what();
  }
  EXPECT_THROW(surface_sizing(model, {{"horizon", 0.1}}, 0.25, 0.9), ParameterError);
  // Globs and kinds: z* names the bottom and the top.
  EXPECT_EQ(surface_sizing(model, {{"z*", 0.1}}, 0.25, 1.3).rule_matches, std::vector<int>{2});
}

TEST(SizeField, SizesGrowFromItsPointsAtTheSlope) {
  const SizeField field({Vec3(0, 0, 0), Vec3(10, 0, 0)}, {1.0, 4.0});
  EXPECT_DOUBLE_EQ(field.size_at(Vec3(0, 0, 0), 0.3), 1.0);
  EXPECT_DOUBLE_EQ(field.size_at(Vec3(0, 3, 0), 0.3), 1.0 + 0.3 * 3.0);
  // Next to the coarse point the fine one's cone is smaller until 1 + 0.3 d = 4.
  EXPECT_DOUBLE_EQ(field.size_at(Vec3(9, 0, 0), 0.3), 1.0 + 0.3 * 9.0);
  EXPECT_DOUBLE_EQ(field.size_at(Vec3(10, 0, 0), 0.3), 4.0);
  EXPECT_EQ(field.nearest(Vec3(8, 1, 0)), 1);
  EXPECT_THROW(SizeField({Vec3::Zero()}, {0.0}), ParameterError);
  EXPECT_THROW(SizeField({}, {}), ParameterError);
}

TEST(SizeField, OnlyRefinesAndIsGradedAlongTheSurfaces) {
  // A point of size 0.02 in the middle of the horizon of the unit box, cells of 0.25 elsewhere.
  const StructuralModel model = build_model(test::lattice_box(8, true));
  const Vec3 well = Vec3(0.5, 0.5, 0.5) - model.frame.origin;
  const SizeField field({well}, {0.02});
  const double h = 0.25, gradation = 1.3;
  const SurfaceSizing s = surface_sizing(model, {}, h, gradation, &field);
  for (size_t v = 0; v < model.vertices.size(); ++v) {
    EXPECT_LE(s.size[v], h);
    EXPECT_GE(s.size[v], std::min(h, 0.02 + 0.3 * (model.vertices[v] - well).norm()) - 1e-12);
  }
  const ModelTriangles flat = flatten(model);
  for (const Triangle& t : flat.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      EXPECT_LE(std::abs(s.size[a] - s.size[b]),
                0.3 * (model.vertices[a] - model.vertices[b]).norm() + 1e-12);
    }
  // The horizon's vertex at the point gets its size; the box's corners keep h.
  double at_well = h;
  for (size_t v = 0; v < model.vertices.size(); ++v)
    if ((model.vertices[v] - well).norm() < 1e-9) at_well = s.size[v];
  EXPECT_DOUBLE_EQ(at_well, 0.02);
  EXPECT_GT(s.seed_factor, 1.0);
}

TEST(SizeField, InputTrianglesLargerThanTheSizesAreBisected) {
  // A point inside a horizon triangle (no vertex there): the triangles around it are bisected
  // until their edges are no longer than the sizes at their ends; the surfaces do not move.
  StructuralModel model = build_model(test::lattice_box(4, true));
  const double area = model.area();
  const size_t triangles = model.num_triangles();
  const Vec3 well = Vec3(0.3, 0.4, 0.5) - model.frame.origin;
  const SizeField field({well}, {0.02});
  const double h = 0.25, gradation = 1.3;
  // No round past the budget: with the model's own count, nothing is split.
  StructuralModel capped = model;
  EXPECT_EQ(refine_for_sizes(capped, {}, h, gradation, &field, capped.num_triangles()), 0);
  const int split = refine_for_sizes(model, {}, h, gradation, &field, 1000000);
  EXPECT_GT(split, 0);
  EXPECT_GT(model.num_triangles(), triangles);
  EXPECT_NEAR(model.area(), area, 1e-12 * area);
  const SurfaceSizing s = surface_sizing(model, {}, h, gradation, &field);
  const ModelTriangles flat = flatten(model);
  double nearest = 1e30;
  for (const Triangle& t : flat.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      nearest = std::min(nearest, (model.vertices[a] - well).norm());
      const double shorter = std::min(s.size[a], s.size[b]);
      if (shorter < h) {
        EXPECT_LE((model.vertices[a] - model.vertices[b]).norm(), shorter + 1e-12);
      }
    }
  EXPECT_LT(nearest, 0.05);  // a vertex came near the point, where the size is asked
  // Away from the point (sizes of h) nothing was split: the model stays as coarse as it was.
  StructuralModel coarse = build_model(test::lattice_box(4, true));
  EXPECT_EQ(refine_for_sizes(coarse, {}, h, gradation, nullptr, 1000000), 0);
}

}  // namespace
}  // namespace voroseal
