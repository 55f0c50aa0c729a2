// Card group B: the body's segments (B.2), joints (B.3), joint springs (B.4), joint damping
// (B.5) and the per-segment convergence tests (B.6), as ATB V.3's INPUT_BCARDS and INPUT_JOINTS
// read them.
#include "lang/legacy/body_reader.h"
#include "lang/legacy/rotations.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

class BodyReader : public DeckFields {
 public:
  explicit BodyReader(DeckFields& fields) : DeckFields(fields.source(), fields.deck()) {}

  void Read() {
    const Card b1 = r_.Next("B.1", {"(2I6,8X,A20,I5)"});
    deck_.body_line = b1.line;
    const int segments = Count(b1, 1, 6, "NSEG, the number of segments", kMaxSegments);
    const int joints = Count(b1, 7, 12, "NJNT, the number of joints", kMaxSegments);
    deck_.body_title = r_.Text(b1, 21, 40);
    const int deformable = r_.Integer(b1, 41, 45, "NFBOD, the number of deformable bodies");
    if (deformable != 0) {
      Refuse(b1, 41, 45, fmt::format("NFBOD is {}: deformable bodies", deformable),
             "sled's segments are rigid; remove the deformable bodies (and their B.3.c cards)");
    }
    if (segments > 0 && joints != segments - 1) {
      Invalid(b1, 7, 12, fmt::format("NJNT is {} for {} segments", joints, segments),
              "segment J+1 hangs from joint J, so a deck has NSEG - 1 joints");
    }
    for (int i = 0; i < segments; ++i) ReadSegment(i + 1);
    for (int j = 0; j < joints && j + 1 < segments; ++j) ReadJoint(j + 1, segments);
    for (auto& joint : deck_.joints) ReadJointSprings(joint);
    for (auto& joint : deck_.joints) ReadJointDamping(joint);
    ReadConvergenceTests(segments);
  }

 private:
  // B.6: per segment, for its angular and linear velocity and acceleration, a magnitude test,
  // an absolute and a relative error. sled's integrator controls the relative error of every
  // state with one `tolerance`: the smallest relative error given becomes it (at least as strict
  // as each test), and the rest is approximated (W0504 at the first card that sets any).
  void ReadConvergenceTests(int segments) {
    bool warned = false;
    for (int i = 0; i < segments; ++i) {
      const Card b6 = r_.Next(fmt::format("B.6 (segment {})", i + 1), {"(12F6.0)"});
      bool any = false;
      for (int f = 0; f < 12; ++f) {
        const int first = 6 * f + 1;
        const double value = r_.Real(b6, first, first + 5, "an integrator convergence test");
        if (value < 0) {
          Invalid(b6, first, first + 5, fmt::format("a convergence test of {}", value),
                  "a magnitude test or an error is zero (none) or positive");
        }
        any = any || value != 0;
        if (f % 3 == 2 && value > 0 && (deck_.tolerance == 0 || value < deck_.tolerance))
          deck_.tolerance = value;
      }
      if (any && !warned) {
        warned = true;
        Approximated(b6, 1, 72,
                     "ATB tests each segment's angular and linear velocity and acceleration "
                     "against its own magnitude test, absolute and relative error; sled's "
                     "integrator controls the relative error of every state with one "
                     "`tolerance`, the smallest relative error of the B.6 cards (at least as "
                     "strict as each), and does not use the magnitude tests and absolute errors");
      }
    }
    if (deck_.tolerance > kMaxTolerance) deck_.tolerance = 0;  // sled's default is stricter
    if (deck_.tolerance != 0 && deck_.tolerance < kMinTolerance) {
      deck_.tolerance = kMinTolerance;  // as strict as double precision can meet (E0419)
    }
  }

  // The range of sled's `tolerance` (docs/language.md, integrator).
  static constexpr double kMinTolerance = 2.3e-14;
  static constexpr double kMaxTolerance = 0.1;

