// `sled sweep` of the flagship scene (cut to 20 ms) over two speeds and two belt slacks: the
// table holds every criterion of every run, and sweep.html loads in headless Chromium without a
// script error, with a plot of each criterion against each input and a response surface over
// the two inputs. Skipped, saying so, where Chromium is not installed.
#include <algorithm>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/sled_process.h"
#include "tests/report/chromium.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::WriteText;

using SweepPage = testing::SledProcessTest;

std::string AttributeOf(const std::string& html, const std::string& name) {
  std::smatch match;
  if (std::regex_search(html, match, std::regex(name + "=\"([^\"]*)\""))) return match[1];
  return "";
}

TEST_F(SweepPage, FlagshipSweepPageLoadsInChromiumWithEveryPlot) {
  WriteText(temp() / "flagship.sled", testing::FlagshipScene("20 ms"));
  const fs::path out = temp() / "sweep";
  const testing::SledResult result =
      Sled({"sweep", (temp() / "flagship.sled").string(), "-o", out.string(), "--vary",
            "speed=40,56 km/h", "--vary", "belt_slack=0..10 mm step 10"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string csv = ReadText(out / "sweep.csv");
  EXPECT_THAT(csv, HasSubstr("speed [km/h],belt_slack [mm],status"));
  EXPECT_THAT(csv, HasSubstr("hic15(occupant.head)"));
  EXPECT_THAT(csv, HasSubstr("3,runs/0003,56,10,done"));
  const std::string html = ReadText(out / "sweep.html");
  // Each criterion with values (the table's columns between `message` and the first peak): a
  // response surface over the two inputs.
  std::vector<std::vector<std::string>> lines;
  std::istringstream rows(csv);
  for (std::string line; std::getline(rows, line);) lines.push_back(testing::SplitCommas(line));
  ASSERT_EQ(lines.size(), 5u);
  long criteria = 0;
  for (std::size_t c = 8; c < lines[0].size() && lines[0][c].rfind("peak ", 0) != 0; ++c) {
    bool all = true;  // columns 0-7: run, folder, two inputs, status, exit code, wall, message
    for (std::size_t r = 1; r < lines.size(); ++r)
      all &= c < lines[r].size() && !lines[r][c].empty();
    criteria += all ? 1 : 0;
  }
  EXPECT_GE(criteria, 5) << csv.substr(0, 2000);
  long surfaces = 0;
  for (std::size_t at = html.find("<figure class=\"surface\">"); at != std::string::npos;
       at = html.find("<figure class=\"surface\">", at + 1)) {
    ++surfaces;
  }
  EXPECT_EQ(surfaces, criteria);

  const fs::path chromium = testing::FindChromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "Chromium is not installed (Debian package `chromium`; scripts/setup.sh "
                    "installs it), so the sweep page was not loaded in a browser";
  }
  const testing::LoadedPage page = testing::LoadInChromium(chromium, out / "sweep.html", temp());
  ASSERT_TRUE(page.loaded) << "chromium failed:\n" << page.console;
  ASSERT_NE(page.dom.find("</html>"), std::string::npos) << "no DOM dumped:\n" << page.console;
  EXPECT_EQ(AttributeOf(page.dom, "data-script-error"), "") << page.console;
  EXPECT_EQ(page.console.find("Uncaught"), std::string::npos) << page.console;
  EXPECT_EQ(AttributeOf(page.dom, "data-sweep"), "ready") << page.console;
  const auto plots = std::stol("0" + AttributeOf(page.dom, "data-plots"));
  long svgs = 0;
  for (std::size_t at = html.find("<svg class=\"plot\""); at != std::string::npos;
       at = html.find("<svg class=\"plot\"", at + 1)) {
    ++svgs;
  }
  EXPECT_EQ(plots, svgs);
  EXPECT_GT(plots, 10);
}

}  // namespace
}  // namespace sled
