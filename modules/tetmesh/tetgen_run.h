// One TetGen run on an in-memory PLC, in a child process: its console output captured, its
// failures — error codes, failed assertions, crashes — turned into return codes.
#pragma once

#include <tetgen.h>

#include <string>

namespace voroseal {

/// Return code of run_tetgen() when TetGen died (a failed assertion, a segfault).
constexpr int kTetgenCrashed = -1;

/// Runs TetGen (1.5) with `switches` on `in`, filling `out` (points, tets with attributes,
/// boundary/interface faces with markers); everything TetGen prints goes to `printed`, not to
/// stdout or stderr. Returns 0 on success, TetGen's error code (1 out of memory, 2 internal
/// error, 3 self-intersection, 4 very small feature, 5 very close facets, 10 bad switches or
/// input) or kTetgenCrashed (`printed` then ends with the signal and TetGen's assertion).
///
/// Why a child process: TetGen 1.5.0 as packaged keeps its assert()s, and some inputs trip
/// them (modelA4 of the RING models under Y: recoveredgebyflips, "Assertion `0' failed"),
/// which would abort the whole program. The child (fork) runs TetGen and writes its output to
/// a temporary file that the parent reads back; when fork is impossible the run happens in
/// this process.
///
/// Why not TetGen's own tetrahedralize(): in library mode TetGen 1.5.0 frees its mesh and
/// then throws, and the mesh's destructor frees it again while the exception unwinds (a double
/// free). This runs the same sequence of steps for the switches voroseal uses (p, q, a, A, Y,
/// d, J, Q, V, O, T; not r, m, i, R, o2) with a heap-allocated mesh that is not destroyed after
/// a failure.
///
/// `sliver_dihedral_deg` > 0 makes TetGen's optimisation step (-O, on by default) smooth Steiner
/// points of, and split, every tet whose largest dihedral angle exceeds it. TetGen 1.5 fixes
/// both thresholds at 179° and no switch sets them, so only the flattest slivers are treated;
/// slivers spanning a layer thinner than the surface triangles (all four vertices on surfaces,
/// largest angle 170–178°) stay. Pair it with the switch `o/<same angle>` (the flip target).
/// 0 keeps TetGen's thresholds.
///
/// Runs are serialised (by the stdout capture's lock), which TetGen needs anyway in-process:
/// exactinit() sets its predicates' static error bounds from each input's bounding box.
/// \throws MesherError when stdout cannot be captured or the child's output cannot be read.
int run_tetgen(const std::string& switches, tetgenio& in, tetgenio& out, std::string& printed,
               double sliver_dihedral_deg = 0.0);

}  // namespace voroseal