  void ReadSegment(int number) {
    const Card card = r_.Next(fmt::format("B.2.a (segment {})", number), {"(A4,2X,10F6.0,I4)"});
    SegmentCard segment;
    segment.line = card.line;
    segment.name = r_.Text(card, 1, 4);
    if (segment.name.empty() && card.line != 0) {
      Invalid(card, 1, 4, "the segment has no name", "give each segment a name in columns 1-4");
    }
    segment.weight = r_.Real(card, 7, 12, "WEIGHT, the segment's weight");
    segment.inertia = Triple(card, 13, 6, "PHI, the principal moments of inertia");
    segment.semi_axes = Triple(card, 31, 6, "the contact ellipsoid's semi-axes");
    segment.center = Triple(card, 49, 6, "the contact ellipsoid's centre");
    const int lpmi = r_.Integer(card, 67, 70, "LPMI, principal axes given");
    if (segment.weight < 0) {
      Invalid(card, 7, 12, fmt::format("WEIGHT is {}", segment.weight),
              "a weight is zero (a singular segment) or positive");
    }
    CheckInertia(card, segment);
    CheckSemiAxes(card, 31, segment.semi_axes, true);
    if (lpmi == 1) {
      const Card axes = r_.Next(fmt::format("B.2.b (segment {})", number), {"(12X,3F6.0)"});
      segment.has_principal_axes = true;
      segment.principal_axes = Triple(axes, 13, 6, "yaw, pitch and roll of the principal axes");
    } else if (lpmi != 0) {
      Invalid(card, 67, 70, fmt::format("LPMI is {}", lpmi),
              "LPMI is 1 when a B.2.b card follows, else 0 or blank");
    }
    deck_.segments.push_back(std::move(segment));
  }

  // PHI: with a positive weight, three positive moments that a rigid body can have (each at
  // most the sum of the other two); with zero weight (a singular segment) none is used.
  void CheckInertia(const Card& card, SegmentCard& segment) {
    const Vec3& phi = segment.inertia;
    if (phi[0] < 0 || phi[1] < 0 || phi[2] < 0) {
      Invalid(card, 13, 30,
              fmt::format("a principal moment of inertia is negative ({}, {}, {})", phi[0], phi[1],
                          phi[2]),
              "moments of inertia are positive");
      return;
    }
    if (segment.weight == 0) {
      if (phi != Vec3{}) {
        Ignored(card, 13, 30,
                "PHI of a segment of zero weight: ATB makes the segment singular, without mass "
                "or inertia",
                "a singular segment has neither mass nor inertia; leave columns 13-30 blank");
        segment.inertia = Vec3{};
      }
      return;
    }
    if (phi[0] == 0 || phi[1] == 0 || phi[2] == 0) {
      Refuse(card, 13, 30,
             fmt::format("a segment of weight {} with a zero moment of inertia", segment.weight),
             "sled's singular segment has neither mass nor inertia; give all three moments, or "
             "a zero weight");
      return;
    }
    const double sum = phi[0] + phi[1] + phi[2];
    for (std::size_t i = 0; i < 3; ++i) {
      if (phi[i] > sum - phi[i] + 1e-9 * sum) {
        Invalid(card, 13, 30,
                fmt::format("the principal moments ({}, {}, {}) break the triangle inequality: "
                            "the {} moment exceeds the sum of the other two",
                            phi[0], phi[1], phi[2], "xyz"[i]),
                "no rigid body has these moments; check the columns and the order of the axes");
        return;
      }
    }
  }

