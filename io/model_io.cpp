// Dispatch of model and volume-mesh files to their format by extension (case-insensitive).
#include "io/model_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "framework/core/error.h"
#include "io/atomic_file.h"
#include "io/gmsh_format.h"
#include "io/gocad_model3d.h"
#include "io/gocad_tsurf.h"
#include "io/line_reader.h"
#include "io/medit_format.h"
#include "io/medit_names.h"
#include "io/obj_format.h"
#include "io/tetgen_format.h"
#include "io/vtk_format.h"

namespace voroseal {

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

namespace {

std::string list(const std::vector<std::string>& extensions) {
  std::string s;
  for (const std::string& e : extensions) s += (s.empty() ? "" : " ") + e;
  return s;
}

}  // namespace

std::vector<std::string> readable_model_extensions() { return {".ml", ".ts", ".obj", ".mesh", ".vtu", ".msh"}; }
std::vector<std::string> writable_model_extensions() { return {".ml", ".ts", ".obj", ".mesh", ".vtu", ".msh"}; }
std::vector<std::string> writable_volume_extensions() { return {".mesh", ".vtu", ".msh", ".node", ".ele"}; }

namespace {

void require_readable_extension(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, not a model file");
  const std::string ext = file_extension(path);
  const auto& readable = readable_model_extensions();
  if (std::find(readable.begin(), readable.end(), ext) == readable.end())
    throw InputError(path, 0, "unknown model file extension '" + ext + "' (supported: " + list(readable) + ")");
}

SurfaceSoup read_soup_source(const TextSource& source) {
  const std::string ext = file_extension(source.name());
  if (ext == ".ml") return read_model3d(source);
  if (ext == ".ts") return read_tsurf(source);
  if (ext == ".obj") return read_obj(source);
  if (ext == ".mesh") return read_medit(source);
  if (ext == ".vtu") return read_vtu(source);
  return read_msh(source);
}

// The writer of a model format, chosen by the extension of `path`. \throws OutputError
std::function<void(std::ostream&)> model_writer(const StructuralModel& model,
                                                const std::string& path,
                                                const WriteOptions& options) {
  const std::string ext = file_extension(path);
  const int precision = options.precision;
  std::function<void(std::ostream&)> write;
  if (ext == ".ml")
    write = [&model, precision](std::ostream& out) { write_model3d(model, out, precision); };
  else if (ext == ".ts")
    write = [&model, precision](std::ostream& out) { write_tsurf(model, out, precision); };
  else if (ext == ".obj")
    write = [&model, precision](std::ostream& out) { write_obj(model, out, precision); };
  else if (ext == ".mesh")
    write = [&model, precision](std::ostream& out) { write_medit(model, out, precision); };
  else if (ext == ".vtu" && options.ascii)
    write = [&model, precision](std::ostream& out) { write_vtu_ascii(model, out, precision); };
  else if (ext == ".vtu")
    write = [&model, precision](std::ostream& out) { write_vtu(model, out, precision); };
  else if (ext == ".msh")
    write = [&model, precision](std::ostream& out) { write_msh(model, out, precision); };
  else
    throw OutputError(path + ": unknown model file extension '" + ext +
                      "' (supported: " + list(writable_model_extensions()) + ")");
  return write;
}

}  // namespace

SurfaceSoup read_soup(const std::string& path) {
  require_readable_extension(path);
  return read_soup_source(load_text(path));
}

StructuralModel read_model(const std::string& path, const ReadOptions& options) {
  return build_model(read_soup(path), options.build);
}

StructuralModel read_model_text(std::string text, const std::string& path,
                                const ReadOptions& options) {
  require_readable_extension(path);
  return build_model(read_soup_source(TextSource{path, std::move(text)}), options.build);
}

void write_model(const StructuralModel& model, const std::string& path,
                 const WriteOptions& options) {
  write_atomically(path, options.protected_paths, model_writer(model, path, options));
}

std::string model_text(const StructuralModel& model, const std::string& path,
                       const WriteOptions& options) {
  std::ostringstream out;
  model_writer(model, path, options)(out);
  return out.str();
}

void write_text(const std::string& text, const std::string& path, const WriteOptions& options) {
  write_atomically(path, options.protected_paths, [&](std::ostream& out) { out << text; });
}

VolumeMesh read_volume_mesh(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, not a volume mesh");
  const std::string ext = file_extension(path);
  if (ext == ".mesh") {
    VolumeMesh mesh = read_medit_volume(load_text(path));
    // Names and kinds from the sidecar, when there is one (medit_names.h).
    const std::string names = medit_names_path(path);
    if (std::filesystem::is_regular_file(names, ec)) apply_medit_names(load_text(names), mesh);
    return mesh;
  }
  if (ext == ".vtu") return read_vtu_volume(load_text(path));
  if (ext == ".msh") return read_msh_volume(load_text(path));
  if (ext == ".node" || ext == ".ele" || ext == ".face") {
    const std::string base = tetgen_base(path);
    const TextSource node = load_text(base + ".node");
    const TextSource ele = load_text(base + ".ele");
    if (std::filesystem::exists(base + ".face", ec)) {
      const TextSource face = load_text(base + ".face");
      return read_tetgen(node, ele, &face);
    }
    return read_tetgen(node, ele, nullptr);
  }
  throw InputError(path, 0, "unknown volume mesh extension '" + ext + "' (supported: .mesh .vtu .msh .node .ele .face)");
}

std::optional<VolumeMesh> read_tets_if_any(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext == ".node" || ext == ".ele" || ext == ".face") return read_volume_mesh(path);
  if (ext != ".mesh" && ext != ".vtu" && ext != ".msh") return std::nullopt;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return std::nullopt;
  try {
    VolumeMesh mesh = read_volume_mesh(path);
    if (!mesh.tets.empty()) return mesh;
  } catch (const InputError&) {
  }
  return std::nullopt;
}

