// The report page's script and style (output/report/assets), embedded at build time.
#pragma once

#include <string_view>

namespace sled::report {

// The animation viewer: reads the GLB embedded in the page and draws it with WebGL.
std::string_view ViewerScript();
// The page's style sheet.
std::string_view PageStyle();

}  // namespace sled::report