  void ReadJoint(int number, int segments) {
    const Card line1 =
        r_.Next(fmt::format("B.3.a (joint {})", number), {"(A4,2X,2I4,6F6.0,I4,2F6.0)"});
    const Card line2 = r_.Next(fmt::format("B.3.b (joint {})", number), {"(14X,9F6.0,6I2)"});
    JointCard joint;
    joint.line = line1.line;
    joint.name = r_.Text(line1, 1, 4);
    joint.parent = r_.Integer(line1, 7, 10, "JNT, the proximal segment");
    const int jtype = r_.Integer(line1, 11, 14, "JTYPE, the joint type");
    joint.jtype = jtype;
    joint.at_parent = Triple(line1, 15, 6, "the joint's location in the proximal segment");
    joint.at_child = Triple(line1, 33, 6, "the joint's location in the distal segment");
    const int ieuler = r_.Integer(line1, 51, 54, "IEULER");
    const double tension = r_.Real(line1, 55, 60, "TENS_MAX, the tension that unlocks a slip");
    const double compression =
        r_.Real(line1, 61, 66, "COMP_MAX, the compression that unlocks a slip");
    if (joint.parent < 0) {
      Refuse(line1, 7, 10, fmt::format("JNT is {}: a flexible chain", joint.parent),
             "flexible segment chains have no counterpart in sled; use ordinary joints");
    } else if (joint.parent > segments || joint.parent == number + 1) {
      r_.Report(DiagnosticKind::kDeckCountOutOfRange, line1, 7, 10,
                fmt::format("card {}, {} (JNT, the proximal segment): segment {} does not "
                            "exist or is the joint's own distal segment",
                            line1.label, r_.Where(line1, 7, 10), joint.parent),
                fmt::format("name a segment from 0 (a new reference body) to {}", segments));
      joint.parent = 0;
    }
    const bool euler = jtype == 4 || (ieuler == 0 && jtype <= -4);
    if (euler) {
      joint.type = JointType::kEuler;
      Unverified(line1, 11, 14,
                 "an Euler joint: sled maps the B.4.a flexure and torsion springs and the B.4.b "
                 "spring to its precession, nutation and spin axes in that order");
    } else if (std::abs(jtype) >= 5) {
      joint.type = JointType::kSlip;
      Unverified(line1, 11, 14,
                 "a slip joint: the slip direction is taken as sled's default axis, and its B.4 "
                 "spring, stop, damping and friction as a force against its displacement");
    } else if (jtype == 0) {
      joint.type = JointType::kBall;
    } else if (jtype == 2 || jtype == -2) {
      // ATB's unpinned lockable joint: a ball and socket in VISPR (flexure and torsion springs
      // as JTYPE 0), which UPDATE_JOINTS locks and unlocks by the size of its torque vector,
      // as sled's lock levels of a ball joint; JTYPE -2 is its locked state.
      joint.type = JointType::kBall;
      joint.lockable = true;
      joint.locked = jtype < 0;
    } else if (jtype == 1 || jtype == -1) {
      // ATB's pinned joint: it turns about HB, the y axis of its joint axes in the proximal
      // segment (OUTPUT_JOINTS, UPDATE_JOINTS, INPUT_ROBOTICS); JTYPE -1 is its locked state.
      joint.type = JointType::kPin;
      joint.locked = jtype < 0;
    } else {
      Refuse(line1, 11, 14,
             fmt::format("JTYPE {}: ATB's globographic joint, a lockable ball whose stop VISPR "
                         "computes in GLOBAL, a routine the reference does not have",
                         jtype),
             "the stop's shape (F.4.b's torque-deflection and Herron functions) is not known; "
             "give JTYPE 2 (-2 locked), the same joint without the globographic stop, and a "
             "B.4.a joint-stop angle if it needs a stop");
    }
    SlipLock(joint, line1, jtype, ieuler, tension, compression);
    joint.axes_parent = Triple(line2, 15, 6, "YPR1, the joint axes in the proximal segment");
    joint.axes_child = Triple(line2, 33, 6, "YPR2, the joint axes in the distal segment");
    const Vec3 ypr3 = Triple(line2, 51, 6, "YPR3, the Euler joint's centre of symmetry");
    if (ypr3 != Vec3{} && joint.type == JointType::kEuler) {
      Refuse(line2, 51, 68,
             "YPR3, the centre of symmetry of an Euler joint (ATB's CNTR_SYM: its angles and "
             "springs are measured from it), is not zero",
             "sled's Euler joint springs act from zero angles; turn the joint's axes instead");
    } else if (ypr3 != Vec3{}) {
      Ignored(line2, 51, 68, "YPR3 of a joint that is not an Euler joint",
              "ATB reads it for Euler joints only (OUTPUT_JOINTS); it is left out");
    }
    RotationOrder(joint.axes_parent, line2, 69, "YPR1");
    RotationOrder(joint.axes_child, line2, 75, "YPR2");
    deck_.joints.push_back(std::move(joint));
  }

