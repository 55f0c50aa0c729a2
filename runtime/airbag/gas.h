// Gas dynamics and geometry of a uniform-pressure airbag, as pure functions: the mass flow of an
// ideal gas through an orifice (choked or not), and the cap an ellipsoid loses to a cutting
// plane. docs/runtime.md, "Airbags", gives the formulas.
#pragma once

#include "runtime/model/model_types.h"

namespace sled::runtime {

// Mass flow [kg/s] of an ideal gas (ratio of specific heats `gamma`, specific gas constant
// `gas_constant`) at `pressure` and `temperature` out through an orifice of effective area
// `discharge_area` (discharge coefficient times area) into `ambient_pressure`: isentropic
// nozzle flow, choked when the pressure ratio is at or below the critical one. Zero when the
// gas is not above the ambient pressure (outside air never flows in).
double OrificeMassFlow(double discharge_area, double pressure, double temperature,
                       double ambient_pressure, double gamma, double gas_constant);

// ATB's polytropic gas: the absolute pressure of a gas that takes `ambient_volume` at
// `ambient_pressure`, compressed (or expanded) to `volume` along p V^gamma = constant.
double PolytropicPressure(double ambient_pressure, double ambient_volume, double volume,
                          double gamma);

// ATB's vent: the mass flow [kg/s] of an incompressible orifice flow, C_d A sqrt(2 rho dp), of
// the gas at `density` driven by the gauge pressure `gauge`, while the gauge pressure is above
// `opening_pressure`; zero otherwise (and for a closed bag).
double SquareRootVentFlow(double discharge_area, double density, double gauge,
                          double opening_pressure);

// The cap of height `height` (from the surface, along the unit `normal`) that a plane
// perpendicular to `normal` cuts from an ellipsoid with semi-axes `semi_axes` whose axes are the
// columns of `rotation`: its volume and the area of its flat base, which is the derivative of
// the volume with respect to the height. Heights beyond the ellipsoid's width give the whole
// ellipsoid and a zero base.
struct EllipsoidCap {
  double volume = 0.0;
  double area = 0.0;
};
EllipsoidCap CutEllipsoidCap(const Vec3& semi_axes, const Mat3& rotation, const Vec3& normal,
                             double height);

}  // namespace sled::runtime
