// Sizes the user asks for by name: `PATTERN=H` rules (`remesh --size`, `tetmesh --region-size`)
// and the regions a pattern names. Patterns are shell globs (`F*`, `Region_?`) on the names
// `voroseal stats` lists.
#pragma once

#include <string>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

/// One `PATTERN=H` rule: a target edge length H on what PATTERN names.
struct SizeRule {
  std::string pattern;
  double size = 0.0;
};

/// Rules separated by commas or new lines (the option given several times):
/// "kind:fault=50,F1=20". \throws ParameterError naming `option` and the rule that is not
/// PATTERN=H with a positive finite H.
std::vector<SizeRule> parse_size_rules(const std::string& text, const std::string& option);

/// True when the shell glob `pattern` matches `name` (case-insensitive when `fold_case`).
bool name_matches(const std::string& pattern, const std::string& name, bool fold_case = false);

/// The regions `pattern` names: by region name, or every region of a layer it names. Sorted.
std::vector<int> regions_named(const StructuralModel& model, const std::string& pattern);

/// "a, b, c, ...": names for a message, cut after about 400 characters.
std::string names_for_message(const std::vector<std::string>& names);

/// "Region_1, Region_2, ..., Layer_1": the region and layer names, for messages.
std::string region_and_layer_names(const StructuralModel& model);

}  // namespace voroseal
