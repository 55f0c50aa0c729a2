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

// ATB's free bag holds its gas at the ambient pressure while it unfolds: AIRBGG gives the volume
// CYV the cylinder's delivered gas takes there, CYVMAX (1 - Q^(-2 gamma / (gamma - 1))), which is
// not proportional to the weight delivered, V0 rho0 (1 - Q^(-2 / (gamma - 1))); AIRBG3 freezes
// their ratio, SWITCH, when the bag becomes full, and the polytropic law of the full bag uses it.
// sled's free bag takes a volume proportional to its gas mass at the ambient pressure,
// m R T_ref / p_a. `reference_temperature` is the T_ref that makes the ratio ATB's SWITCH at
// the fill (with nothing in the bag's way): the full bag's gas law is then ATB's exactly.
// `largest_unfolding_difference` is the largest difference, over the unfolding, between the two
// volumes, as a share of the bag's volume. When the cylinder's whole gas takes less than the bag
// (`fills` false), T_ref is the limit of the ratio, T0 / gamma.
struct BagFill {
  bool fills = false;
  double reference_temperature = 0;
  double largest_unfolding_difference = 0;
};
BagFill FillFreeBag(const Cylinder& cylinder, double bag_volume);

}  // namespace sled::lang::legacy
