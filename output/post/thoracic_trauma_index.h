// The Thoracic Trauma Index of side impacts in its dummy form (FMVSS 214, the SID):
// TTI = (G_R + G_LS) / 2, with G_R the peak magnitude of the struck-side rib's lateral
// acceleration and G_LS that of the lower spine (T12), both in g (crash-conventions §2.1).
#pragma once

#include <span>

namespace sled::runtime::post {

struct TtiResult {
  double value = 0.0;       // [g]
  double rib_peak = 0.0;    // G_R [g]
  double spine_peak = 0.0;  // G_LS [g]
  double rib_time = 0.0;    // [s]
  double spine_time = 0.0;
};

// `rib_lateral` and `spine_lateral` in g.
TtiResult ThoracicTraumaIndex(std::span<const double> rib_lateral,
                              std::span<const double> spine_lateral, double sample_period,
                              double start_time);

}  // namespace sled::runtime::post
