// The version and commit the program was built from, for `sled --version`.
#pragma once

#include <string_view>

namespace sled::driver {

// The project's version (CMakeLists.txt `project(sled VERSION ...)`).
inline constexpr std::string_view kSledVersion = SLED_VERSION;

// The commit of the source tree at build time, `+modified` when the tree had changes; `unknown`
// outside a git checkout. Written by commit_info.cmake at every build, only when it changes.
std::string_view BuildCommit();

}  // namespace sled::driver
