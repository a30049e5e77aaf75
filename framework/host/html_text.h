// Text put into the HTML (and inline SVG) of the study reports: escaped markup and URLs.
#pragma once

#include <string>

namespace voroseal {

/// Escapes & < > " ' so that the text is safe in element content and attribute values.
std::string escape_html(const std::string& text);

/// Percent-encodes what is not safe in a relative URL path (keeps '/').
std::string escape_url(const std::string& path);

}  // namespace voroseal
