// Headless Chromium (Debian `chromium`) for the page tests: the report and the sweep page are
// loaded and their DOM dumped after the scripts ran.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/compiler/sled_process.h"

namespace sled::testing {

namespace fs = std::filesystem;

// The Chromium program on PATH (SLED_CHROMIUM overrides), or empty.
inline fs::path FindChromium() {
  if (const char* chosen = std::getenv("SLED_CHROMIUM"); chosen && *chosen) return chosen;
  const char* path = std::getenv("PATH");
  if (path == nullptr) return {};
  std::string folders = path;
  std::size_t start = 0;
  while (start <= folders.size()) {
    const std::size_t colon = std::min(folders.find(':', start), folders.size());
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path candidate = fs::path(folders.substr(start, colon - start)) / name;
      if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    start = colon + 1;
  }
  return {};
}

// A page loaded in headless Chromium: the DOM after its scripts ran, and the console log.
struct LoadedPage {
  bool loaded = false;  // Chromium ran and exited 0
  std::string dom;
  std::string console;
};

// Loads `page` with a profile of its own under `work` (so tests side by side and a user's
// browser never share one) and software WebGL (SwiftShader), as a machine without a GPU has.
inline LoadedPage LoadInChromium(const fs::path& chromium, const fs::path& page,
                                 const fs::path& work) {
  const fs::path dom = work / "dom.html";
  const fs::path log = work / "chromium.log";
  const std::string command =
      "timeout 120 " + Quote(chromium.string()) +
      " --headless --disable-gpu --no-sandbox --enable-unsafe-swiftshader --no-first-run"
      " --user-data-dir=" +
      Quote((work / "profile").string()) + " --enable-logging=stderr --v=0 --dump-dom " +
      Quote("file://" + fs::absolute(page).string()) + " >" + Quote(dom.string()) + " 2>" +
      Quote(log.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  LoadedPage result;
  result.loaded = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  result.dom = ReadText(dom);
  result.console = ReadText(log);
  return result;
}

}  // namespace sled::testing
