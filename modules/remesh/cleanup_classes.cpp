#include "modules/remesh/cleanup_classes.h"

namespace voroseal::cleanup {

std::vector<std::vector<int>> independent_classes(Editor& e, const std::vector<int>& vertices) {
  std::vector<int> class_of(e.mesh().vertices.size(), -1);
  std::vector<std::vector<int>> classes;
  std::vector<char> taken;
  for (int v : vertices) {
    // The first class none of v's neighbours is in.
    taken.assign(classes.size() + 1, 0);
    for (int t : e.star(v))
      for (int w : e.mesh().triangles[t])
        if (w != v && class_of[w] >= 0) taken[class_of[w]] = 1;
    size_t c = 0;
    while (taken[c]) ++c;
    if (c == classes.size()) classes.emplace_back();
    classes[c].push_back(v);
    class_of[v] = static_cast<int>(c);
  }
  return classes;
}

}  // namespace voroseal::cleanup
