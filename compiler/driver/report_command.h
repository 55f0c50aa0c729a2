// `sled report DIR [-o FILE]`: the run in DIR (what `sled run -o DIR` wrote) as one HTML page,
// FILE or DIR/report.html. Exit 0 written, 1 when DIR holds no readable summary.json or the page
// cannot be written.
#pragma once

#include <string>

namespace sled::driver {

int ReportCommand(const std::string& directory, const std::string& output);

}  // namespace sled::driver
