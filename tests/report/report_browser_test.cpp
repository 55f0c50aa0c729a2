// `sled report` end to end: the flagship scene cut to 30 ms is run, its folder turned into a
// page, and the page loaded in headless Chromium (Debian `chromium`). The DOM Chromium dumps
// after loading must show the viewer ready (`data-viewer="ready"`, set only when the GLB was
// read and the first frame drawn without a WebGL error), no uncaught script error (the page's
// error trap writes `data-script-error`), and the viewer must have found as many nodes and key
// frames as the GLB and the CSV hold. Skipped, saying so, where Chromium is not installed.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/mini_json.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using ReportCommand = testing::SledProcessTest;

// The Chromium program on PATH (SLED_CHROMIUM overrides), or empty.
fs::path FindChromium() {
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

// The node count of a GLB's JSON chunk.
std::size_t GlbNodeCount(const std::string& glb) {
  if (glb.size() < 20) return 0;
  std::uint32_t length = 0;
  for (int i = 3; i >= 0; --i) {
    length = (length << 8) | static_cast<unsigned char>(glb[12 + static_cast<std::size_t>(i)]);
  }
  const testing::Json json = testing::JsonReader::Parse(glb.substr(20, length));
  return json["nodes"].size();
}

std::string Attribute(const std::string& html, const std::string& name) {
  std::smatch match;
  if (std::regex_search(html, match, std::regex(name + "=\"([^\"]*)\""))) return match[1];
  return "";
}

TEST_F(ReportCommand, UsageErrors) {
  SledResult result = Sled({"report"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("`report` takes one run folder"), std::string::npos) << result.err;
  result = Sled({"report", (temp() / "no-such-run").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("summary.json"), std::string::npos) << result.err;
}

TEST_F(ReportCommand, FlagshipReportLoadsInChromiumWithoutScriptErrors) {
  WriteText(temp() / "flagship.sled", testing::FlagshipScene("30 ms"));
  const fs::path run = temp() / "run";
  SledResult result = Sled({"run", (temp() / "flagship.sled").string(), "-o", run.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  result = Sled({"report", run.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const fs::path page = run / "report.html";
  ASSERT_TRUE(fs::exists(page)) << result.out << result.err;
  EXPECT_NE(result.out.find("report.html"), std::string::npos) << result.out;
  const std::string html = ReadText(page);
  EXPECT_NE(html.find("hic15"), std::string::npos);
  EXPECT_NE(html.find("id=\"animation-glb\""), std::string::npos);

  // -o puts the page elsewhere.
  result = Sled({"report", run.string(), "-o", (temp() / "elsewhere.html").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReadText(temp() / "elsewhere.html"), html);

  const fs::path chromium = FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "Chromium is not installed (Debian package `chromium`; scripts/setup.sh "
                    "installs it), so the report was not loaded in a browser";
  }
  // A profile of its own, so tests side by side and a user's browser never share one; software
  // WebGL (SwiftShader), as a machine without a GPU has.
  const fs::path dom = temp() / "dom.html";
  const fs::path log = temp() / "chromium.log";
  const std::string command =
      "timeout 120 " + testing::Quote(chromium.string()) +
      " --headless --disable-gpu --no-sandbox --enable-unsafe-swiftshader --no-first-run"
      " --user-data-dir=" +
      testing::Quote((temp() / "profile").string()) + " --enable-logging=stderr --v=0 --dump-dom " +
      testing::Quote("file://" + fs::absolute(page).string()) + " >" +
      testing::Quote(dom.string()) + " 2>" + testing::Quote(log.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0) << "chromium failed:\n"
                                                                             << ReadText(log);
  const std::string loaded = ReadText(dom);
  const std::string console = ReadText(log);
  ASSERT_NE(loaded.find("</html>"), std::string::npos) << "no DOM dumped:\n" << console;
  EXPECT_EQ(Attribute(loaded, "data-script-error"), "") << console;
  EXPECT_EQ(console.find("Uncaught"), std::string::npos) << console;
  EXPECT_EQ(Attribute(loaded, "data-viewer"), "ready")
      << "viewer status: " << Attribute(loaded, "data-state") << "\n"
      << console;
  // What the viewer read is what the files hold: every node of the GLB, a key frame per row.
  EXPECT_EQ(Attribute(loaded, "data-nodes"),
            std::to_string(GlbNodeCount(ReadText(run / "animation.glb"))));
  EXPECT_EQ(Attribute(loaded, "data-frames"), "301");  // 30 ms at 0.1 ms
}

}  // namespace
}  // namespace sled
