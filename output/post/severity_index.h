// The Gadd Severity Index: SI = integral of a(t)^2.5 dt over the pulse, with the resultant
// acceleration a in g and t in s (Gadd 1966; ATB reports it for the head as HSI and for the
// chest as CSI). The whole record is the pulse.
#pragma once

#include <span>

namespace sled::runtime::post {

// Trapezoid rule over the samples; negative samples count as zero.
double GaddSeverityIndex(std::span<const double> resultant_g, double sample_period);

}  // namespace sled::runtime::post
