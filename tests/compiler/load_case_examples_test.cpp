// The standard load-case examples end to end, as a user runs them: `sled run` exits 0, the scene
// settles before the run and starts it at rest (below the threshold its `settle` block states,
// read both from summary.json and from the first row of the time histories), and the criteria
// are computed and judged against the limits of their standard.
#include <cmath>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/mini_json.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::JsonReader;
using testing::ReadText;
using testing::SledResult;

using LoadCaseExamples = testing::SledProcessTest;

// The speed of a point's velocity channels (ground frame) at a row.
double Speed(const testing::CsvTable& table, std::size_t row, const std::string& prefix) {
  double sum = 0.0;
  for (const char* axis : {"x", "y", "z"}) {
    const std::size_t column = table.Column(prefix + ".velocity." + axis + " [m/s]");
    EXPECT_LT(column, table.names.size()) << prefix << " has no velocity channels";
    if (column >= table.names.size()) return NAN;
    sum += table.rows[row][column] * table.rows[row][column];
  }
  return std::sqrt(sum);
}

TEST_F(LoadCaseExamples, TheRearImpactSettlesStartsAtRestAndJudgesItsCriteria) {
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", "examples/rear_impact.sled", "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.err, ::testing::HasSubstr("sled: settled in"));
  const testing::Json summary = JsonReader::Parse(ReadText(out / "summary.json"));
  EXPECT_EQ(summary["status"].text, "ok");
  const testing::Json& settle = summary["settle"];
  EXPECT_TRUE(settle["converged"].boolean);
  // The threshold the example's `settle` block states: 5 mm/s.
  EXPECT_DOUBLE_EQ(settle["velocity_tolerance"].number, 0.005);
  EXPECT_LE(settle["largest_velocity"].number, 0.005);
  const testing::CsvTable table = testing::ReadCsv(out / "timeseries.csv");
  ASSERT_FALSE(table.rows.empty());
  EXPECT_LT(Speed(table, 0, "occupant.head"), 0.005);
  EXPECT_LT(Speed(table, 0, "occupant.pelvis"), 0.005);
  // The head restraint catches the head: the contact carries load during the run.
  const std::size_t restraint = table.Column("occupant.head.head_restraint.contact_force.x [N]");
  ASSERT_LT(restraint, table.names.size());
  double largest = 0.0;
  for (const auto& row : table.rows) largest = std::max(largest, std::abs(row[restraint]));
  EXPECT_GT(largest, 10.0);
  // At rest means in equilibrium: at the start (the pulse's onset, no acceleration yet) every
  // centre of mass the example watches accelerates by less than 0.1 g.
  for (const char* segment : {"occupant.head", "occupant.thorax", "occupant.pelvis"}) {
    double sum = 0.0;
    for (const char* axis : {"x", "y", "z"}) {
      const double a =
          table.rows[0][table.Column(std::string(segment) + ".acceleration." + axis + " [m/s^2]")];
      sum += a * a;
    }
    EXPECT_LT(std::sqrt(sum), 0.1 * 9.80665) << segment;
  }
  // Every criterion computed, with its limit and the standard it comes from; Nkm and NIC, the
  // rear impact's neck criteria, among them.
  const testing::Json& criteria = summary["criteria"];
  bool nkm = false;
  bool nic = false;
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    if (!criteria[i]["variant"].text.empty()) continue;  // a quadrant or clip variant
    SCOPED_TRACE(criteria[i]["name"].text);
    EXPECT_EQ(criteria[i]["value"].kind, testing::Json::Kind::kNumber);
    EXPECT_EQ(criteria[i]["limit"].kind, testing::Json::Kind::kNumber);
    EXPECT_FALSE(criteria[i]["limit_source"].text.empty());
    nkm = nkm || criteria[i]["name"].text == "nkm";
    nic = nic || criteria[i]["name"].text == "nic";
  }
  EXPECT_TRUE(nkm);
  EXPECT_TRUE(nic);
}

}  // namespace
}  // namespace sled
