// Where `import` finds modules: the standard library's folder for `import std.x.y`, and the
// extra folders of $SLED_PATH for other imports.
#pragma once

#include <string>
#include <vector>

namespace sled::compiler {

// The standard library folder Check uses when CheckOptions::stdlib_root is empty, the first of:
//   1. $SLED_STDLIB, when set;
//   2. share/sled/stdlib beside the running program's bin/ folder (an installed `sled`, or any
//      program installed into the same prefix);
//   3. the stdlib/ folder of the source tree this library was built from, when it still exists
//      (programs run from the build tree);
//   4. share/sled/stdlib under the prefix the build was configured to install into.
// When none exists, the last candidate that was tried, so E0203 names a path.
std::string DefaultStdlibRoot();

// The folders of $SLED_PATH (separated by `:`, empty entries skipped), in order; empty when the
// variable is not set.
std::vector<std::string> ModulePathFromEnvironment();

}  // namespace sled::compiler
