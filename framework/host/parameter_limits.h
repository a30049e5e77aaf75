// Bounds of the numeric parameters that have no natural limit of their own, named once for
// every module, so that each option is bounded where it is parsed. What a value within them
// costs is estimated separately, against the memory (memory_budget.h).
#pragma once

namespace voroseal {

/// Counts (seeds, sample points) are held in an int.
constexpr double kMaxCount = 2147483647.0;
/// Random seeds fit a signed 64-bit integer.
constexpr double kMaxRandomSeed = 9.2e18;
/// Lengths in model units: far beyond any model in any unit, yet finite.
constexpr double kMaxModelLength = 1e15;
/// Volumes in model units^3 (kMaxModelLength cubed).
constexpr double kMaxModelVolume = 1e45;
/// Radius-edge ratios: 2 is already a loose mesh.
constexpr double kMaxRadiusEdge = 100.0;

}  // namespace voroseal
