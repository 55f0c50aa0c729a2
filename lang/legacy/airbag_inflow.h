// ATB's airbag cylinder (AIRBGG, with the constants INPUT_AIRBAGS sets up) tabulated as sled's
// inflow function. ATB's cylinder starts emptying at CYTD through a choked throat and delivers a
// gas weight of closed form: with Q = 1 + C (t - CYTD),
//   W(t) = V0 rho0 (1 - Q^(-2 / (gamma - 1))),
//   C = (gamma - 1) / 2 * c0 CYCD / L0 * ((gamma + 1) / 2)^(-(gamma + 1) / (2 (gamma - 1))),
// where c0 = sqrt(gamma R T0 G) is the speed of sound of the cylinder's gas, L0 = V0 / CYAT,
// rho0 = (CYSP + CYPA) / (R T0) its weight density (R is ATB's gas constant per weight). The
// mass flow is dW/dt / G. sled's `inflow` is a table of it, interpolated linearly and zero after
// its last row.
#pragma once

#include <utility>
#include <vector>

namespace sled::lang::legacy {

struct Cylinder {
  double gamma = 0;             // CYK
  double gas_constant = 0;      // CYR, per weight: length / temperature
  double temperature = 0;       // CYT0
  double supply_pressure = 0;   // CYSP, above ambient
  double ambient_pressure = 0;  // CYPA
  double volume = 0;            // CYV0
  double throat_area = 0;       // CYAT
  double discharge = 0;         // CYCD
  double g = 0;                 // A.3's G
};

// The rows (time since CYTD, mass flow in force * time / length) every `step` from 0 to the time
// by which 99.9 % of the gas is delivered, values to 6 significant digits; `step` is that time
// over 50, rounded down to 1, 2 or 5 times a power of ten. `delivered` is the share of the
// cylinder's gas (ATB delivers all of it, as t grows) that the table, interpolated linearly and
// zero after its last row, delivers.
struct InflowTable {
  bool valid = false;  // false when the deck's values give no finite, positive flow to tabulate
  double step = 0;
  double end = 0;
  double delivered = 0;
  std::vector<std::pair<double, double>> rows;
};

InflowTable TabulateCylinder(const Cylinder& cylinder);

}  // namespace sled::lang::legacy
