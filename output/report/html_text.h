// Text for HTML and SVG: every name in a report comes from a user's scene, so it is escaped
// before it goes into an element or an attribute.
#pragma once

#include <string>
#include <string_view>

namespace sled::report {

// `&`, `<`, `>`, `"` and `'` as character references.
std::string EscapeHtml(std::string_view text);

}  // namespace sled::report
