// The output files of one command, checked before any computation: a bad name is a bad
// command line (exit 2), found in a second, not after an hour of remeshing.
#pragma once

#include <string>
#include <vector>

#include "framework/host/parameters.h"

namespace voroseal {

/// Checks every given output parameter of `specs` (ParameterSpec::output): a known extension,
/// not a directory, in an existing writable directory, none the same file as another output
/// or as one of `inputs` (the model read, reference models: the Path parameters that are not
/// outputs are added). TetGen outputs count as their three files (.node .ele .face).
/// \throws ParameterError naming the option and the path.
void check_output_paths(const std::vector<ParameterSpec>& specs, const Parameters& parameters,
                        std::vector<std::string> inputs);

}  // namespace voroseal
