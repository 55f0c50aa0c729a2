// The scene's injury criteria (Model::criterion_*), computed after the run from the raw output
// channels: each input channel is filtered at the class its criterion prescribes (SAE J211),
// then resultants and axial loads are formed, then the criterion.
//
// Inputs by criterion: the head criteria read the acceleration of the segment's centre of mass
// at CFC 1000, the chest criteria at CFC 180; neck tension and compression the joint force at
// CFC 1000; Nij, Nkm and the Tibia Index the joint force and torque at CFC 600; femur load the
// joint force at CFC 600; NIC the head's and T1's accelerations along their own x at CFC 60;
// TTI the rib's and lower spine's along their own y at CFC 180.
// Joint loads are read as a load cell in the child segment would: the axial force along the
// child's z axis (compression when it pushes the child away from the joint, tension when it
// pulls), shear along x (forward) and flexion as the moment about -y (y to the occupant's left),
// all about the joint point, which stands for the occipital condyle in Nij.
#pragma once

#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/model/model.h"
#include "runtime/run/time_series.h"

namespace sled::runtime::post {

// One value per criterion; the 3 ms criteria give two (cumulative and continuous) and Nij
// gives its value and then its four quadrant terms. A criterion whose channels cannot be
// filtered (too low a sample rate) or whose record is too short is returned not computed, with
// the reason.
std::vector<CriterionValue> EvaluateCriteria(const Model& model, const TimeSeries& raw);

}  // namespace sled::runtime::post
