// The Tibia Index: TI(t) = |M_R(t)| / M_c + |F_z(t)| / F_c, with M_R the resultant of the
// bending moments about the tibia's x and y axes and F_z its axial force; the criterion is the
// largest value over time (Euro NCAP TB 021, as pyisomme's calculate_tibia_index implements it;
// crash-conventions §2.1 gives the UN R94 limit 1.3).
#pragma once

#include <span>

namespace sled::runtime::post {

struct TibiaConstants {
  double critical_moment = 0.0;  // M_c [N*m]
  double critical_force = 0.0;   // F_c [N]
};
// Hybrid III 50th male: 225 N*m and 35.9 kN (Euro NCAP TB 021 via pyisomme).
inline constexpr TibiaConstants kHybridIII50thMaleTibia{225.0, 35900.0};

struct TibiaResult {
  double value = 0.0;
  double time = 0.0;  // [s]
};

TibiaResult TibiaIndex(std::span<const double> moment_x, std::span<const double> moment_y,
                       std::span<const double> axial_force, double sample_period, double start_time,
                       const TibiaConstants& constants);

}  // namespace sled::runtime::post
