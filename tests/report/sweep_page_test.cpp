// The sweep page's pieces: the response surface's least-squares fit against surfaces it must
// recover exactly, and the table's CSV.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "output/report/sweep_page.h"

namespace sled::report {
namespace {

using ::testing::HasSubstr;

TEST(FitQuadratic, RecoversAQuadraticSampledOnAGrid) {
  std::vector<double> x, y, z;
  for (double a = 40; a <= 64; a += 8) {
    for (double b = 0; b <= 30; b += 10) {
      x.push_back(a);
      y.push_back(b);
      z.push_back(3 + 2 * a - b + 0.5 * a * a + 0.25 * a * b - 0.1 * b * b);
    }
  }
  const auto fit = FitQuadratic(x, y, z);
  ASSERT_TRUE(fit.has_value());
  const std::array<double, 6> expected = {3, 2, -1, 0.5, 0.25, -0.1};
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(fit->c[k], expected[k], 1e-8) << k;
  EXPECT_NEAR(fit->r_squared, 1.0, 1e-12);
}

TEST(FitQuadratic, WithTwoLevelsOfAnInputLeavesOutItsSquare) {
  // Two values of y: y^2 cannot be told from y; the fit keeps x^2 and xy.
  std::vector<double> x, y, z;
  for (double a : {1.0, 2.0, 3.0, 4.0}) {
    for (double b : {0.0, 1.0}) {
      x.push_back(a);
      y.push_back(b);
      z.push_back(1 + a * a + 2 * a * b);
    }
  }
  const auto fit = FitQuadratic(x, y, z);
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR((*fit)(2.5, 0.5), 1 + 6.25 + 2.5, 1e-9);
  EXPECT_NEAR(fit->c[5], 0.0, 1e-12);
}

TEST(FitQuadratic, RefusesTooFewPoints) {
  EXPECT_FALSE(FitQuadratic({1, 2}, {1, 2}, {1, 2}).has_value());
}

TEST(SweepCsv, QuotesMessagesAndLeavesMissingValuesEmpty) {
  SweepTable table;
  table.inputs = {"speed [km/h]"};
  table.outputs = {"hic15(occupant.head)"};
  table.criteria = 1;
  SweepRow row;
  row.folder = "runs/0000";
  row.status = "failed";
  row.exit_code = 3;
  row.wall_seconds = 0.5;
  row.message = "sled: the simulation failed at t = 0.06 s, in \"ball\"";
  row.inputs = {40};
  row.outputs = {std::nullopt};
  table.rows.push_back(row);
  EXPECT_EQ(SweepCsv(table),
            "run,folder,speed [km/h],status,exit_code,wall_seconds,message,hic15(occupant.head)\n"
            "0,runs/0000,40,failed,3,0.5,\"sled: the simulation failed at t = 0.06 s, in "
            "\"\"ball\"\"\",\n");
}

}  // namespace
}  // namespace sled::report
