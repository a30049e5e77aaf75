// clean_up(): the phases of the schedule (cleanup_schedule.h) in turn, each kept only when it
// leaves no more defects than it found, then what the census finds left.
#include "modules/remesh/mesh_cleanup.h"

#include <optional>

#include "modules/remesh/cleanup_phase.h"
#include "modules/remesh/cleanup_schedule.h"

namespace voroseal {

using namespace cleanup;

CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input,
                       const SurfaceProjector& projector, const CleanupOptions& options,
                       Progress* progress) {
  CleanupReport report;
  Editor e(surface, input);
  e.ignore_crossings_between(options.crossing_parts);
  e.set_projector(&projector);
  const ContactArcs arcs(input);
  e.set_fidelity(options.fidelity_tolerance, &arcs);
  e.set_thresholds(options.thresholds);
  // The sharp points of the mesh building are bends of their contacts like those the fidelity
  // refinement adds: with a tolerance, they slide and go where the contact keeps to the input.
  if (options.fidelity_tolerance > 0.0)
    for (size_t v = 0; v < surface.vertices.size(); ++v)
      if (surface.features[v].kind == VertexFeature::Contact && surface.features[v].pinned)
        e.mark_bend(static_cast<int>(v));
  const CleanupContext context{projector, options, options.thresholds, report};
  DefectCensus census(e);
  for (const PhaseSpec& phase : cleanup_schedule(options.thresholds)) {
    if (phase.rounds <= 0 || !phase.enabled(context)) continue;
    std::optional<ProgressStep> step;
    if (progress) step.emplace(*progress, phase.name);
    report.phases.push_back(run_phase(e, phase, context, census, report));
    if (step) step->finish();
  }
  const Violations& defects = census.count();
  report.intersections_left = defects.crossings;
  report.holes_left = defects.holes;
  report.leaks_left = defects.leaks;
  report.degenerate_left = defects.degenerate;
  report.pinches_left = defects.pinches;
  report.folds_left = defects.folds;
  e.finish();
  return report;
}

void RemeshedSurface::remove_triangles(const std::vector<char>& dead) {
  size_t kept = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (t < dead.size() && dead[t]) continue;
    triangles[kept] = triangles[t];
    triangle_part[kept] = triangle_part[t];
    ++kept;
  }
  triangles.resize(kept);
  triangle_part.resize(kept);
  remove_unused_vertices();
}

void RemeshedSurface::remove_unused_vertices() {
  std::vector<int> index(vertices.size(), -1);
  int n = 0;
  for (const Triangle& t : triangles)
    for (int v : t)
      if (index[v] < 0) index[v] = n++;
  std::vector<Vec3> new_vertices(n);
  std::vector<VertexFeature> new_features(n);
  for (size_t v = 0; v < vertices.size(); ++v)
    if (index[v] >= 0) {
      new_vertices[index[v]] = vertices[v];
      new_features[index[v]] = features[v];
    }
  for (Triangle& t : triangles)
    for (int& v : t) v = index[v];
  vertices = std::move(new_vertices);
  features = std::move(new_features);
}

}  // namespace voroseal
