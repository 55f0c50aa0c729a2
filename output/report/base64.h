// Base64 (RFC 4648, with padding), to put the animation's binary glTF inside the page.
#pragma once

#include <string>
#include <string_view>

namespace sled::report {

std::string Base64(std::string_view bytes);

}  // namespace sled::report
