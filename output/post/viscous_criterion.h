// The Viscous Criterion: VC(t) = SF * V(t) * D(t) / Dc, the chest's compression velocity V times
// its relative compression, scaled; the criterion is the largest value over time. V comes from
// the deflection D by five-point differentiation,
// V_i = [8 (D_{i+1} - D_{i-1}) - (D_{i+2} - D_{i-2})] / (12 dt).
#pragma once

#include <span>

namespace sled::runtime::post {

struct ViscousConstants {
  double scale = 0.0;                // SF
  double critical_deflection = 0.0;  // Dc [m]
};
// Hybrid III 50th male.
inline constexpr ViscousConstants kHybridIII50thMaleVc{1.3, 0.229};

struct ViscousResult {
  double value = 0.0;  // [m/s]
  double time = 0.0;
};

// `deflection` [m], compression positive. The two samples at each end, where the five-point
// difference has no neighbours, are left out.
ViscousResult ViscousCriterion(std::span<const double> deflection, double sample_period,
                               double start_time, const ViscousConstants& constants);

}  // namespace sled::runtime::post
