// What a `contact_force` request reports: the pairs of its group summed (a segment with several
// ellipsoids touching one surface gives several pairs).
#pragma once

#include "runtime/model/data.h"

namespace sled::runtime {

struct ContactGroupValues {
  Vec3 force = Vec3::Zero();  // on the first surface, world frame: normal force and friction
  double normal_force = 0.0;  // sum of the pairs' normal forces (>= 0)
  Vec3 point = Vec3::Zero();  // normal-force-weighted mean of the pairs' points; 0 when apart
  double deflection = 0.0;    // the largest deflection of the pairs; 0 when apart
};

ContactGroupValues EvaluateContactGroup(const Model& model, const Data& data, std::size_t group);

}  // namespace sled::runtime
