#include "framework/host/output_paths.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "framework/core/error.h"

namespace voroseal {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The files a path stands for: itself, or a TetGen triple.
std::vector<fs::path> files_of(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec).lexically_normal();
  const std::string ext = lower_extension(p);
  if (ext != ".node" && ext != ".ele" && ext != ".face") return {p};
  std::vector<fs::path> triple;
  for (const char* e : {".node", ".ele", ".face"})
    triple.push_back(fs::path(p).replace_extension(e));
  return triple;
}

bool same_file(const fs::path& a, const fs::path& b) {
  if (a == b) return true;
  std::error_code ec;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

}  // namespace

void check_output_paths(const std::vector<ParameterSpec>& specs, const Parameters& parameters,
                        std::vector<std::string> inputs) {
  for (const ParameterSpec& spec : specs)
    if (spec.type == ParameterType::Path && !spec.output && parameters.has(spec.name))
      inputs.push_back(parameters.get_string(spec.name));
  struct Claimed {
    std::string option;
    fs::path file;
  };
  std::vector<Claimed> claimed;
  for (const std::string& input : inputs)
    if (!input.empty())
      for (const fs::path& f : files_of(input)) claimed.push_back({"", f});
  for (const ParameterSpec& spec : specs) {
    if (!spec.output || !parameters.has(spec.name)) continue;
    const std::string path = parameters.get_string(spec.name);
    const std::string where = "parameter --" + spec.name + ": '" + path + "'";
    if (path.empty()) throw ParameterError("parameter --" + spec.name + ": empty file name");
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw ParameterError(where + " is a directory");
    const std::string ext = lower_extension(path);
    if (!spec.extensions.empty() &&
        std::find(spec.extensions.begin(), spec.extensions.end(), ext) == spec.extensions.end()) {
      std::string list;
      for (const std::string& e : spec.extensions) list += (list.empty() ? "" : " ") + e;
      throw ParameterError(where + ": unknown extension '" + ext + "' (supported: " + list + ")");
    }
    const fs::path parent = fs::absolute(path, ec).parent_path();
    if (!fs::is_directory(parent, ec))
      throw ParameterError(where + ": no directory " + parent.string());
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
      throw ParameterError(where + ": the directory " + parent.string() + " is not writable");
    for (const fs::path& file : files_of(path)) {
      for (const Claimed& c : claimed)
        if (same_file(file, c.file))
          throw ParameterError(where + (c.option.empty() ? " is an input of this run"
                                                         : " is also the file of --" + c.option));
      claimed.push_back({spec.name, file});
    }
  }
}

}  // namespace voroseal
