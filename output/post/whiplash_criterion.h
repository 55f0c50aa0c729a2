// The Neck Injury Criterion of rear impacts (Bostrom et al., IRCOBI 1996), as UN GTR 7 computes
// it: the relative acceleration a_rel = a_T1,x - a_head,x of the first thoracic vertebra and
// the head (both longitudinal, each in its own axes, CFC 60), its integral v_rel from the start
// of the record, and NIC(t) = 0.2 a_rel(t) + v_rel(t)^2 [m^2/s^2]; NICmax is the largest value.
// GTR 7 takes the maximum until the head leaves the head restraint; here the whole record
// counts, which is the same for a run that ends before the rebound or gives the larger value.
#pragma once

#include <span>

namespace sled::runtime::post {

struct NicResult {
  double value = 0.0;  // [m^2/s^2]
  double time = 0.0;   // [s]
};

// `t1` and `head` [m/s^2] sampled together; v_rel by the trapezoid rule from v_rel = 0 at the
// first sample.
NicResult NeckInjuryCriterionOfRearImpact(std::span<const double> t1, std::span<const double> head,
                                          double sample_period, double start_time);

}  // namespace sled::runtime::post
