// `voroseal convert IN OUT`: rewrites a model or a volume mesh in another format. A model keeps
// the structure the target format can hold (.ml keeps regions and layers; other formats keep
// surface parts as groups). A volume mesh (an input holding tets, TetGen files included) keeps
// its tets with their region ids, its triangles with their surface ids, its contact edges and
// corner points; a target that cannot hold tets, edges or points is refused rather than written
// without them.
#include <algorithm>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/host/module.h"
#include "framework/host/registry.h"
#include "io/model_io.h"

namespace voroseal {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

class ConvertModule : public Module {
 public:
  std::string name() const override { return "convert"; }
  std::string description() const override {
    return "convert a model or a volume mesh between file formats (tets kept)";
  }
  bool reads_volume_mesh() const override { return true; }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec output{"output", ParameterType::Path, nullptr, "output file; format from its extension"};
    output.required = true;
    output.positional = true;
    output.short_name = "o";
    output.output = true;
    output.extensions = writable_model_extensions();
    for (const std::string& e : writable_volume_extensions())
      if (!contains(output.extensions, e)) output.extensions.push_back(e);
    ParameterSpec ascii{"ascii", ParameterType::Bool, false,
                        "write .vtu as ASCII text rather than zlib-compressed binary (the other "
                        "formats are text already)"};
    return {output, ascii};
  }
  void run(Context& context, const Parameters& parameters) const override {
    const std::string out = parameters.get_string("output");
    const std::string ext = lower_extension(out);
    WriteOptions write{{context.input_path}};
    write.ascii = parameters.get_bool("ascii");
    if (context.volume && !context.model) {
      const VolumeMesh& mesh = *context.volume;
      if (!contains(writable_volume_extensions(), ext))
        throw ParameterError(context.input_path + " holds " + std::to_string(mesh.tets.size()) +
                             " tets; " + out + ": the " + ext +
                             " format holds surfaces only, the tets would be lost (write " +
                             "a volume format: .mesh .vtu .msh .node .ele)");
      // TetGen's .node/.ele/.face hold no edges or points: they would be lost.
      if ((ext == ".node" || ext == ".ele") && (!mesh.edges.empty() || !mesh.corners.empty()))
        throw ParameterError(context.input_path + " holds " + std::to_string(mesh.edges.size()) +
                             " contact edges and " + std::to_string(mesh.corners.size()) +
                             " corner points; " + out +
                             ": TetGen files hold neither, they would be lost (write .mesh "
                             ".vtu or .msh)");
      write_volume_mesh(mesh, out, write);
      context.report["convert"] = {
          {"input", context.input_path},     {"output", out},
          {"tets", mesh.tets.size()},        {"triangles", mesh.triangles.size()},
          {"edges", mesh.edges.size()},      {"corners", mesh.corners.size()},
          {"vertices", mesh.vertices.size()}};
    } else {
      if (!context.model) throw ModelError("convert needs a model or a volume mesh");
      if (!contains(writable_model_extensions(), ext))
        throw ParameterError(out + ": the " + ext + " format holds tets, and " +
                             context.input_path +
                             " holds surfaces only (tet-mesh it with `voroseal tetmesh`)");
      write_model(*context.model, out, write);
      context.report["convert"] = {{"input", context.input_path}, {"output", out}};
    }
    context.log.info("wrote " + out);
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_convert(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::ConvertModule>());
}
