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
  const int nextcd = r.Integer(d1, 67, 72, "NEXTCD, the joint actuators");
  if (nextcd == 0) return 0;
  f.Refuse(d1, 67, 72,
           fmt::format("NEXTCD is {}: F.10 joint actuators, ATB's PID torques about pin "
                       "joints, their gains functions of the target angle; ATB's integral term "
                       "is one sum shared by every actuator, its angle and rate take opposite "
                       "senses (JNTFNC), and how the torque enters the equations of motion (the "
                       "caller of JNTFNC) is not in the reference",
                       nextcd),
           "drive the joint with a `load NAME on JOINT { torque = ... }` written by hand, or "
           "set NEXTCD to 0 and remove the D.1.b and F.10 cards");
  const Card d1b = r.Next("D.1.b", {"(12I6)"});
  return f.Count(d1b, 1, 6, "NRTORQ, the number of joint actuators",
                 static_cast<int>(f.deck().joints.size()));
}

void ReadActuators(DeckFields& f, int count) {
  DeckSource& r = f.source();
  for (int k = 0; k < count && !r.truncated(); ++k) {
    r.Next(fmt::format("F.10 (actuator {})", k + 1), {"(6I4)"});
  }
}

}  // namespace sled::lang::legacy
