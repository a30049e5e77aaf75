#include "framework/model/size_rules.h"

#include <fnmatch.h>

#include <cmath>
#include <cstdlib>

#include "framework/core/error.h"

namespace voroseal {

namespace {

// Names listed in a message, up to about this many characters.
constexpr size_t kNamesInMessage = 400;

std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::vector<SizeRule> parse_size_rules(const std::string& text, const std::string& option) {
  std::vector<SizeRule> rules;
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t end = std::min(text.find_first_of(",\n", begin), text.size());
    const std::string item = trimmed(text.substr(begin, end - begin));
    begin = end + 1;
    if (item.empty()) continue;
    const size_t eq = item.rfind('=');
    const std::string bad = "parameter " + option + ": '" + item + "' ";
    if (eq == std::string::npos || eq == 0) throw ParameterError(bad + "is not NAME=H");
    const std::string number = trimmed(item.substr(eq + 1));
    char* stop = nullptr;
    const double h = std::strtod(number.c_str(), &stop);
    if (number.empty() || *stop != '\0' || !std::isfinite(h) || !(h > 0.0))
      throw ParameterError(bad + "needs a positive size after '='");
    rules.push_back({trimmed(item.substr(0, eq)), h});
  }
  return rules;
}

bool name_matches(const std::string& pattern, const std::string& name, bool fold_case) {
  return fnmatch(pattern.c_str(), name.c_str(), fold_case ? FNM_CASEFOLD : 0) == 0;
}

std::vector<int> regions_named(const StructuralModel& model, const std::string& pattern) {
  std::vector<char> named(model.regions.size(), 0);
  for (size_t r = 0; r < model.regions.size(); ++r)
    if (name_matches(pattern, model.regions[r].name)) named[r] = 1;
  for (const Layer& l : model.layers)
    if (name_matches(pattern, l.name))
      for (int r : l.regions) named[r] = 1;
  std::vector<int> regions;
  for (size_t r = 0; r < named.size(); ++r)
    if (named[r]) regions.push_back(static_cast<int>(r));
  return regions;
}

std::string names_for_message(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names)
    if (s.size() < kNamesInMessage) s += (s.empty() ? "" : ", ") + n;
  return s.size() >= kNamesInMessage ? s + ", ..." : s;
}

std::string region_and_layer_names(const StructuralModel& model) {
  std::vector<std::string> names;
  for (const Region& r : model.regions) names.push_back(r.name);
  for (const Layer& l : model.layers) names.push_back(l.name);
  return names_for_message(names);
}

}  // namespace voroseal
