// Physical dimensions: the exponents of length, mass, time, angle and temperature a quantity
// carries.
//
// Angle is a base dimension on purpose, although SI treats it as dimensionless: it lets the
// checker tell a torque (N*m) from a rotational stiffness (N*m/rad), an angular velocity (rad/s)
// from a frequency (Hz), and catch `stop = 0.7` where `0.7 deg` was meant.
//
// Some named dimensions coincide: energy is torque (kg*m^2/s^2) and mass flow is damping (kg/s).
// DescribeDimension gives the name a crash model needs more often (torque, damping); a caller that
// knows it expects energy or mass flow can name it itself and use SiUnitSymbol for the unit.
#pragma once

#include <string>

namespace sled::compiler {

struct Dimension {
  int length = 0;
  int mass = 0;
  int time = 0;
  int angle = 0;
  int temperature = 0;  // the inflator gas of an airbag

  // This dimension raised to a whole power: (m/s)^2 is m^2/s^2.
  constexpr Dimension Pow(int exponent) const {
    return {length * exponent, mass * exponent, time * exponent, angle * exponent,
            temperature * exponent};
  }
  constexpr bool IsDimensionless() const {
    return length == 0 && mass == 0 && time == 0 && angle == 0 && temperature == 0;
  }

  friend constexpr Dimension operator*(Dimension a, Dimension b) {
    return {a.length + b.length, a.mass + b.mass, a.time + b.time, a.angle + b.angle,
            a.temperature + b.temperature};
  }
  friend constexpr Dimension operator/(Dimension a, Dimension b) {
    return {a.length - b.length, a.mass - b.mass, a.time - b.time, a.angle - b.angle,
            a.temperature - b.temperature};
  }
  friend constexpr bool operator==(Dimension a, Dimension b) = default;
};

// The named dimensions the schema and the unit table use.
namespace dim {

inline constexpr Dimension kDimensionless{};
inline constexpr Dimension kLength{.length = 1};
inline constexpr Dimension kMass{.mass = 1};
inline constexpr Dimension kTime{.time = 1};
inline constexpr Dimension kAngle{.angle = 1};
inline constexpr Dimension kTemperature{.temperature = 1};

inline constexpr Dimension kArea = kLength.Pow(2);
inline constexpr Dimension kVolume = kLength.Pow(3);
inline constexpr Dimension kVelocity = kLength / kTime;
inline constexpr Dimension kAcceleration = kVelocity / kTime;
inline constexpr Dimension kAngularVelocity = kAngle / kTime;
inline constexpr Dimension kAngularAcceleration = kAngularVelocity / kTime;
inline constexpr Dimension kForce = kMass * kAcceleration;
inline constexpr Dimension kTorque = kForce * kLength;
inline constexpr Dimension kStiffness = kForce / kLength;
inline constexpr Dimension kDamping = kForce * kTime / kLength;
inline constexpr Dimension kRotationalStiffness = kTorque / kAngle;
inline constexpr Dimension kRotationalDamping = kTorque * kTime / kAngle;
inline constexpr Dimension kInertia = kMass * kArea;
inline constexpr Dimension kPressure = kForce / kArea;
inline constexpr Dimension kEnergy = kForce * kLength;  // the same dimension as kTorque
inline constexpr Dimension kFrequency = kDimensionless / kTime;
inline constexpr Dimension kMassFlow = kMass / kTime;  // the same dimension as kDamping
inline constexpr Dimension kDensity = kMass / kVolume;
inline constexpr Dimension kImpulse = kForce * kTime;
// The specific gas constant R of an ideal gas: p = rho R T.
inline constexpr Dimension kSpecificGasConstant = kEnergy / kMass / kTemperature;

}  // namespace dim

// The SI unit of a dimension: "m", "N", "N*m/rad", "m/s^2", "kg*m^2/s"; empty when dimensionless.
std::string SiUnitSymbol(Dimension dimension);

// A readable name with the SI unit: "length [m]", "rotational stiffness [N*m/rad]",
// "dimensionless", or for a combination without a name a formula such as
// "mass*length^2/time [kg*m^2/s]".
std::string DescribeDimension(Dimension dimension);

// Both sides of a mismatch for a message, such as "length [m] and time [s]", so that a caller can
// write "cannot add {}" or "cannot compare {}".
std::string DescribeMismatch(Dimension a, Dimension b);

// A help text for a value of dimension `found` where `expected` belongs, or empty when there is
// nothing useful to add: it points out a missing unit or a missing or extra angle unit.
std::string MismatchHelp(Dimension expected, Dimension found);

// MismatchHelp, or else a general hint naming the expected dimension: never empty.
std::string DimensionHelp(Dimension expected, Dimension found);

}  // namespace sled::compiler