  // B.3.b IDYPR: the rotation order of YPR1 (columns 69-74) or YPR2 (75-80), three axis numbers
  // from `first`; 0 first (as blank) is ATB's 3, 2, 1, yaw, pitch and roll as sled reads them.
  // Another order is turned into sled's yaw, pitch and roll of the same axes (DRCYPR's matrix).
  void RotationOrder(Vec3& angles, const Card& card, int first, std::string_view of) {
    std::array<int, 3> order{};
    for (std::size_t i = 0; i < 3; ++i) {
      const int at = first + 2 * static_cast<int>(i);
      order[i] = r_.Integer(card, at, at + 1, "IDYPR, a rotation order");
    }
    if (order[0] == 0) {
      if (order[1] != 0 || order[2] != 0) {
        Ignored(card, first, first + 5, fmt::format("IDYPR of {} without its first axis", of),
                "ATB takes the default order 3, 2, 1 whenever the first number is 0 "
                "(INPUT_JOINTS); the other two are left out");
      }
      return;
    }
    const std::optional<Mat> turn = OrderedYawPitchRoll(angles, order);
    if (!turn) {
      Invalid(card, first, first + 5,
              fmt::format("IDYPR of {} is {}, {}, {}", of, order[0], order[1], order[2]),
              "each number is an axis, 1 to 3 (x, y, z), negative as ATB's DRCYPR allows; ATB "
              "stops above 3 (STOP 101)");
      return;
    }
    angles = ZyxDegrees(*turn);
  }

  // B.3.a JTYPE, IEULER, TENS_MAX and COMP_MAX of a slip joint. ATB's UPDATE_JOINTS holds a
  // joint of negative JTYPE locked (it unlocks one by turning the sign, when its torque passes
  // B.5.a's VISC(4): never when that is 0, and B.5.a's levels of a slip joint are refused), and a
  // slip joint whose IEULER is negative locked until the force along its axis leaves [TENS_MAX,
  // COMP_MAX] (never, when both are 0), then lets it slide for good; it tests TENS_MAX and
  // COMP_MAX for no other joint.
  void SlipLock(JointCard& joint, const Card& card, int jtype, int ieuler, double tension,
                double compression) {
    const bool limits = tension != 0 || compression != 0;
    if (joint.type == JointType::kSlip && jtype < 0) {
      joint.locked = true;
      if (ieuler < 0 && limits) {
        Refuse(card, 55, 66,
               "TENS_MAX and COMP_MAX of a slip joint also locked by its negative JTYPE",
               "ATB releases the two locks separately; sled's joint has one: give the joint a "
               "positive JTYPE, or set TENS_MAX and COMP_MAX to 0");
      }
      return;
    }
    if (joint.type != JointType::kSlip || ieuler >= 0) {
      if (limits) {
        Ignored(card, 55, 66,
                fmt::format("TENS_MAX {} and COMP_MAX {} of a joint that is not a locked slip "
                            "joint",
                            tension, compression),
                "ATB tests them only for a slip joint locked by a negative IEULER "
                "(UPDATE_JOINTS); they are left out");
      }
      return;
    }
    joint.locked = true;
    if (!limits) return;
    if (compression > 0 && tension == -compression) {
      joint.unlock_above = compression;
      return;
    }
    Refuse(card, 55, 66,
           fmt::format("a slip joint unlocked by an axial force outside [{}, {}] (TENS_MAX, "
                       "COMP_MAX), a band not symmetric about zero",
                       tension, compression),
           "sled's locked slip joint slides once the size of its axial force passes one "
           "`unlock_above`; give TENS_MAX = -COMP_MAX, or edit the converted joint");
  }

