#include "framework/host/html_text.h"

#include <cctype>
#include <cstdio>

#include "framework/core/markup_text.h"

namespace voroseal {

std::string escape_html(const std::string& text) {
  return escape_markup(text, "&#39;");
}

std::string escape_url(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '=' || c == '~') {
      out += static_cast<char>(c);
    } else {
      char buffer[4];
      std::snprintf(buffer, sizeof buffer, "%%%02X", c);
      out += buffer;
    }
  }
  return out;
}

}  // namespace voroseal
