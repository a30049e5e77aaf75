#include "io/tag_names.h"

namespace voroseal {

std::string kind_prefixed_name(SurfaceKind kind, const std::string& name) {
  return std::string(to_string(kind)) + ":" + name;
}

void split_kind_prefixed_name(const std::string& text, SurfaceKind& kind, std::string& name) {
  kind = SurfaceKind::Unknown;
  name = text;
  const size_t colon = text.find(':');
  if (colon == std::string::npos) return;
  const std::string word = text.substr(0, colon);
  for (SurfaceKind k : {SurfaceKind::Unknown, SurfaceKind::Horizon, SurfaceKind::Fault,
                        SurfaceKind::Boundary, SurfaceKind::Unconformity})
    if (word == to_string(k)) {
      kind = k;
      name = text.substr(colon + 1);
      return;
    }
}

}  // namespace voroseal
