#include "modules/tetmesh/tetgen_run.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <new>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/signal_cleanup.h"
#include "modules/tetmesh/stdout_capture.h"

namespace voroseal {

namespace {

/// The steps of TetGen 1.5.0's tetrahedralize(tetgenbehavior*, ...) (tetgen.cxx, main_cxx) for a
/// PLC without background mesh, added points, coarsening or second-order output, minus its
/// timing printouts. Throws TetGen's int codes.
void tetrahedralize_plc(tetgenbehavior& b, tetgenio& in, tetgenio& out, tetgenmesh& m) {
  std::clock_t ts = 0;
  std::clock_t last = std::clock();
  // TetGen prints its step names; the times are printed here (its own driver did).
  auto timed = [&](const char* step) {
    const std::clock_t now = std::clock();
    if (!b.quiet) std::printf("%s seconds:  %g\n", step, static_cast<double>(now - last) / CLOCKS_PER_SEC);
    last = now;
  };
  m.b = &b;
  m.in = &in;
  m.addin = nullptr;
  m.initializepools();
  m.transfernodes();
  exactinit(b.verbose, b.noexact, b.nostaticfilter, m.xmax - m.xmin, m.ymax - m.ymin, m.zmax - m.zmin);
  m.incrementaldelaunay(ts);
  timed("Delaunay");
  m.meshsurface();
  timed("Surface mesh");
  if (b.diagnose) {  // -d: report the intersecting facets and stop
    m.detectinterfaces();
    timed("Self-intersection");
    out.firstnumber = in.firstnumber;
    out.mesh_dim = in.mesh_dim;
    if (m.subfaces->items > 0l) {
      m.outnodes(&out);
      m.outsubfaces(&out);
    }
    return;
  }
  if (b.nobisect)
    m.recoverboundary(ts);  // -Y: no Steiner point on the boundary
  else
    m.constraineddelaunay(ts);
  timed(b.nobisect ? "Boundary recovery" : "Constrained Delaunay");
  m.carveholes();
  timed("Exterior tets removal");
  if (b.nobisect && m.subvertstack->objects > 0l) {
    m.suppresssteinerpoints();
    timed("Steiner suppression");
  }
  if (b.nobisect) {
    m.recoverdelaunay();
    timed("Delaunay recovery");
  }
  if (b.quality) {
    m.delaunayrefinement();
    timed("Refinement");
  }
  if (b.optlevel > 0) {
    m.optimizemesh();
    timed("Optimization");
  }
  if (!b.nojettison && (m.dupverts > 0 || m.unuverts > 0)) m.jettisonnodes();
  out.firstnumber = in.firstnumber;
  out.mesh_dim = in.mesh_dim;
  m.outnodes(&out);
  if (m.tetrahedrons->items > 0l) m.outelements(&out);
  if (m.subfaces->items > 0l) m.outsubfaces(&out);
  timed("Output");
  if (!b.quiet) m.statistics();
}

/// TetGen's run inside this process: 0 or TetGen's error code.
int run_in_process(tetgenbehavior& behavior, tetgenio& in, tetgenio& out) {
  auto mesh = std::make_unique<tetgenmesh>();
  try {
    tetrahedralize_plc(behavior, in, out, *mesh);
  } catch (int c) {
    // TetGen freed the mesh's pools before throwing; destroying it would free them again.
    static_cast<void>(mesh.release());
    return c == 0 ? 2 : c;
  } catch (const std::bad_alloc&) {
    return 1;  // thrown by new inside TetGen: its pools are intact and freed normally
  }
  return 0;
}

// The child's output file: a header of counts, then the arrays.
struct Header {
  int code = 0;
  int firstnumber = 0;
  int points = 0;
  int tets = 0;
  int corners = 0;
  int attributes = 0;
  int faces = 0;
  int face_markers = 0;  // 1 when trifacemarkerlist is present
};

template <typename T>
bool write_array(std::FILE* f, const T* data, size_t n) {
  return n == 0 || (data != nullptr && std::fwrite(data, sizeof(T), n, f) == n);
}

template <typename T>
T* read_array(std::FILE* f, size_t n) {
  if (n == 0) return nullptr;
  T* data = new T[n];
  if (std::fread(data, sizeof(T), n, f) != n) {
    delete[] data;
    throw MesherError("cannot read TetGen's output back from its process");
  }
  return data;
}

void write_output(std::FILE* f, int code, const tetgenio& out) {
  Header h;
  h.code = code;
  h.firstnumber = out.firstnumber;
  h.points = out.pointlist != nullptr ? out.numberofpoints : 0;
  h.tets = out.tetrahedronlist != nullptr ? out.numberoftetrahedra : 0;
  h.corners = out.numberofcorners;
  h.attributes = out.tetrahedronattributelist != nullptr ? out.numberoftetrahedronattributes : 0;
  h.faces = out.trifacelist != nullptr ? out.numberoftrifaces : 0;
  h.face_markers = out.trifacemarkerlist != nullptr ? 1 : 0;
  bool ok = std::fwrite(&h, sizeof h, 1, f) == 1;
  ok = ok && write_array(f, out.pointlist, 3 * static_cast<size_t>(h.points));
  ok = ok && write_array(f, out.tetrahedronlist, static_cast<size_t>(h.corners) * h.tets);
  ok = ok && write_array(f, out.tetrahedronattributelist, static_cast<size_t>(h.attributes) * h.tets);
  ok = ok && write_array(f, out.trifacelist, 3 * static_cast<size_t>(h.faces));
  if (h.face_markers) ok = ok && write_array(f, out.trifacemarkerlist, static_cast<size_t>(h.faces));
  ok = ok && std::fflush(f) == 0;
  if (!ok) std::_Exit(120);
}

int read_output(std::FILE* f, tetgenio& out) {
  std::rewind(f);
  Header h;
  if (std::fread(&h, sizeof h, 1, f) != 1) throw MesherError("TetGen's process wrote no output");
  out.firstnumber = h.firstnumber;
  out.numberofpoints = h.points;
  out.pointlist = read_array<REAL>(f, 3 * static_cast<size_t>(h.points));
  out.numberoftetrahedra = h.tets;
  out.numberofcorners = h.corners;
  out.tetrahedronlist = read_array<int>(f, static_cast<size_t>(h.corners) * h.tets);
  out.numberoftetrahedronattributes = h.attributes;
  out.tetrahedronattributelist = read_array<REAL>(f, static_cast<size_t>(h.attributes) * h.tets);
  out.numberoftrifaces = h.faces;
  out.trifacelist = read_array<int>(f, 3 * static_cast<size_t>(h.faces));
  if (h.face_markers) out.trifacemarkerlist = read_array<int>(f, static_cast<size_t>(h.faces));
  return h.code;
}

}  // namespace

int run_tetgen(const std::string& switches, tetgenio& in, tetgenio& out, std::string& printed,
               double sliver_dihedral_deg) {
  std::vector<char> buffer(switches.begin(), switches.end());
  buffer.push_back('\0');
  tetgenbehavior behavior;
  StdoutCapture capture;  // the child inherits the redirected stdout
  if (!behavior.parse_commandline(buffer.data()) || behavior.refine || behavior.insertaddpoints ||
      behavior.coarsen || behavior.order == 2) {
    printed = capture.finish();
    return 10;
  }
  if (sliver_dihedral_deg > 0.0) {
    // Both: smoothing drops from its queue the tets below its own threshold before the
    // splitting sees them (improvequalitybysmoothing), so a lower split threshold alone does
    // nothing.
    behavior.optminsmtdihed = sliver_dihedral_deg;
    behavior.optminslidihed = sliver_dihedral_deg;
  }

  std::FILE* result = std::tmpfile();
  std::fflush(stderr);
  const pid_t parent = ::getpid();
  pid_t child = -1;
  int child_slot = -1;
  if (result != nullptr) {
    // The child gets a process group of its own, registered before any signal can be
    // handled, so that the parent's signal handler kills it and nothing else.
    SignalBlock block;
    child = ::fork();
    if (child > 0) {
      ::setpgid(child, child);  // also done by the child: whichever runs first
      child_slot = register_child_group(child);
    }
  }
  if (child == 0) {
    // Child: TetGen only, then leave without running any destructor or atexit handler. It
    // dies with its parent, even one killed by SIGKILL (PR_SET_PDEATHSIG), and leaves at once
    // when the parent is already gone.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) std::_Exit(121);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    ::signal(SIGHUP, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);  // SignalBlock's mask was inherited
    ::dup2(STDOUT_FILENO, STDERR_FILENO);  // assertion messages join the captured text
    const int code = run_in_process(behavior, in, out);
    std::fflush(stdout);
    write_output(result, code, out);
    std::_Exit(0);
  }
  int code = 0;
  if (child < 0) {  // no child process: run here (a failed assertion would end the program)
    if (result != nullptr) std::fclose(result);
    code = run_in_process(behavior, in, out);
    printed = capture.finish();
    return code;
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  unregister_child_group(child_slot);
  printed = capture.finish();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    try {
      code = read_output(result, out);
    } catch (...) {
      std::fclose(result);
      throw;
    }
  } else {
    code = kTetgenCrashed;
    if (WIFSIGNALED(status))
      printed += "\nTetGen crashed: signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    else
      printed += "\nTetGen's process ended with status " + std::to_string(WEXITSTATUS(status));
  }
  std::fclose(result);
  return code;
}

}  // namespace voroseal
