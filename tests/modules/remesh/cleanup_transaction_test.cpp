// The Editor's transactions (cleanup_editor.h) nest, and a rollback restores everything an
// edit may change: positions, triangles, parts, features (pins) and bends.
#include <gtest/gtest.h>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_editor.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using cleanup::Editor;

bool same_features(const std::vector<VertexFeature>& a, const std::vector<VertexFeature>& b) {
  if (a.size() != b.size()) return false;
  for (size_t v = 0; v < a.size(); ++v)
    if (a[v].kind != b[v].kind || a[v].id != b[v].id || a[v].pinned != b[v].pinned) return false;
  return true;
}

TEST(CleanupTransaction, ARollbackUndoesNestedCommittedEditsAndFeatures) {
  const StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface s = test::as_remeshed(input);
  Editor e(s, input);
  const RemeshedSurface before = s;  // as the Editor snapped it
  const int v = s.triangles[0][0];
  e.begin();  // a phase
  e.move(v, e.p(v) + Vec3(0.01, 0.0, 0.0));
  e.pin(v);
  e.mark_bend(v);
  e.begin();  // an edit inside it, kept
  e.kill(1);
  const int added = e.add_triangle(before.triangles[1], before.triangle_part[1]);
  e.commit();
  EXPECT_TRUE(e.in_transaction());
  EXPECT_TRUE(e.changed_in_transaction());
  e.rollback();
  EXPECT_FALSE(e.in_transaction());
  EXPECT_EQ(s.vertices, before.vertices);
  EXPECT_TRUE(same_features(s.features, before.features));
  EXPECT_FALSE(e.is_bend(v));
  EXPECT_TRUE(e.alive(1));
  EXPECT_FALSE(e.alive(added));
  EXPECT_EQ(e.census().count.total(), 0);
}

TEST(CleanupTransaction, AnInnerRollbackKeepsTheOuterEdits) {
  const StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface s = test::as_remeshed(input);
  Editor e(s, input);
  const int v = s.triangles[0][0];
  e.begin();
  e.pin(v);
  e.begin();
  e.kill(1);
  e.rollback();
  EXPECT_TRUE(e.alive(1));
  EXPECT_TRUE(s.features[v].pinned);
  e.commit();
  EXPECT_FALSE(e.in_transaction());
  EXPECT_TRUE(s.features[v].pinned);
}

}  // namespace
}  // namespace voroseal
