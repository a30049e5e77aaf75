#include "modules/tetmesh/tetgen_plc.h"

#include "framework/core/error.h"

namespace voroseal {

std::vector<int> plc_vertices(const ModelTriangles& flat, size_t model_vertices) {
  std::vector<int> vertices;
  std::vector<bool> used(model_vertices, false);
  for (const Triangle& t : flat.triangles)
    for (int v : t)
      if (!used[v]) {
        used[v] = true;
        vertices.push_back(v);
      }
  return vertices;
}

PlcMap build_plc(const StructuralModel& model, tetgenio& in,
                 const std::vector<double>& region_max_volume) {
  PlcMap map;
  const ModelTriangles flat = flatten(model);
  if (flat.triangles.empty()) throw ModelError("model '" + model.name + "' has no triangles to tet-mesh");
  map.region_points = region_points(model);  // throws first: cheaper than a failed TetGen run

  // Only vertices used by triangles: TetGen would insert any other point as a volume vertex.
  map.point_vertex = plc_vertices(flat, model.vertices.size());
  map.vertex_point.assign(model.vertices.size(), -1);
  for (size_t i = 0; i < map.point_vertex.size(); ++i) map.vertex_point[map.point_vertex[i]] = static_cast<int>(i);
  map.facet_triangle = flat.triangles;
  map.facet_part = flat.part;

  in.firstnumber = 0;
  in.mesh_dim = 3;
  in.numberofpoints = static_cast<int>(map.point_vertex.size());
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int i = 0; i < in.numberofpoints; ++i)
    for (int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = model.vertices[map.point_vertex[i]][d];

  in.numberoffacets = static_cast<int>(flat.triangles.size());
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  in.facetmarkerlist = new int[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::polygon& polygon = facet.polygonlist[0];
    tetgenio::init(&polygon);
    polygon.numberofvertices = 3;
    polygon.vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) polygon.vertexlist[k] = map.vertex_point[flat.triangles[f][k]];
    in.facetmarkerlist[f] = flat.part[f] + 1;
  }

  in.numberofregions = static_cast<int>(map.region_points.size());
  in.regionlist = new REAL[5 * in.numberofregions];
  for (int r = 0; r < in.numberofregions; ++r) {
    REAL* entry = in.regionlist + 5 * r;
    for (int d = 0; d < 3; ++d) entry[d] = map.region_points[r].point[d];
    entry[3] = r + 1;  // attribute (used with A)
    // The region's volume bound (with a bare switch `a`); -1: none.
    const bool bounded =
        static_cast<size_t>(r) < region_max_volume.size() && region_max_volume[r] > 0.0;
    entry[4] = bounded ? region_max_volume[r] : -1.0;
  }
  return map;
}

void reorder_facets(tetgenio& in, PlcMap& map, const std::vector<int>& order) {
  const int n = in.numberoffacets;
  // The facet structs only hold pointers: moving them moves the polygons, nothing is freed.
  auto* facets = new tetgenio::facet[n];
  auto* markers = new int[n];
  std::vector<Triangle> triangles(n);
  std::vector<int> parts(n);
  for (int i = 0; i < n; ++i) {
    facets[i] = in.facetlist[order[i]];
    markers[i] = in.facetmarkerlist[order[i]];
    triangles[i] = map.facet_triangle[order[i]];
    parts[i] = map.facet_part[order[i]];
  }
  delete[] in.facetlist;
  delete[] in.facetmarkerlist;
  in.facetlist = facets;
  in.facetmarkerlist = markers;
  map.facet_triangle = std::move(triangles);
  map.facet_part = std::move(parts);
}

}  // namespace voroseal