  JointSpring Spring(const Card& card, int first) {
    JointSpring spring;
    const double c1 = r_.Real(card, first, first + 5, "the linear spring coefficient");
    spring.quadratic = r_.Real(card, first + 6, first + 11, "the quadratic spring coefficient");
    spring.cubic = r_.Real(card, first + 12, first + 17, "the cubic spring coefficient");
    spring.energy_loss =
        r_.Real(card, first + 18, first + 23, "the energy-dissipation coefficient");
    spring.stop = r_.Real(card, first + 24, first + 35, "the joint-stop angle");
    if (c1 < 0) {
      // A negative first coefficient names joint function |n|; the rest of the spring is unused.
      spring.function =
          Ref{static_cast<int>(std::fabs(c1)), r_.Range(card, first, first + 5), card.label};
      spring.quadratic = spring.cubic = spring.energy_loss = spring.stop = 0;
    } else {
      spring.linear = c1;
    }
    const double lowest = spring.linear != 0      ? spring.linear
                          : spring.quadratic != 0 ? spring.quadratic
                                                  : spring.cubic;
    if (spring.function.number == 0 && lowest < 0) {
      Invalid(card, first, first + 17,
              fmt::format("the spring's lowest coefficient is negative ({})", lowest),
              "a joint spring resists its angle: its lowest non-zero coefficient is positive");
    }
    if (spring.energy_loss < 0 || spring.energy_loss > 1) {
      Invalid(card, first + 18, first + 23,
              fmt::format("the energy-dissipation coefficient is {}", spring.energy_loss),
              "it is a fraction from 0 to 1");
    }
    if (spring.stop < 0 || spring.stop > 180) {
      Invalid(card, first + 24, first + 35,
              fmt::format("the joint-stop angle is {} deg", spring.stop),
              "a stop angle is from 0 (none) to 180 degrees");
    }
    return spring;
  }

  static bool HasAnyTerm(const JointSpring& spring) {
    return spring.function.number != 0 || spring.linear != 0 || spring.quadratic != 0 ||
           spring.cubic != 0 || spring.energy_loss != 0 || spring.stop != 0;
  }

  void ReadJointSprings(JointCard& joint) {
    const std::size_t j = static_cast<std::size_t>(&joint - deck_.joints.data()) + 1;
    const Card card = r_.Next(fmt::format("B.4.a (joint {})", j), {"(2(4F6.0,F12.0))"});
    joint.flexure = Spring(card, 1);
    joint.twist = Spring(card, 37);
    if (joint.type == JointType::kEuler && joint.twist.stop != 0) {
      Refuse(card, 61, 72,
             fmt::format("a torsion stop angle ({} deg) of an Euler joint", joint.twist.stop),
             "sled's Euler joint has one `stop`, from the B.4.a flexure stop; leave columns "
             "61-72 blank");
    }
    if (joint.type == JointType::kPin && HasAnyTerm(joint.twist)) {
      Ignored(card, 37, 72, "a torsion spring of a pin joint",
              "a pin keeps the joint's z axes turning about its y axis only, so ATB's torsion "
              "angle stays 0 and the spring never acts; it is left out");
    }
    if (joint.type == JointType::kSlip && HasAnyTerm(joint.twist)) {
      Refuse(card, 37, 72, "a torsion spring of a slip joint",
             "sled's slip joint has one characteristic, `flexure` (B.4.a columns 1-36); leave "
             "columns 37-72 blank");
    }
    if (joint.type == JointType::kEuler) {
      const Card spin = r_.Next(fmt::format("B.4.b (joint {})", j), {"(2(4F6.0,F12.0))", 8});
      joint.spin = Spring(spin, 1);
      joint.initial_angles = Triple(spin, 37, 6, "ANG, the initial joint angles");
      if (joint.spin.stop != 0) {
        Refuse(spin, 25, 36, fmt::format("a spin stop angle ({} deg)", joint.spin.stop),
               "sled's Euler joint has one `stop`, from the B.4.a flexure stop; leave columns "
               "25-36 blank");
      }
    }
  }

