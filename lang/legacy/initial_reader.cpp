// Card group G, the initial conditions: G.1.a (the velocity source I3), a G.2 card per
// reference segment (position and velocity, IREF2 and IREF4) and a G.3.a card per segment
// (orientation and angular velocity), as ATB V.3's INPUT_INITIAL_CONDITIONS, INPUT_LINEAR and
// INPUT_ORIENT read them.
#include "lang/legacy/initial_reader.h"

#include "lang/legacy/equilibrium_reader.h"
#include "lang/legacy/rotations.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
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
      RotationOrder(card, orientation);
      const int segment = static_cast<int>(s) + 1;
      const bool reference =
          std::find(references.begin(), references.end(), segment) != references.end();
      ReadOrientationReference(card, segment, reference, orientation);
      deck_.initial_orientations.push_back(orientation);
    }
    if (i1 == 15 && !r_.truncated()) ReadEquilibriumCards(*this, g1);
  }

  // G.3.a ID1 to ID3 (columns 61-69): the axes, in turn, of the three rotations that take the
  // segment from its reference frame to its own axes; ID1 = 0 is ATB's default 1, 2, 3
  // (INPUT_ORIENT). DRCYPR turns about each axis by the angle it pairs with it (yaw about z,
  // pitch about y, roll about x) and ATB keeps the result untransposed as the segment's
  // direction cosines, so 1, 2, 3 is R = Rx(roll) Ry(pitch) Rz(yaw): the yaw about the
  // reference's z first, then the pitch and the roll about its y and x. The angles are
  // rewritten as the z-y-x angles of that R, sled's yaw, pitch and roll, so every later use of
  // them (the reference segment's `orientation`, its angular velocity, the joint angles) turns
  // the segment as ATB does. ID1 < 0 (G.3.b projections) is refused.
  void RotationOrder(const Card& card, OrientationCard& orientation) {
    std::array<int, 3> order{};
    for (std::size_t i = 0; i < 3; ++i) {
      const int first = 61 + 3 * static_cast<int>(i);
      order[i] = r_.Integer(card, first, first + 2, "ID, a rotation order");
    }
    if (order[0] < 0) {
      Refuse(card, 61, 63, fmt::format("ID1 is {}: the orientation from projections", order[0]),
             "the G.3.b projection card's reader (INPUT_PROJANG) is not in the reference; give "
             "the yaw, pitch and roll with ID1 = 0 or an order of axes");
      return;
    }
    if (order[0] == 0) {
      if (order[1] != 0 || order[2] != 0) {
        Ignored(card, 61, 69, "ID2 and ID3 without ID1",
                "ATB takes the default order 1, 2, 3 whenever ID1 is 0 (INPUT_ORIENT); the "
                "other two are left out");
      }
      order = {1, 2, 3};
    } else if (const auto why = OrderProblem(order)) {
      Invalid(card, 61, 69, fmt::format("ID1 to ID3 are {}, {}, {}", order[0], order[1], order[2]),
              std::string(*why));
      return;
    }
    const std::optional<Mat> turn = OrderedYawPitchRoll(orientation.angles, order);
    if (!turn) {
      Invalid(card, 61, 69, fmt::format("ID1 to ID3 are {}, {}, {}", order[0], order[1], order[2]),
              "with a negative number DRCYPR picks the angle by the sum of the three; this sum "
              "names none");
      return;
    }
    orientation.given = orientation.angles;
    orientation.order = order;
    orientation.angles = ZyxDegrees(*turn);
  }

  // CHECK_ROTATION_ORDER's rules for an order with ID1 > 0 (ATB's STOPs 230 to 232).
  static std::optional<std::string_view> OrderProblem(const std::array<int, 3>& order) {
    for (const int id : order) {
      if (id == 0 || id > 3 || id < -3) {
        return "each of ID1 to ID3 is an axis, 1 to 3 (x, y, z), ID2 and ID3 maybe negative "
               "(ATB stops otherwise, STOP 230)";
      }
    }
    const int second = std::abs(order[1]), third = std::abs(order[2]);
    if (order[0] == second || second == third) {
      return "two rotations in a row cannot be about the same axis (ATB's STOP 231)";
    }
    if (order[0] == third && order[2] != -order[0]) {
      return "when the first and third axes are the same, the third is negative (ATB's "
             "STOP 232)";
    }
    return std::nullopt;
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
