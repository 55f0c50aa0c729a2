// A sweep's results as a table (sweep.csv) and a self-contained HTML page (sweep.html): each
// injury criterion and channel peak of each run against each varied input, and for pairs of
// inputs a response surface (a quadratic fitted by least squares, drawn as colored cells under
// the runs' own values).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace sled::report {

struct SweepRow {
  std::string folder;  // runs/0007
  std::string status;  // done, failed, error, crashed, not run
  int exit_code = -1;
  double wall_seconds = 0.0;
  std::string message;
  std::vector<double> inputs;                  // in the inputs' units
  std::vector<std::optional<double>> outputs;  // nullopt: not computed / no such output
};

struct SweepTable {
  std::string scene;
  std::vector<std::string> inputs;  // "speed [km/h]"
  // Criteria first ("hic15(occupant.head)", "head_3ms(occupant.head) cumulative [g]"), then
  // channel peaks ("peak occupant.head.acceleration.x [m/s^2]").
  std::vector<std::string> outputs;
  std::size_t criteria = 0;  // how many of `outputs` are criteria
  std::vector<SweepRow> rows;
};

// sweep.csv: run, folder, each input, status, exit code, wall time, message, each output; a
// value that is missing is an empty field.
std::string SweepCsv(const SweepTable& table);

// The coefficients of z = c0 + c1 x + c2 y + c3 x^2 + c4 xy + c5 y^2 fitted to the points by
// least squares, with the fit's R^2; nullopt with fewer than six points or a singular fit.
struct QuadraticFit {
  std::array<double, 6> c{};
  double r_squared = 0.0;
  double operator()(double x, double y) const {
    return c[0] + c[1] * x + c[2] * y + c[3] * x * x + c[4] * x * y + c[5] * y * y;
  }
};
std::optional<QuadraticFit> FitQuadratic(const std::vector<double>& x, const std::vector<double>& y,
                                         const std::vector<double>& z);

std::string BuildSweepPage(const SweepTable& table);

}  // namespace sled::report
