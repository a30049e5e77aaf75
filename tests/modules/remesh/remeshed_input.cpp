#include "tests/modules/remesh/remeshed_input.h"

#include "framework/model/structural_model.h"

namespace voroseal::test {

RemeshedSurface as_remeshed(const StructuralModel& m) {
  RemeshedSurface s;
  s.vertices = m.vertices;
  s.features.assign(m.vertices.size(), VertexFeature{});
  for (size_t p = 0; p < m.parts.size(); ++p)
    for (int v : m.parts[p].model_vertex)
      s.features[v] = {VertexFeature::Surface, static_cast<int>(p)};
  for (size_t c = 0; c < m.contacts.size(); ++c)
    for (int v : m.contacts[c].vertices)
      s.features[v] = {VertexFeature::Contact, static_cast<int>(c)};
  for (size_t k = 0; k < m.corners.size(); ++k)
    s.features[m.corners[k].vertex] = {VertexFeature::Corner, static_cast<int>(k)};
  const ModelTriangles t = flatten(m);
  s.triangles = t.triangles;
  s.triangle_part = t.part;
  return s;
}

}  // namespace voroseal::test
