// Models and volume meshes from arrays given in Python: what the file readers check, checked
// the same way, so the C++ code can rely on it whichever way a mesh came in.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/model/model_builder.h"
#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace voroseal::python {

// Ids past this are refused, as the file readers do: every id below gets a name.
constexpr long long kMaxId = 1000000;

/// The kind whose to_string() is `word` exactly (the words files use: "fault", not "Fault").
std::optional<SurfaceKind> kind_word(const std::string& word);

/// build_model() with the options Python passes, without holding the GIL (it can take seconds).
std::shared_ptr<StructuralModel> build_soup(const SurfaceSoup& soup, double feature_angle,
                                            double weld_tolerance);

/// One id per element, each in [0, kMaxId]; every id gets a name ("<what>_<id>", the readers'
/// default, where none was given). \throws ParameterError otherwise.
void check_ids(const std::vector<int>& ids, size_t count, std::vector<std::string>& names,
               const std::string& what, const std::string& element);

/// Makes a VolumeMesh given in file coordinates what every volume reader returns, then moves
/// it to a local frame with the readers' rule (see the definition). \throws ParameterError.
void finish_volume_mesh(VolumeMesh& mesh);

}  // namespace voroseal::python
