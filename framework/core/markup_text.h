// Text put into markup (XML files, HTML reports): the five characters that end text or an
// attribute value, as character entities.
#pragma once

#include <string>

namespace voroseal {

/// `text` with & < > " ' escaped, safe in element content and in attribute values; the
/// apostrophe becomes `apostrophe` ("&apos;" in XML, "&#39;" in HTML, which before HTML5 had no
/// &apos;).
std::string escape_markup(const std::string& text, const char* apostrophe);

}  // namespace voroseal
