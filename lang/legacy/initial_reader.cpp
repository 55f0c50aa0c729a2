// Card group G, the initial conditions: G.1.a (the velocity source I3), a G.2 card per
// reference segment (position and velocity, IREF2 and IREF4) and a G.3.a card per segment
// (orientation and angular velocity), as ATB V.3's INPUT_INITIAL_CONDITIONS, INPUT_LINEAR and
// INPUT_ORIENT read them.
#include "lang/legacy/initial_reader.h"

#include "lang/legacy/equilibrium_reader.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

class InitialReader : public DeckFields {
 public:
  InitialReader(DeckFields& fields, int bags)
      : DeckFields(fields.source(), fields.deck()), bags_(bags) {}

  void Read() {
    const Card g1 = r_.Next("G.1.a", {"(30X,2I4,8X,I4)", -1, false, 35});
    const int i1 = r_.Integer(g1, 31, 34, "I1");
    const int j1 = r_.Integer(g1, 35, 38, "J1");
    const int i3 = r_.Integer(g1, 47, 50, "I3, the velocity source");
    // I3 = 0: every reference segment moves with the primary vehicle and the G.2 and G.3
    // velocities are not used (INPUT_LINEAR, INPUT_ORIENT); 1: the G cards give them; 2: the G
    // cards where IREF2 is 0, which is every card sled converts (IREF2 is refused).
    if (i3 < 0 || i3 > 2) {
      Invalid(g1, 47, 50, fmt::format("I3 is {}", i3),
              "I3 is 0 (velocities of the primary vehicle), 1 or 2 (velocities from the G cards)");
    }
    deck_.velocities_from_vehicle = i3 == 0;
    deck_.velocity_source_line = g1.line;
    if (j1 != 0) {
      r_.Next("G.1.b (obsolete)", {"(I1)"});
      Unverified(g1, 35, 38, "J1 is not zero: the obsolete G.1.b card is read and ignored");
    }
    // One G.2 card per reference segment: segment 1 and each J+1 whose JNT(J) = 0.
    std::vector<int> references{1};
    for (std::size_t j = 0; j < deck_.joints.size(); ++j) {
      if (deck_.joints[j].parent == 0) references.push_back(static_cast<int>(j) + 2);
    }
    for (const int segment : references) {
      const Card card =
          r_.Next(fmt::format("G.2 (reference segment {})", segment), {"(6F10.0,2I3)"});
      InitialCard initial;
      initial.line = card.line;
      initial.segment = segment;
      initial.position = Triple(card, 1, 10, "the position");
      initial.velocity = GivenVelocity(card, "velocity");
      if (r_.Integer(card, 61, 63, "IREF2") != 0) {
        Refuse(card, 61, 63, "IREF2: the velocity of a vehicle",
               "write the velocity on the card itself");
      }
      // IREF4: the position is in the axes of a segment with prescribed motion, from its
      // position (INPUT_LINEAR): a vehicle; anything else stops ATB (STOP 223).
      if (const int iref4 = r_.Integer(card, 64, 66, "IREF4"); iref4 != 0) {
        const auto frame = FrameOf(card, 64, 66, iref4, bags_, "IREF4");
        if (frame && frame->kind == DeckFrame::Kind::kVehicle) {
          initial.position_vehicle = frame->index;
        } else if (frame) {
          Invalid(card, 64, 66, fmt::format("IREF4 is {}, which has no prescribed motion", iref4),
                  "IREF4 names a vehicle (NSEG + its number) or is 0 (the inertial frame); ATB "
                  "stops otherwise (STOP 223)");
        }
      }
      deck_.initial_positions.push_back(initial);
    }
    for (std::size_t s = 0; s < deck_.segments.size(); ++s) {
      const Card card = r_.Next(fmt::format("G.3.a (segment {})", s + 1), {"(6F10.0,4I3)"});
      OrientationCard orientation;
      orientation.line = card.line;
      orientation.angles = Triple(card, 1, 10, "yaw, pitch and roll");
      orientation.angles_where = r_.Range(card, 1, 30);
      orientation.angular_velocity = GivenVelocity(card, "angular velocity");
      for (int i = 0; i < 3; ++i) {
        const int first = 61 + 3 * i;
        const int value = r_.Integer(card, first, first + 2, "ID, a rotation order");
        if (value != 0) {
          Refuse(card, first, first + 2, fmt::format("ID{} is {}", i + 1, value),
                 "sled's initial orientations are yaw, pitch, roll (about z, then y, then x); "
                 "leave columns 61-69 blank (ATB's default order)");
          break;
        }
      }
      const int segment = static_cast<int>(s) + 1;
      const bool reference =
          std::find(references.begin(), references.end(), segment) != references.end();
      ReadOrientationReference(card, segment, reference, orientation);
      if (!reference && orientation.angular_velocity != Vec3{}) {
        Refuse(card, 31, 60,
               fmt::format("an initial angular velocity of segment {}, which hangs from joint {}",
                           segment, s),
               "sled solves a jointed segment's joint rates from an angular velocity in the "
               "ground frame, and how ATB combines this one with the reference segment's "
               "(COMPUTE_INIT_ANG_VEL) is not in the reference; leave columns 31-60 blank and "
               "give `initial BODY.SEGMENT { angular_velocity = ... }` in the scenario");
        orientation.angular_velocity = Vec3{};
      }
      deck_.initial_orientations.push_back(orientation);
    }
    if (i1 == 15 && !r_.truncated()) ReadEquilibriumCards(*this, g1);
  }

