// Checks for the SVG and HTML the study reports write: well-formedness and attribute values.
#pragma once

#include <string>
#include <vector>

namespace voroseal::test {

/// "" when every element of `markup` is closed in order and every '&' starts an entity;
/// otherwise what is wrong. Void HTML elements (img, meta, br, input) need no closing tag.
std::string markup_problem(const std::string& markup);

/// The values of attribute `name` of every element `tag` in `markup`, in order.
std::vector<std::string> attribute_values(const std::string& markup, const std::string& tag,
                                          const std::string& name);

/// How many times `needle` occurs in `text`.
size_t count_of(const std::string& text, const std::string& needle);

}  // namespace voroseal::test