  // B.5.a 19-30 and 49-54: the torque that unlocks a locked joint, and the torque and the
  // angular velocity below which an unlocked one locks (ATB's printout: "Max Torque for a Locked
  // Joint", "Min Torque for Unlocked Joint", "Min. Ang. Velocity for Unlocked Joint"). ATB's
  // UPDATE_JOINTS tests them for joints of JTYPE other than 0 and 4: a pin's torque about its
  // axis, a JTYPE 2 ball's torque vector's size, against the first (while locked) and the second
  // (while unlocked; the velocity only without the second), as sled's `unlock_above` and
  // `lock_below` do. Euler joints are tested
  // in UPDATE_EULER_JOINTS, which the reference lacks.
  void LockLevels(JointCard& joint, const Card& card, double unlock) {
    const double lock = r_.Real(card, 25, 30, "the torque below which the joint locks");
    const double rate = r_.Real(card, 49, 54, "the angular velocity below which it locks");
    if (unlock == 0 && lock == 0 && rate == 0) return;
    const std::string what =
        fmt::format("lock levels (unlock above {}, lock below {} or below {} rad/{})", unlock, lock,
                    rate, deck_.units.time);
    switch (joint.type) {
      case JointType::kBall:
        if (joint.lockable) {
          TorqueLockLevels(joint, card, unlock, lock, rate);
          return;
        }
        Ignored(card, 19, 54, what + " of a ball joint (JTYPE 0)",
                "ATB's UPDATE_JOINTS never locks or unlocks a joint of JTYPE 0; they are left out "
                "(JTYPE 2 is the ball joint it locks)");
        return;
      case JointType::kPin:
        TorqueLockLevels(joint, card, unlock, lock, rate);
        return;
      case JointType::kEuler:
        Refuse(card, 19, 54, what + " of an Euler joint",
               "ATB locks an Euler joint's axes in UPDATE_EULER_JOINTS, which the reference does "
               "not have; leave the fields 0, or give the converted joint `locked`, `lock_below` "
               "and `unlock_above` by hand");
        return;
      default:
        Refuse(card, 19, 54, what + " of a slip joint",
               "ATB compares a slip joint's constraint torque with these levels, sled a slip "
               "joint's axial force; leave the fields 0, or give the converted joint "
               "`lock_below` and `unlock_above` by hand");
        return;
    }
  }

  // A pin's torque about its axis, a lockable ball's (JTYPE 2) torque vector's size.
  void TorqueLockLevels(JointCard& joint, const Card& card, double unlock, double lock,
                        double rate) {
    if (unlock < 0 || lock < 0 || rate < 0) {
      Invalid(card, 19, 54,
              fmt::format("a negative lock level (unlock above {}, lock below {}, rate {})", unlock,
                          lock, rate),
              "ATB compares them with a torque's size and an angular velocity: give them 0 "
              "(none) or positive");
      return;
    }
    if (lock == 0 && rate != 0) {
      Refuse(card, 49, 54,
             fmt::format("a joint that locks below an angular velocity of {} rad/{}", rate,
                         deck_.units.time),
             "sled locks a joint when its torque falls below `lock_below` (B.5.a columns "
             "25-30), not by its speed; leave the field 0");
      return;
    }
    if (lock != 0 && rate != 0) {
      Ignored(card, 49, 54, "the angular velocity below which the joint locks",
              "ATB tests it only when the torque level (columns 25-30) is 0 (UPDATE_JOINTS); it "
              "is left out");
    }
    if (unlock != 0 && lock > unlock) {
      Refuse(card, 19, 30,
             fmt::format("a joint that locks below {} but unlocks above {}", lock, unlock),
             "sled's `lock_below` is at most `unlock_above`, else the joint would lock and "
             "unlock at once");
      return;
    }
    joint.unlock_above = unlock;
    joint.lock_below = lock;
  }

