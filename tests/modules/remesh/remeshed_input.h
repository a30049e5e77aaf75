// A model's own triangles as a RemeshedSurface, for tests of the clean-up.
#pragma once

#include "framework/model/structural_model.h"
#include "modules/remesh/remeshed_surface.h"

namespace voroseal::test {

/// The model's triangles as a RemeshedSurface, each vertex tagged with the feature it lies on.
RemeshedSurface as_remeshed(const StructuralModel& m);

}  // namespace voroseal::test