void write_volume_mesh(const VolumeMesh& mesh, const std::string& path, const WriteOptions& options) {
  const std::string ext = file_extension(path);
  const int precision = options.precision;
  if (ext == ".node" || ext == ".ele") {
    // Three files: all are written to temporaries first, then renamed, so a failure while
    // writing leaves none of them.
    const std::string base = tetgen_base(path);
    AtomicFile node(base + ".node", options.protected_paths);
    AtomicFile ele(base + ".ele", options.protected_paths);
    AtomicFile face(base + ".face", options.protected_paths);
    write_tetgen_node(mesh, node.stream(), precision);
    write_tetgen_ele(mesh, ele.stream());
    write_tetgen_face(mesh, face.stream());
    node.close();
    ele.close();
    face.close();
    node.commit();
    ele.commit();
    face.commit();
    return;
  }
  if (ext == ".mesh") {
    // The mesh and its names sidecar (medit_names.h), both written before either is renamed.
    AtomicFile medit(path, options.protected_paths);
    AtomicFile names(medit_names_path(path), options.protected_paths);
    write_medit_volume(mesh, medit.stream(), precision);
    names.stream() << medit_names_text(mesh);
    medit.close();
    names.close();
    medit.commit();
    names.commit();
    return;
  }
  std::function<void(std::ostream&)> write;
  if (ext == ".vtu" && options.ascii)
    write = [&](std::ostream& out) { write_vtu_volume_ascii(mesh, out, precision); };
  else if (ext == ".vtu")
    write = [&](std::ostream& out) { write_vtu_volume(mesh, out, precision); };
  else if (ext == ".msh")
    write = [&](std::ostream& out) { write_msh_volume(mesh, out, precision); };
  else
    throw OutputError(path + ": unknown volume mesh extension '" + ext +
                      "' (supported: " + list(writable_volume_extensions()) + ")");
  write_atomically(path, options.protected_paths, write);
}

}  // namespace voroseal