  // B.5.a (B.5.b and B.5.c for the second and third axes of an Euler joint, as INPUT_JOINTS
  // reads VISC(., 3J-2..3J)): viscous and Coulomb terms, the rate of full Coulomb friction
  // (VISC(3), which ATB requires above zero for every joint with a proximal segment: STOP 294),
  // torque bounds and restitution. sled's `viscous` and `coulomb` act alike on every axis, so an
  // Euler joint converts when its three cards agree.
  void ReadJointDamping(JointCard& joint) {
    const std::size_t j = static_cast<std::size_t>(&joint - deck_.joints.data()) + 1;
    const int cards = joint.type == JointType::kEuler ? 3 : 1;
    for (int k = 0; k < cards; ++k) {
      const Card card = r_.Next(fmt::format("B.5.{} (joint {})", static_cast<char>('a' + k), j),
                                {"(5F6.0,18X,2F6.0)"});
      const double viscous = r_.Real(card, 1, 6, "the viscous coefficient");
      const double coulomb = r_.Real(card, 7, 12, "the Coulomb friction torque");
      const double full = r_.Real(card, 13, 18, "the angular velocity of full Coulomb friction");
      const double unlock = r_.Real(card, 19, 24, "the torque that unlocks a locked joint");
      if (k == 0) joint.unlock_level = unlock;
      LockLevels(joint, card, unlock);
      const double restitution = r_.Real(card, 55, 60, "the coefficient of restitution");
      if (joint.parent != 0 && full <= 0 && card.line != 0) {
        Invalid(card, 13, 18,
                fmt::format("the angular velocity of full Coulomb friction is {}", full),
                fmt::format("ATB requires it above zero for every joint (STOP 294), in deg/{} "
                            "(even without Coulomb friction)",
                            deck_.units.time));
      } else if (coulomb != 0 && full > 0 && (k == 0 || full != joint.coulomb_rate)) {
        // sled's ramp does not depend on the rate, so an axis whose rate differs from the first
        // axis's converts to the same `coulomb`, approximated alike.
        Approximated(
            card, 7, 18,
            fmt::format("Coulomb friction of {} {}*{} reaching its full torque at {} "
                        "deg/{} (ATB's ramp; its law is not in the reference); sled's "
                        "`coulomb` rises as tanh(rate / 0.01 rad/s): 76 % of the torque "
                        "at 0.573 deg/s, 99.9 % at 2.2 deg/s, whatever the deck's rate",
                        coulomb, deck_.units.force, deck_.units.length, full, deck_.units.time));
      }
      if (viscous < 0) {
        Invalid(card, 1, 6, fmt::format("the viscous coefficient is {}", viscous),
                "a viscous coefficient is zero or positive: it resists the motion");
      }
      if (coulomb < 0) {
        Invalid(card, 7, 12, fmt::format("the Coulomb friction torque is {}", coulomb),
                "a friction torque is zero or positive: it resists the motion");
      }
      if (restitution < 0 || restitution > 1) {
        Invalid(card, 55, 60, fmt::format("the coefficient of restitution is {}", restitution),
                "a coefficient of restitution is from 0 to 1");
      }
      if (k == 0) {
        joint.viscous = viscous;
        joint.coulomb = coulomb;
        joint.restitution = restitution;
      } else if (viscous != joint.viscous || coulomb != joint.coulomb ||
                 restitution != joint.restitution) {
        Refuse(card, 1, 60, "damping of this Euler joint axis unlike the first axis's (B.5.a)",
               "sled's `viscous`, `coulomb` and `restitution` act alike on the three axes of an "
               "Euler joint; give B.5.b and B.5.c the values of B.5.a");
      }
      if (k == 0) joint.coulomb_rate = full;
    }
  }
};

}  // namespace

void ReadBody(DeckFields& fields) { BodyReader(fields).Read(); }

}  // namespace sled::lang::legacy
