// The docs/diagnostics/*.md pages, embedded at build time so `sled explain` works anywhere.
#pragma once

#include <optional>
#include <string_view>

namespace sled::driver {

std::optional<std::string_view> ExplainPage(std::string_view code);

}  // namespace sled::driver
