// The census of defects of the clean-up, kept phase after phase. After a phase's edits only what
// they touched is counted again: the triangles with a touched vertex (their shape, and their
// crossings with any triangle), those triangles' edges and the touched vertices' fans. Nothing
// else can have changed, so the counts are those of a whole census (Editor::census()), at a
// cost that follows the edits rather than the surface.
// Internal to the remesh module (see cleanup_phase.h).
#pragma once

#include <utility>
#include <vector>

#include "modules/remesh/cleanup_editor.h"

namespace voroseal::cleanup {

class DefectCensus {
 public:
  // The whole census of the editor's surface.
  explicit DefectCensus(Editor& e);

  const Violations& count() const { return count_; }

  // The census after the edits journaled since `mark` in e's open transaction (this census
  // being the one before them): counted again around the touched vertices, or whole when
  // they are more than kWholeCensusShare of the vertices.
  DefectCensus after_edits(Editor& e, size_t mark) const;

 private:
  DefectCensus() = default;
  void recount();

  struct EdgeDefect {
    std::pair<int, int> edge;  // a < b
    Violations v;              // its holes, leaks and folds
  };
  std::vector<std::pair<int, int>> crossings_;  // triangle pairs, sorted
  std::vector<int> degenerate_;                 // triangles, sorted
  std::vector<EdgeDefect> edges_;               // sorted by edge
  std::vector<std::pair<int, int>> pinches_;    // (vertex, extra fans), sorted
  Violations count_;
};

}  // namespace voroseal::cleanup
