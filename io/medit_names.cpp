#include "io/medit_names.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "framework/core/error.h"

namespace voroseal {

namespace {

constexpr long long kMaxRef = 1000000;  // refs beyond this are refused (as Medit name tables)

nlohmann::json entry(int id, const std::string& name) {
  return {{"ref", id + 1}, {"name", name}};
}

// Entries of one list, one a line.
void write_list(const char* key, const std::vector<nlohmann::json>& entries, bool last,
                std::string& out) {
  out += "  \"" + std::string(key) + "\": [";
  for (size_t i = 0; i < entries.size(); ++i)
    out += std::string(i ? ",\n    " : "\n    ") + entries[i].dump();
  out += std::string(entries.empty() ? "]" : "\n  ]") + (last ? "\n" : ",\n");
}

std::vector<nlohmann::json> named(const std::vector<std::string>& names) {
  std::vector<nlohmann::json> entries;
  for (size_t i = 0; i < names.size(); ++i) entries.push_back(entry(static_cast<int>(i), names[i]));
  return entries;
}

// 1-based line of byte `at` of `text`.
long line_of(std::string_view text, size_t at) {
  at = std::min(at, text.size());
  return 1 + static_cast<long>(std::count(text.begin(), text.begin() + at, '\n'));
}

}  // namespace

std::string medit_names_path(const std::string& mesh_path) {
  return mesh_path + ".json";
}

std::string medit_names_text(const VolumeMesh& mesh) {
  const nlohmann::json counts = {{"vertices", mesh.vertices.size()},
                                 {"triangles", mesh.triangles.size()},
                                 {"tetrahedra", mesh.tets.size()},
                                 {"edges", mesh.edges.size()},
                                 {"corners", mesh.corners.size()}};
  std::string out = "{\n  \"voroseal_medit_names\": 1,\n  \"counts\": " + counts.dump() + ",\n";
  std::vector<nlohmann::json> surfaces = named(mesh.surface_names);
  for (size_t i = 0; i < surfaces.size(); ++i)
    surfaces[i]["kind"] = to_string(mesh.surface_kind(static_cast<int>(i)));
  write_list("surfaces", surfaces, false, out);
  write_list("regions", named(mesh.region_names), false, out);
  write_list("contacts", named(mesh.contact_names), false, out);
  write_list("corners", named(mesh.corner_names), true, out);
  return out + "}\n";
}

void apply_medit_names(const TextSource& sidecar, VolumeMesh& mesh) {
  const std::string& file = sidecar.name();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(sidecar.text().begin(), sidecar.text().end());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, line_of(sidecar.text(), e.byte > 0 ? e.byte - 1 : 0),
                     std::string("not valid JSON: ") + e.what());
  }
  auto fail = [&](const std::string& message) { throw InputError(file, 0, message); };
  if (!doc.is_object() || !doc.contains("voroseal_medit_names"))
    fail("not a voroseal names sidecar (no \"voroseal_medit_names\")");
  if (doc["voroseal_medit_names"] != 1) fail("unsupported \"voroseal_medit_names\" version");
  // The counts tie the sidecar to the mesh it was written with.
  const std::pair<const char*, size_t> counts[] = {{"vertices", mesh.vertices.size()},
                                                   {"triangles", mesh.triangles.size()},
                                                   {"tetrahedra", mesh.tets.size()},
                                                   {"edges", mesh.edges.size()},
                                                   {"corners", mesh.corners.size()}};
  if (!doc.contains("counts") || !doc["counts"].is_object()) fail("\"counts\" must be an object");
  for (const auto& [key, actual] : counts) {
    const nlohmann::json& n = doc["counts"].value(key, nlohmann::json());
    if (!n.is_number_unsigned() || n.get<size_t>() != actual)
      fail(std::string("counts.") + key + " is " + n.dump() + " but the mesh has " +
           std::to_string(actual) + ": the sidecar belongs to another mesh (remove it)");
  }
  auto apply = [&](const char* key, std::vector<std::string>& names, const char* prefix,
                   bool kinds) {
    if (!doc.contains(key)) return;
    const nlohmann::json& list = doc[key];
    if (!list.is_array()) fail(std::string("\"") + key + "\" must be an array");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string at = std::string(key) + "[" + std::to_string(i) + "]";
      const nlohmann::json& e = list[i];
      if (!e.is_object() || !e.contains("ref") || !e["ref"].is_number_integer() ||
          !e.contains("name") || !e["name"].is_string())
        fail(at + " needs an integer \"ref\" and a string \"name\"");
      const long long ref = e["ref"].get<long long>();
      if (ref < 1 || ref > kMaxRef) fail(at + ": ref " + std::to_string(ref) + " out of range");
      const size_t id = static_cast<size_t>(ref - 1);
      while (names.size() <= id) names.push_back(prefix + std::to_string(names.size() + 1));
      names[id] = e["name"].get<std::string>();
      if (!kinds) continue;
      if (e.contains("kind") && !e["kind"].is_string()) fail(at + ": \"kind\" must be a string");
      mesh.surface_kinds.resize(names.size(), SurfaceKind::Unknown);
      mesh.surface_kinds[id] = surface_kind_from_string(e.value("kind", std::string()));
    }
  };
  apply("surfaces", mesh.surface_names, "surface_", true);
  apply("regions", mesh.region_names, "region_", false);
  apply("contacts", mesh.contact_names, "contact_", false);
  apply("corners", mesh.corner_names, "corner_", false);
}

}  // namespace voroseal
