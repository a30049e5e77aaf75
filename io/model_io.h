// Reading and writing models and volume meshes, format chosen by file extension.
//
// Model formats:  .ml (GOCAD Model3d: parts, regions, layers), .ts (GOCAD TSurf),
//                 .obj (groups), .mesh (Medit triangles with refs; tetrahedra too),
//                 written also as .vtu (VTK XML) and .msh (Gmsh 4.1).
// Volume formats: .mesh (with its names in OUT.mesh.json), .vtu, .msh, and TetGen
//                 .node/.ele/.face (give the .node or .ele path).
//
// Readers throw InputError("file:line: message") on malformed input. Writers write a temporary
// file beside the target and rename it, so a failed write never leaves a partial file, and they
// refuse to write over any path in WriteOptions::protected_paths (the inputs of the run).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "framework/model/model_builder.h"
#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

struct ReadOptions {
  BuildOptions build;
};

struct WriteOptions {
  std::vector<std::string> protected_paths;  // never written over (compared as files)
  int precision = 17;                         // significant digits of coordinates
  bool ascii = false;  // .vtu as ASCII text (else zlib-compressed binary); other formats are text
};

/// The extension of `path` in lower case, with its dot (".vtu"); empty when none.
std::string file_extension(const std::string& path);

/// Reads the triangulated surfaces of a model file without inferring topology.
/// \throws InputError
SurfaceSoup read_soup(const std::string& path);
/// Reads a model file and builds the StructuralModel (explicit structure for .ml).
/// \throws InputError, ModelError
StructuralModel read_model(const std::string& path, const ReadOptions& options = {});
/// \throws OutputError
void write_model(const StructuralModel& model, const std::string& path, const WriteOptions& options = {});
/// The text write_model() would write at `path` (format from its extension). \throws OutputError
std::string model_text(const StructuralModel& model, const std::string& path,
                       const WriteOptions& options = {});
/// Reads `text` the way read_model() reads a file `path` holding it. \throws InputError, ModelError
StructuralModel read_model_text(std::string text, const std::string& path,
                                const ReadOptions& options = {});
/// Writes `text` at `path` atomically (AtomicFile), refusing the protected paths.
/// \throws OutputError
void write_text(const std::string& text, const std::string& path, const WriteOptions& options = {});

/// Reads a tetrahedral mesh: .mesh (Tetrahedra), .vtu, .msh, or TetGen files (any of
/// .node/.ele/.face; the .face file is optional). Vertices are moved to a local frame.
/// \throws InputError
VolumeMesh read_volume_mesh(const std::string& path);
/// The volume mesh in `path` when it holds tets: TetGen files (read errors thrown), or a .mesh,
/// .vtu or .msh file that reads as a volume mesh with tets; nullopt otherwise (other formats,
/// surfaces only, or a file the volume reader refuses: the model reader then says why).
/// \throws InputError for TetGen files
std::optional<VolumeMesh> read_tets_if_any(const std::string& path);
/// \throws OutputError
void write_volume_mesh(const VolumeMesh& mesh, const std::string& path, const WriteOptions& options = {});

/// Extensions (with the dot, lower case) that read_model / write_model / write_volume_mesh accept.
std::vector<std::string> readable_model_extensions();
std::vector<std::string> writable_model_extensions();
std::vector<std::string> writable_volume_extensions();

}  // namespace voroseal
