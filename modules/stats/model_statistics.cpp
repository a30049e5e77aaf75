#include "modules/stats/model_statistics.h"

#include <chrono>
#include <cstdio>
#include <sstream>

#include "framework/core/error.h"

namespace voroseal {

ModelStatistics measure_model(const StructuralModel& model) {
  ModelStatistics s;
  s.model = model.name;
  const ModelTriangles t = flatten(model);
  s.triangles = static_cast<long>(t.triangles.size());
  std::vector<char> used(model.vertices.size(), 0);
  BoundingBox box;
  for (const Triangle& f : t.triangles)
    for (int v : f)
      if (!used[v]) {
        used[v] = 1;
        ++s.vertices;
        box.extend(model.vertices[v]);
      }
  s.surfaces = static_cast<int>(model.parts.size());
  s.contacts = static_cast<int>(model.contacts.size());
  s.corners = static_cast<int>(model.corners.size());
  s.regions = static_cast<int>(model.regions.size());
  s.interfaces = static_cast<int>(model.interfaces.size());
  s.quality = summarize_quality(model.vertices, t.triangles, 30.0);
  s.bbox_diagonal = box.diagonal();
  return s;
}

FidelityStatistics hausdorff(const StructuralModel& model, const StructuralModel& reference, size_t samples,
                             uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  const ModelTriangles a = flatten(model), b = flatten(reference);
  if (a.triangles.empty()) throw ModelError(model.name + ": no triangle to measure a distance from");
  if (b.triangles.empty()) throw ModelError(reference.name + ": no triangle to measure a distance to");
  // Both in the reference's local frame: the origins are integer points, so the shift is exact
  // for coordinates that were exact in the model's frame.
  const Vec3 shift = model.frame.origin - reference.frame.origin;
  std::vector<Vec3> moved(model.vertices.size());
  for (size_t v = 0; v < moved.size(); ++v) moved[v] = model.vertices[v] + shift;
  FidelityStatistics f;
  f.distance = hausdorff_distance(moved, a.triangles, reference.vertices, b.triangles, samples, seed);
  // Locations of the farthest samples in file coordinates.
  f.distance.a_to_b.max_at += reference.frame.origin;
  f.distance.b_to_a.max_at += reference.frame.origin;
  BoundingBox box;
  for (const Triangle& t : b.triangles)
    for (int v : t) box.extend(reference.vertices[v]);
  f.reference_diagonal = box.diagonal();
  f.hausdorff_pct = f.reference_diagonal > 0 ? 100.0 * f.distance.hausdorff / f.reference_diagonal : 0.0;
  const double ref_area = summarize_quality(reference.vertices, b.triangles).area;
  f.area_ratio = ref_area > 0 ? summarize_quality(moved, a.triangles).area / ref_area : 0.0;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return f;
}

namespace {

nlohmann::json statistics_json(const ModelStatistics& s) {
  const QualitySummary& q = s.quality;
  return {{"model", s.model},
          {"vertices", s.vertices},
          {"triangles", s.triangles},
          {"surfaces", s.surfaces},
          {"contacts", s.contacts},
          {"corners", s.corners},
          {"regions", s.regions},
          {"interfaces", s.interfaces},
          {"min_angle_deg", q.min_angle_deg},
          {"max_angle_deg", q.max_angle_deg},
          {"mean_min_angle_deg", q.mean_min_angle_deg},
          {"triangles_angle_below_30", q.below_threshold},
          {"pct_triangles_angle_below_30", q.pct_below_threshold},
          {"avg_quality", q.avg_q},
          {"min_quality", q.min_q},
          {"area", q.area},
          {"bbox_diagonal", s.bbox_diagonal}};
}

nlohmann::json one_sided_json(const OneSidedDistance& d, double diagonal) {
  auto pct = [&](double x) { return diagonal > 0 ? 100.0 * x / diagonal : 0.0; };
  return {{"max", d.max},
          {"max_pct", pct(d.max)},
          {"mean", d.mean},
          {"mean_pct", pct(d.mean)},
          {"rms", d.rms},
          {"samples", d.samples},
          {"max_at", {d.max_at.x(), d.max_at.y(), d.max_at.z()}}};
}

std::string format(const char* spec, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

}  // namespace

nlohmann::json to_json(const ModelStatistics& statistics, const FidelityStatistics* fidelity,
                       const ModelStatistics* reference) {
  nlohmann::json j = statistics_json(statistics);
  if (fidelity) {
    j["hausdorff_pct"] = fidelity->hausdorff_pct;
    j["hausdorff"] = fidelity->distance.hausdorff;
    j["reference_bbox_diagonal"] = fidelity->reference_diagonal;
    j["area_ratio"] = fidelity->area_ratio;
    j["distance_to_reference"] = one_sided_json(fidelity->distance.a_to_b, fidelity->reference_diagonal);
    j["distance_from_reference"] = one_sided_json(fidelity->distance.b_to_a, fidelity->reference_diagonal);
    j["timing_s"] = {{"hausdorff", fidelity->seconds}};
  }
  if (reference) j["reference"] = statistics_json(*reference);
  return j;
}

std::string to_table(const ModelStatistics& statistics, const FidelityStatistics* fidelity,
                     const ModelStatistics* reference) {
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line, "%-24s %9s %9s %8s %8s %7s %7s %10s %7s %6s %6s %12s %11s%s\n", "model", "vertices",
                "triangles", "surfaces", "contacts", "corners", "regions", "min angle", "% <30", "avg Q", "min Q",
                "area", "bbox diag", fidelity ? "  Hausdorff %" : "");
  out << line;
  auto row = [&](const ModelStatistics& s, const std::string& extra) {
    std::string name = s.model;
    if (name.size() > 24) name = "..." + name.substr(name.size() - 21);
    const QualitySummary& q = s.quality;
    std::snprintf(line, sizeof line, "%-24s %9ld %9ld %8d %8d %7d %7d %10s %7s %6s %6s %12s %11s%s\n", name.c_str(),
                  s.vertices, s.triangles, s.surfaces, s.contacts, s.corners, s.regions,
                  format("%.4g", q.min_angle_deg).c_str(), format("%.1f", q.pct_below_threshold).c_str(),
                  format("%.3f", q.avg_q).c_str(), format("%.3g", q.min_q).c_str(), format("%.6g", q.area).c_str(),
                  format("%.6g", s.bbox_diagonal).c_str(), extra.c_str());
    out << line;
  };
  row(statistics, fidelity ? "  " + format("%12.4g", fidelity->hausdorff_pct) : "");
  if (reference) row(*reference, fidelity ? "  (reference)" : "");
  if (fidelity) {
    const double d = fidelity->reference_diagonal;
    out << "Hausdorff " << format("%.6g", fidelity->distance.hausdorff) << " ("
        << format("%.4g", fidelity->hausdorff_pct) << "% of the reference diagonal): model->reference "
        << format("%.4g", d > 0 ? 100 * fidelity->distance.a_to_b.max / d : 0) << "%, reference->model "
        << format("%.4g", d > 0 ? 100 * fidelity->distance.b_to_a.max / d : 0) << "%; area ratio "
        << format("%.6f", fidelity->area_ratio) << "\n";
  }
  return out.str();
}

}  // namespace voroseal
