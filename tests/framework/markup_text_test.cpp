#include "framework/core/markup_text.h"

#include <gtest/gtest.h>

namespace voroseal {
namespace {

TEST(MarkupText, EscapesTheFiveCharactersAndTheApostropheAsAsked) {
  const std::string text = "a&b <c> \"d\" 'e'";
  EXPECT_EQ(escape_markup(text, "&apos;"), "a&amp;b &lt;c&gt; &quot;d&quot; &apos;e&apos;");
  EXPECT_EQ(escape_markup(text, "&#39;"), "a&amp;b &lt;c&gt; &quot;d&quot; &#39;e&#39;");
  EXPECT_EQ(escape_markup("plain F1/0", "&apos;"), "plain F1/0");
  EXPECT_EQ(escape_markup("", "&apos;"), "");
}

}  // namespace
}  // namespace voroseal
