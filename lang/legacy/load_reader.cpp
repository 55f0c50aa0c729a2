// D.9: ATB's applied forces and torques (INPUT_FORCE_TORQUE reads them, FORCE_TORQUE applies
// them): a function of time times a direction fixed in a segment's axes, as a force at a point
// of the segment (NFVSEG > 0) or a torque (NFVSEG < 0).
#include <cstdlib>

#include <fmt/format.h>

#include "lang/legacy/load_reader.h"

namespace sled::lang::legacy {

void ReadAppliedLoads(DeckFields& f, int count) {
  DeckSource& r = f.source();
  Deck& deck = f.deck();
  const int body_segments = static_cast<int>(deck.segments.size());
  const int frames = body_segments + static_cast<int>(deck.vehicles.size());
  for (int k = 0; k < count && !r.truncated(); ++k) {
    const Card card = r.Next(fmt::format("D.9 (force or torque {})", k + 1), {"(2I6,6F10.0)"});
    LoadCard load;
    load.line = card.line;
    load.segment = f.Reference(card, 1, 6, "NFVSEG, the segment (negative: a torque)");
    load.function = f.Reference(card, 7, 12, "NFVNT, the function of time");
    // FORCE_TORQUE evaluates function |NFVNT|: the sign of the number means nothing.
    load.function.number = std::abs(load.function.number);
    load.point = f.Triple(card, 13, 10, "the point of application");
    load.orientation = f.Triple(card, 43, 10, "the yaw, pitch and roll of the direction");
    if (r.truncated()) return;
    const int segment = std::abs(load.segment.number);
    if (segment == 0 || segment > frames) {
      f.Invalid(card, 1, 6,
                fmt::format("NFVSEG is {}: there is no segment {}", load.segment.number, segment),
                fmt::format("give a body segment's number, 1 to {}, negative for a torque",
                            body_segments));
      continue;
    }
    if (segment > body_segments) {
      f.Ignored(
          card, 1, 6,
          fmt::format("NFVSEG is {}: a load on vehicle segment {}", load.segment.number, segment),
          "ATB adds it to a segment whose motion it prescribes, so it moves nothing; the "
          "card is left out");
      continue;
    }
    if (load.torque() && load.point != Vec3{}) {
      f.Ignored(card, 13, 42, "the point of application of a torque (NFVSEG < 0)",
                "FORCE_TORQUE applies a torque (NFVSEG < 0) about its axis whatever the point; the "
                "point is left out");
    }
    deck.loads.push_back(load);
  }
}

int ReadActuatorCount(DeckFields& f, const Card& d1) {
  DeckSource& r = f.source();
  if (r.Integer(d1, 67, 72, "NEXTCD, the joint actuators") == 0) return 0;
  const Card d1b = r.Next("D.1.b", {"(12I6)", 1});  // ATB reads NRTORQ alone
  return f.Count(d1b, 1, 6, "NRTORQ, the number of joint actuators",
                 static_cast<int>(f.deck().joints.size()));
}

void ReadActuators(DeckFields& f, int count) {
  DeckSource& r = f.source();
  Deck& deck = f.deck();
  for (int k = 0; k < count && !r.truncated(); ++k) {
    const Card card = r.Next(fmt::format("F.10 (actuator {})", k + 1), {"(6I4)"});
    ActuatorCard actuator;
    actuator.line = card.line;
    actuator.joint = f.Reference(card, 1, 4, "ACT_JNT, the joint");
    actuator.base = f.Reference(card, 5, 8, "BASE_SEG, the base segment");
    actuator.target = f.Reference(card, 9, 12, "the target angle's function of time");
    actuator.proportional = f.Reference(card, 13, 16, "the proportional gain's function");
    actuator.derivative = f.Reference(card, 17, 20, "the derivative gain's function");
    actuator.integral = f.Reference(card, 21, 24, "the integral gain's function");
    if (r.truncated()) return;
    const int joint = actuator.joint.number;
    if (joint < 1 || joint > static_cast<int>(deck.joints.size())) {
      f.Invalid(card, 1, 4, fmt::format("ACT_JNT is {}: there is no joint {}", joint, joint),
                fmt::format("give a joint's number, 1 to {}", deck.joints.size()));
      continue;
    }
    const JointCard& driven = deck.joints[static_cast<std::size_t>(joint - 1)];
    if (driven.type != JointType::kPin) {
      f.Invalid(card, 1, 4,
                fmt::format("joint {} is not a pin joint (JTYPE 1 or -1): ATB stops (STOP 111 in "
                            "INPUT_ROBOTICS)",
                            joint),
                "an actuator drives a pin joint; give one, or make the joint a pin on B.3.a");
      continue;
    }
    const int base = actuator.base.number;
    if (base != driven.parent && base != joint + 1) {
      f.Invalid(card, 5, 8,
                fmt::format("BASE_SEG is {}: neither segment {} nor segment {} of joint {}: ATB "
                            "stops (STOP 112 in INPUT_ROBOTICS)",
                            base, driven.parent, joint + 1, joint),
                "the base segment is the joint's proximal segment (JNT) or its distal one (J + 1)");
      continue;
    }
    actuator.base_is_proximal = base == driven.parent;
    deck.actuators.push_back(actuator);
  }
}

}  // namespace sled::lang::legacy
