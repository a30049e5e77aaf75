#include "tests/framework/host/svg_check.h"

#include <algorithm>
#include <cctype>

namespace voroseal::test {

std::string markup_problem(const std::string& markup) {
  static const std::vector<std::string> kVoid = {"img", "meta", "br", "input", "hr", "link"};
  std::vector<std::string> open;
  for (size_t at = 0; at < markup.size(); ++at) {
    if (markup[at] == '&') {
      const size_t end = markup.find(';', at);
      if (end == std::string::npos || end - at > 10) return "bare & at " + std::to_string(at);
      continue;
    }
    if (markup[at] != '<') continue;
    const size_t end = markup.find('>', at);
    if (end == std::string::npos) return "unclosed tag at " + std::to_string(at);
    const std::string tag = markup.substr(at + 1, end - at - 1);
    at = end;
    if (tag.empty()) return "empty tag";
    if (tag[0] == '!') continue;  // doctype, comment
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes <" + (open.empty() ? std::string() : open.back()) + ">";
      open.pop_back();
      continue;
    }
    size_t n = 0;
    while (n < tag.size() && (std::isalnum(static_cast<unsigned char>(tag[n])) || tag[n] == '-'))
      ++n;
    const std::string name = tag.substr(0, n);
    if (tag.back() == '/' || std::find(kVoid.begin(), kVoid.end(), name) != kVoid.end()) continue;
    open.push_back(name);
    if (name == "style" || name == "script") {  // raw text up to the closing tag
      const size_t close = markup.find("</" + name + ">", at);
      if (close == std::string::npos) return "unclosed <" + name + ">";
      at = close - 1;
    }
  }
  return open.empty() ? "" : "<" + open.back() + "> is not closed";
}

std::vector<std::string> attribute_values(const std::string& markup, const std::string& tag,
                                          const std::string& name) {
  std::vector<std::string> values;
  const std::string opening = "<" + tag + " ";
  for (size_t at = markup.find(opening); at != std::string::npos;
       at = markup.find(opening, at + 1)) {
    const size_t end = markup.find('>', at);
    const std::string element = markup.substr(at, end - at);
    const size_t a = element.find(" " + name + "=\"");
    if (a == std::string::npos) continue;
    const size_t from = a + name.size() + 3;
    values.push_back(element.substr(from, element.find('"', from) - from));
  }
  return values;
}

size_t count_of(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

}  // namespace voroseal::test
