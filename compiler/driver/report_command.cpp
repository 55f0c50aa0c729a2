#include "compiler/driver/report_command.h"

#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "output/report/report.h"

namespace sled::driver {

int ReportCommand(const std::string& directory, const std::string& output) {
  const std::filesystem::path page = output.empty()
                                         ? std::filesystem::path(directory) / "report.html"
                                         : std::filesystem::path(output);
  const report::ReportResult result = report::WriteReport(directory, page);
  if (!result.written) {
    std::cerr << fmt::format("sled: {}\n", result.error);
    return 1;
  }
  for (const std::string& note : result.notes) std::cerr << fmt::format("sled: note: {}\n", note);
  std::cout << fmt::format("sled: wrote `{}`\n", page.string());
  return 0;
}

}  // namespace sled::driver
