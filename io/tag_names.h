// How a surface's kind travels with its name in files without a kind field (internal to
// voroseal_io): "<kind>:<name>", e.g. "fault:F1", in .msh physical names and .vtu field data.
#pragma once

#include <string>

#include "framework/model/structural_model.h"

namespace voroseal {

/// "<kind>:<name>", kind as to_string(SurfaceKind) ("unknown" included, so that a name that
/// itself starts with a kind and ':' reads back whole).
std::string kind_prefixed_name(SurfaceKind kind, const std::string& name);

/// Splits "<kind>:<name>" when the text before the first ':' is exactly a to_string(SurfaceKind)
/// word; else the kind is Unknown and the name the whole text.
void split_kind_prefixed_name(const std::string& text, SurfaceKind& kind, std::string& name);

}  // namespace voroseal
