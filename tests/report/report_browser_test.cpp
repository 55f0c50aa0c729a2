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
#include "tests/report/chromium.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using ReportCommand = testing::SledProcessTest;

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

  const fs::path chromium = testing::FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "Chromium is not installed (Debian package `chromium`; scripts/setup.sh "
                    "installs it), so the report was not loaded in a browser";
  }
  const testing::LoadedPage page_in_browser = testing::LoadInChromium(chromium, page, temp());
  ASSERT_TRUE(page_in_browser.loaded) << "chromium failed:\n" << page_in_browser.console;
  const std::string& loaded = page_in_browser.dom;
  const std::string& console = page_in_browser.console;
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
