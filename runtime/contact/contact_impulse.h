// The impulse option at first contact (CVS): when a pair with `impulse` comes into contact, an
// impulse along the contact normal at the contact point sets the surfaces' normal separation
// speed to the restitution times their closing speed. It acts through the whole system (the
// joints carry it), so momentum is kept; a prescribed side (vehicle, ground) is not changed.
#pragma once

#include "runtime/model/data.h"

namespace sled::runtime {

// Applies the impulse of pair k at data's state (q, v, time), changing data.v; nothing when
// the surfaces close slower than 1 cm/s (the force law takes such a contact). Sets whether the
// force law acts on the pair from here (data.contacts.engaged: not after a rebound, where the
// surfaces part at once; else until the event of their separation). Leaves data's
// kinematics current. False when the system's response cannot be computed (a singular
// articulated inertia).
bool ApplyContactImpulse(const Model& model, Data& data, std::size_t k);

}  // namespace sled::runtime
