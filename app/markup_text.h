// markup_text.h: user text (scene names, file paths, failure lines) made
// safe as the text or an attribute value of HTML and XML: the five markup
// characters escaped, and bytes that are not UTF-8 and control characters
// XML cannot hold replaced by U+FFFD. Used by the JUnit file and the report.
#pragma once

#include <string>

namespace st {

std::string markup_text(const std::string& in);

}  // namespace st