  // G.3.a ID4 (columns 70-72), the frame the yaw, pitch and roll turn from (INPUT_ORIENT,
  // DRCIJK): 0 or the ground's number the ground; a segment before this one or a vehicle its
  // axes; minus the proximal segment the joint's axes. A reference segment's is refused (sled
  // turns it from the ground).
  void ReadOrientationReference(const Card& card, int segment, bool reference,
                                OrientationCard& orientation) {
    const int id4 = r_.Integer(card, 70, 72, "ID4, the orientation's reference");
    orientation.reference_where = r_.Range(card, 70, 72);
    const int segments = static_cast<int>(deck_.segments.size());
    const int vehicles = static_cast<int>(deck_.vehicles.size());
    const int ground = segments + vehicles + bags_ + 1;
    if (id4 == 0 || id4 == ground) return;
    if (reference) {
      Refuse(card, 70, 72, fmt::format("ID4 is {} for reference segment {}", id4, segment),
             "sled turns a reference segment from the ground; give its yaw, pitch and roll in "
             "the ground's axes with ID4 = 0");
      return;
    }
    const auto joint = static_cast<std::size_t>(segment) - 2;
    if (joint >= deck_.joints.size()) return;  // B.1's NJNT was wrong: reported there
    if (id4 < 0) {
      const int proximal = deck_.joints[joint].parent;
      if (-id4 != proximal) {
        Invalid(
            card, 70, 72,
            fmt::format("ID4 is {}, but segment {} hangs from segment {}", id4, segment, proximal),
            fmt::format("a negative ID4 is minus the proximal segment, {} (ATB stops "
                        "otherwise, STOP 25)",
                        -proximal));
        return;
      }
      orientation.reference = OrientationCard::Reference::kJointAxes;
      return;
    }
    if (id4 >= segment && id4 <= segments) {
      Invalid(card, 70, 72, fmt::format("ID4 is {}, not a segment before segment {}", id4, segment),
              "the reference is a segment with a lower number or a vehicle (ATB stops otherwise, "
              "STOP 24)");
      return;
    }
    if (id4 > segments + vehicles) {
      Invalid(card, 70, 72, fmt::format("ID4 is {}, which is no segment or vehicle", id4),
              fmt::format("body segments are 1 to {}, vehicles {} to {}, the ground 0 or {}",
                          segments, segments + 1, segments + vehicles, ground));
      return;
    }
    orientation.reference = OrientationCard::Reference::kFrame;
    orientation.frame = id4;
  }

  // A G.2 velocity or G.3.a angular velocity (columns 31-60), zero when I3 = 0 makes ATB ignore it.
  Vec3 GivenVelocity(const Card& card, std::string_view what) {
    const Vec3 velocity = Triple(card, 31, 10, fmt::format("the {}", what));
    if (!deck_.velocities_from_vehicle || velocity == Vec3{}) return velocity;
    Ignored(card, 31, 60,
            fmt::format("with I3 = 0 on G.1.a, ATB gives the segment the primary vehicle's {} "
                        "and ignores this one",
                        what),
            "set I3 = 1 on G.1.a (columns 47-50) to use the G.2 and G.3 velocities, or leave "
            "these columns blank");
    return Vec3{};
  }

  int bags_;  // D.1.a NBAG: the airbags' numbers come between the vehicles and the ground
};

}  // namespace

void ReadInitialConditions(DeckFields& fields, int bags) { InitialReader(fields, bags).Read(); }

}  // namespace sled::lang::legacy
