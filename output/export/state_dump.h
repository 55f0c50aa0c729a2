// The "complete variable print out" of CVS-III at a chosen time (`sled run --dump-at T`): every
// state variable and force of the scene in a readable text form, after Forward at that time:
// the generalized coordinates and velocities, each vehicle's and segment's pose and motion, the
// joints' angles, torques and forces, springs, contacts, belts and loop-closing constraints.
#pragma once

#include <string>

#include "runtime/model/data.h"

namespace sled::runtime {

// The printout of data's state (kinematics, forces and accelerations must be current).
std::string StateDump(const Model& model, const Data& data);

// `dump_<t>.txt` for time t in seconds, with the shortest decimal that reads back to t.
std::string StateDumpFileName(double t);

// Writes StateDump to `path`; false with `error` set when the file cannot be written.
bool WriteStateDump(const std::string& path, const Model& model, const Data& data,
                    std::string* error);

}  // namespace sled::runtime
