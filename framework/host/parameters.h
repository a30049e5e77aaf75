// Typed module parameters: declared by a module (name, type, default, doc), filled from the
// command line or a pipeline file, read by the module.
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace voroseal {

enum class ParameterType { Bool, Int, Double, String, Path, Choice };

const char* to_string(ParameterType type);

/// Declaration of one parameter of a module.
struct ParameterSpec {
  std::string name;            // long option name: "edge-length" -> --edge-length
  ParameterType type = ParameterType::String;
  nlohmann::json default_value;  // null: no default (optional unless `required`)
  std::string doc;             // one line, shown by --help and `voroseal modules`
  std::vector<std::string> choices;  // for Choice
  std::string short_name;      // optional one-letter flag, e.g. "o"
  bool required = false;
  bool positional = false;     // given on the command line after the model, without a flag
  double min = -std::numeric_limits<double>::infinity();  // numeric bounds, inclusive
  double max = std::numeric_limits<double>::infinity();
  /// A Path parameter naming a file the module writes: checked with the run's other outputs
  /// and inputs before any work (output_paths.h).
  bool output = false;
  /// The extensions (".obj", lower case) an output can have; empty: any.
  std::vector<std::string> extensions;
  /// A String parameter the command line takes several times: the values join, one per line.
  bool repeatable = false;
};

/// Values of a module's parameters, validated against the specs.
class Parameters {
 public:
  Parameters() = default;
  /// Validates `values` (an object) against `specs`, fills defaults.
  /// \throws ParameterError on an unknown name, wrong type, bad choice or out-of-range value.
  Parameters(const std::vector<ParameterSpec>& specs, const nlohmann::json& values);

  bool has(const std::string& name) const;  // given or defaulted (not null)
  bool get_bool(const std::string& name) const;
  long get_int(const std::string& name) const;
  double get_double(const std::string& name) const;
  std::string get_string(const std::string& name) const;
  const nlohmann::json& json() const { return values_; }

 private:
  const nlohmann::json& at(const std::string& name) const;
  nlohmann::json values_ = nlohmann::json::object();
};

}  // namespace voroseal
