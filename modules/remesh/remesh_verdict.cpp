#include "modules/remesh/remesh_verdict.h"

#include <string>

namespace voroseal {

CheckEntry holes_made(const StructuralModel& input, const StructuralModel& output,
                      const std::vector<int>& input_part_of_output, int max_places) {
  CheckEntry entry;
  entry.name = "holes_made";
  // Input parts with a free border of their own (fault tips, open horizons).
  std::vector<char> bordered(input.parts.size(), 0);
  for (const Contact& c : input.contacts)
    if (c.is_free_border())
      for (int p : c.parts) bordered[p] = 1;
  for (const Contact& c : output.contacts) {
    if (!c.is_free_border()) continue;
    bool hole = false;
    for (int p : c.parts) {
      const int q = p < static_cast<int>(input_part_of_output.size()) ? input_part_of_output[p] : -1;
      hole = hole || (q >= 0 && !bordered[q]);
    }
    if (!hole) continue;
    entry.count += static_cast<long>(c.vertices.size()) - 1;
    if (entry.examples.size() < static_cast<size_t>(max_places))
      entry.examples.push_back({"free border of " + std::to_string(c.vertices.size() - 1) +
                                    " edges on a surface sealed in the input",
                                output.vertices[c.vertices.front()] + output.frame.origin,
                                {}});
  }
  entry.message = entry.count == 0 ? "no free border the input does not have"
                                   : std::to_string(entry.count) +
                                         " free border edges on surfaces sealed in the input";
  return entry;
}

CheckEntry no_region_gained(const StructuralModel& input, const TopologyReport& topology,
                            int max_places) {
  CheckEntry entry;
  entry.name = "no_region_gained";
  entry.count = static_cast<long>(topology.regions_gained.size());
  for (const GainedRegion& g : topology.regions_gained) {
    if (entry.examples.size() >= static_cast<size_t>(max_places)) break;
    std::string what = "output region " + std::to_string(g.output_region) + " is a pocket";
    if (g.like_input >= 0)
      what += " inside '" + input.regions[static_cast<size_t>(g.like_input)].name + "'";
    entry.examples.push_back({what, g.location + input.frame.origin, {}});
  }
  entry.message = entry.count == 0
                      ? "every output region is an input region"
                      : std::to_string(entry.count) +
                            " output regions are no input region (pockets between surfaces)";
  return entry;
}

const char* feature_kind(VertexFeature::Kind kind) {
  return kind == VertexFeature::Surface   ? "surface"
         : kind == VertexFeature::Contact ? "contact"
         : kind == VertexFeature::Corner  ? "corner"
                                          : "unknown";
}

CheckEntry topology_kept(const StructuralModel& input, const TopologyReport& topology,
                         int max_places) {
  CheckEntry entry;
  entry.name = "topology_kept";
  const FeatureAudit& audit = topology.features;
  entry.count = static_cast<long>(audit.lost.size() + audit.gained.size() +
                                  audit.regions_lost.size() + audit.region_contacts_lost.size());
  auto add = [&](const std::string& what, const Vec3& local) {
    if (entry.examples.size() < static_cast<size_t>(max_places))
      entry.examples.push_back({what, local + input.frame.origin, {}});
  };
  for (const LostFeature& f : audit.lost)
    add(std::string("input ") + feature_kind(f.kind) + " " + std::to_string(f.id) +
            " without a counterpart",
        f.location);
  // A gained feature is two surfaces touching where the input keeps them apart.
  for (const LostFeature& f : audit.gained)
    add(std::string("output ") + feature_kind(f.kind) + " " + std::to_string(f.id) +
            " that the input does not have",
        f.location);
  // A region or a region contact is lost somewhere along its extent: all of its places.
  for (const LostRegion& r : audit.regions_lost)
    for (const Vec3& x : r.places)
      add("input region '" + input.regions[static_cast<size_t>(r.region)].name +
              "' without a counterpart",
          x);
  for (const LostRegionContact& c : audit.region_contacts_lost)
    for (const Vec3& x : c.places)
      add("input regions '" + input.regions[static_cast<size_t>(c.a)].name + "' and '" +
              input.regions[static_cast<size_t>(c.b)].name + "' no longer touch",
          x);
  entry.message = entry.count == 0
                      ? "every input surface part, contact, corner and region kept"
                      : std::to_string(audit.lost.size()) + " surface parts, contacts or corners, " +
                            std::to_string(audit.gained.size()) + " gained, " +
                            std::to_string(audit.regions_lost.size()) + " regions and " +
                            std::to_string(audit.region_contacts_lost.size()) +
                            " region contacts of the input without a counterpart";
  return entry;
}

}  // namespace voroseal
