#include "framework/host/parameters.h"

#include <cmath>

#include "framework/core/error.h"

namespace voroseal {

const char* to_string(ParameterType type) {
  switch (type) {
    case ParameterType::Bool: return "bool";
    case ParameterType::Int: return "int";
    case ParameterType::Double: return "number";
    case ParameterType::String: return "text";
    case ParameterType::Path: return "path";
    case ParameterType::Choice: return "choice";
  }
  return "?";
}

namespace {

// Converts a value given as a JSON value or a command-line string to the declared type.
nlohmann::json coerce(const ParameterSpec& spec, const nlohmann::json& value) {
  const std::string where = "parameter --" + spec.name;
  auto bad = [&](const std::string& why) { return ParameterError(where + ": " + why); };
  switch (spec.type) {
    case ParameterType::Bool: {
      if (value.is_boolean()) return value;
      if (value.is_string()) {
        const std::string s = value.get<std::string>();
        if (s == "true" || s == "1" || s == "on" || s == "yes") return true;
        if (s == "false" || s == "0" || s == "off" || s == "no") return false;
      }
      throw bad("expected true or false, got " + value.dump());
    }
    case ParameterType::Int: {
      long v = 0;
      if (value.is_number_integer()) {
        v = value.get<long>();
      } else if (value.is_string()) {
        const std::string s = value.get<std::string>();
        size_t used = 0;
        try {
          v = std::stol(s, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != s.size()) throw bad("expected an integer, got '" + s + "'");
      } else {
        throw bad("expected an integer, got " + value.dump());
      }
      if (v < spec.min || v > spec.max)
        throw bad("value " + std::to_string(v) + " is out of range [" + nlohmann::json(spec.min).dump() +
                  ", " + nlohmann::json(spec.max).dump() + "]");
      return v;
    }
    case ParameterType::Double: {
      double v = 0;
      if (value.is_number()) {
        v = value.get<double>();
      } else if (value.is_string()) {
        const std::string s = value.get<std::string>();
        size_t used = 0;
        try {
          v = std::stod(s, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != s.size()) throw bad("expected a number, got '" + s + "'");
      } else {
        throw bad("expected a number, got " + value.dump());
      }
      if (!std::isfinite(v)) throw bad("the value must be finite");
      if (v < spec.min || v > spec.max)
        throw bad("value " + nlohmann::json(v).dump() + " is out of range [" + nlohmann::json(spec.min).dump() +
                  ", " + nlohmann::json(spec.max).dump() + "]");
      return v;
    }
    case ParameterType::String:
    case ParameterType::Path:
      if (!value.is_string()) throw bad("expected text, got " + value.dump());
      return value;
    case ParameterType::Choice: {
      if (!value.is_string()) throw bad("expected one of the choices, got " + value.dump());
      const std::string s = value.get<std::string>();
      for (const std::string& c : spec.choices)
        if (c == s) return value;
      std::string list;
      for (const std::string& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
      throw bad("'" + s + "' is not one of: " + list);
    }
  }
  return value;
}

}  // namespace

Parameters::Parameters(const std::vector<ParameterSpec>& specs, const nlohmann::json& values) {
  if (!values.is_null() && !values.is_object())
    throw ParameterError("parameters must be given as an object of name: value");
  const nlohmann::json given = values.is_null() ? nlohmann::json::object() : values;
  for (const auto& [name, value] : given.items()) {
    bool known = false;
    for (const ParameterSpec& s : specs) known = known || s.name == name;
    if (!known) {
      std::string list;
      for (const ParameterSpec& s : specs) list += (list.empty() ? "" : ", ") + s.name;
      throw ParameterError("unknown parameter '" + name + "' (known: " + list + ")");
    }
  }
  for (const ParameterSpec& spec : specs) {
    const bool given = values.is_object() && values.contains(spec.name) && !values.at(spec.name).is_null();
    if (given) {
      values_[spec.name] = coerce(spec, values.at(spec.name));
    } else if (spec.required) {
      throw ParameterError("parameter --" + spec.name + " is required");
    } else {
      values_[spec.name] = spec.default_value;
    }
  }
}

bool Parameters::has(const std::string& name) const {
  return values_.contains(name) && !values_.at(name).is_null();
}

const nlohmann::json& Parameters::at(const std::string& name) const {
  if (!has(name)) throw ParameterError("parameter --" + name + " has no value");
  return values_.at(name);
}

bool Parameters::get_bool(const std::string& name) const { return at(name).get<bool>(); }
long Parameters::get_int(const std::string& name) const { return at(name).get<long>(); }
double Parameters::get_double(const std::string& name) const { return at(name).get<double>(); }
std::string Parameters::get_string(const std::string& name) const { return at(name).get<std::string>(); }

}  // namespace voroseal
