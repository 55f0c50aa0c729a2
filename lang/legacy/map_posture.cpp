// G.3.a for the segments that hang from joints: ATB gives every segment its own initial
// orientation (INPUT_ORIENT, DRCIJK), sled a jointed segment its joint's angles. The converter
// turns one into the other:
//
//   R_s = Y(ypr)                   ID4 = 0 (a blank card too: the segment starts level)
//   R_s = R_M Y(ypr)               ID4 = M, a segment before s or a vehicle
//   R_J = Y(ypr)                   ID4 = -(the proximal segment): the joint's own angles
//
// with Y(ypr) = Rz(yaw) Ry(pitch) Rx(roll) from the frame's axes to the ground's and R the
// segment's axes in the ground's. sled places the child of a joint at
// R_child = R_parent Y(axes_parent) R_J Y(axes_child)^T with R_J = Rz(precession)
// Ry(nutation) Rx(spin) (B.3.b's YPR1 and YPR2 are `axes`), so
// R_J = (R_parent Y(axes_parent))^T R_s Y(axes_child), whose z-y-x angles are the joint's
// `angles`. A segment's R is known before its children's: ATB numbers a child after its parent.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/legacy/ast_pieces.h"
#include "lang/legacy/deck_mapper.h"
#include "lang/legacy/rotations.h"

namespace sled::lang::legacy::mapping {
namespace {

bool IsIdentity(const Mat& r) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::fabs(r[i][j] - (i == j ? 1 : 0)) > 1e-12) return false;
    }
  }
  return true;
}

double Dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

std::string GivenTurn(const OrientationCard& card) {
  std::string text = fmt::format("yaw, pitch and roll ({}, {}, {}) deg", card.given[0],
                                 card.given[1], card.given[2]);
  if (card.given != card.angles) {
    text += fmt::format(" turned about axes {}, {}, {} in turn (ID1 to ID3: R = ", card.order[0],
                        card.order[1], card.order[2]);
    for (const int id : card.order) {
      const int axis = id < 0 ? -id : id;
      const char* names[] = {"x", "y", "z"};
      text += fmt::format("R{}", names[axis - 1]);
    }
    text += ")";
  }
  return text;
}

void DeckMapper::MapPostures(ast::Block& scenario) {
  const std::size_t n = deck_.segments.size();
  const OrientationCard blank;
  auto card_of = [&](std::size_t s) -> const OrientationCard& {
    return s < deck_.initial_orientations.size() ? deck_.initial_orientations[s] : blank;
  };
  std::vector<Mat> world(n, Identity());
  for (std::size_t s = 0; s < n; ++s) {
    const OrientationCard& card = card_of(s);
    if (s > deck_.joints.size()) break;               // B.1's NJNT was wrong: reported there
    if (s == 0 || deck_.joints[s - 1].parent == 0) {  // a reference segment: from the ground
      // A prescribed one (MSEG) is turned by its C card, not by G.3.a.
      const VehicleCard* prescribed = PrescribedCard(static_cast<int>(s + 1));
      world[s] = YawPitchRoll(prescribed ? prescribed->orientation : card.angles);
      continue;
    }
    const JointCard& joint = deck_.joints[s - 1];
    const auto parent = static_cast<std::size_t>(joint.parent - 1);
    if (joint.parent < 1 || parent >= s) continue;  // ATB numbers children after parents
    const Mat parent_axes = Multiply(world[parent], YawPitchRoll(joint.axes_parent));
    const Mat child_axes = YawPitchRoll(joint.axes_child);
    const Ref where{static_cast<int>(s + 1), card.angles_where, "G.3.a"};
    const bool blank_card =
        IsZero(card.angles) && card.reference == OrientationCard::Reference::kGround;
    Mat relative = Identity();
    std::string from;
    if (joint.type == JointType::kEuler && !IsZero(joint.initial_angles)) {
      if (!blank_card) {
        Report(DiagnosticKind::kDeckNotExpressible, where,
               fmt::format("card G.3.a (segment {}): an orientation of a segment whose Euler "
                           "joint {} has initial angles on B.4.b (line {})",
                           s + 1, s, joint.line),
               "give the joint's posture once: the B.4.b angles or the G.3.a orientation");
        continue;
      }
      relative = YawPitchRoll(joint.initial_angles);  // emitted from B.4.b below
    } else if (card.reference == OrientationCard::Reference::kJointAxes) {
      relative = YawPitchRoll(card.angles);
      from = "about the joint's axes (ID4 < 0)";
    } else {
      Mat frame = Identity();
      from = "from the ground";
      if (card.reference == OrientationCard::Reference::kFrame) {
        const auto m = static_cast<std::size_t>(card.frame);
        if (m <= n) {
          frame = world[m - 1];
          from = fmt::format("from segment {} (ID4)", m);
        } else {
          frame = YawPitchRoll(deck_.vehicles[m - n - 1].orientation);
          from = fmt::format("from vehicle {} (ID4)", m - n);
        }
      }
      const Mat segment = Multiply(frame, YawPitchRoll(card.angles));
      relative = Multiply(Multiply(Transpose(parent_axes), segment), child_axes);
    }
    world[s] = Multiply(Multiply(parent_axes, relative), Transpose(child_axes));
    if (joint.type == JointType::kEuler && !IsZero(joint.initial_angles)) {
      ast::Statement initial = Declaration("initial", Path(body_ + "." + joints_[s - 1]),
                                           CardComment("B.4.b", joint.line));
      Add(initial, Attribute("angles", Vector(joint.initial_angles, "deg")));
      scenario.statements.push_back(std::move(initial));
      continue;
    }
    if (IsIdentity(relative)) continue;
    // A pin turns about its joint axes' y (its `axis`): R_J = Ry(angle), the pin's one angle.
    const bool about_pin = joint.type == JointType::kPin && std::fabs(relative[1][1] - 1) < 1e-12;
    if (joint.type != JointType::kBall && joint.type != JointType::kEuler && !about_pin) {
      const bool slip = joint.type == JointType::kSlip;
      Report(DiagnosticKind::kDeckNotExpressible, where,
             fmt::format("card G.3.a (segment {}): an orientation that turns joint {}, a {} "
                         "joint, {}",
                         s + 1, s, slip ? "slip" : "pin",
                         slip ? "from its axes" : "about another axis than its pin"),
             slip ? "sled's slip joint keeps its child turned as its axes put it; give the "
                    "segment the orientation its joint's axes give it (B.3.b)"
                  : "a pin turns its child about the y axis of its joint axes only; give the "
                    "segment an orientation that pin reaches");
      continue;
    }
    Vec3 angles = ZyxDegrees(relative);
    if (about_pin) {
      angles = {AboutYDegrees(relative), 0, 0};
    }
    ast::Statement initial =
        Declaration("initial", Path(body_ + "." + joints_[s - 1]),
                    CardComment("G.3.a", card.line == 0 ? joint.line : card.line) +
                        fmt::format(": segment {}'s {} {}", s + 1, GivenTurn(card), from));
    Add(initial, Attribute("angles", Vector(angles, "deg")));
    scenario.statements.push_back(std::move(initial));
  }
  MapJointRates(scenario, world);
}

// With I3 = 1 (or 2) ATB starts every segment, jointed or not, with its G.3.a angular velocity,
// in the segment's own axes (COMPUTE_INIT_ANG_VEL: SEG%ANG_VEL is the card's, a blank card
// zero); with I3 = 0 every segment has the primary vehicle's and the cards are ignored. sled
// starts a jointed segment with its parent's angular velocity (zero joint rates) unless an
// `initial SEGMENT { angular_velocity }` in the ground's axes says otherwise, and then solves the
// joint's rates for it. So a segment whose ATB angular velocity differs from its parent's gets
// that statement: w_ground = R_segment w_card. A joint that cannot turn that way (a slip joint,
// a locked one, a pin about another axis) is refused: what ATB does with such a start is not in
// the reference.
void DeckMapper::MapJointRates(ast::Block& scenario, const std::vector<Mat>& world) {
  if (deck_.velocities_from_vehicle) return;
  const std::size_t n = std::min(world.size(), deck_.initial_orientations.size());
  std::vector<Vec3> omega(n);  // each segment's angular velocity in the ground's axes, deg/T
  for (std::size_t s = 0; s < n; ++s) {
    const OrientationCard& card = deck_.initial_orientations[s];
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 3; ++k) omega[s][i] += world[s][i][k] * card.angular_velocity[k];
    }
    if (s == 0 || s > deck_.joints.size()) continue;
    const JointCard& joint = deck_.joints[s - 1];
    if (joint.parent < 1 || static_cast<std::size_t>(joint.parent) > s) continue;
    const auto parent = static_cast<std::size_t>(joint.parent - 1);
    Vec3 relative{};
    for (std::size_t i = 0; i < 3; ++i) relative[i] = omega[s][i] - omega[parent][i];
    const double size = std::sqrt(Dot(relative, relative));
    if (size <= 1e-9 * (1 + std::sqrt(Dot(omega[s], omega[s])))) continue;
    const Ref where{static_cast<int>(s + 1), card.angles_where, "G.3.a"};
    std::string cannot;
    if (joint.type == JointType::kSlip || joint.locked) {
      cannot = joint.locked ? "a locked joint" : "a slip joint, which does not turn";
    } else if (joint.type == JointType::kPin) {
      const Mat parent_axes = Multiply(world[parent], YawPitchRoll(joint.axes_parent));
      const Vec3 axis{parent_axes[0][1], parent_axes[1][1], parent_axes[2][1]};
      const double along = Dot(relative, axis);
      if (std::fabs(std::fabs(along) - size) > 1e-9 * size) {
        cannot = "a pin, and the difference from its proximal segment's is not about its axis";
      }
    }
    if (!cannot.empty()) {
      Report(DiagnosticKind::kDeckNotExpressible, where,
             fmt::format("card G.3.a (segment {}): an angular velocity that joint {}, {}, "
                         "cannot give it",
                         s + 1, s, cannot),
             "give the segment the angular velocity of its proximal segment (as turned by the "
             "joint only about the axes it turns about)");
      continue;
    }
    ast::Statement initial =
        Declaration("initial", Path(body_ + "." + segments_[s]),
                    CardComment("G.3.a", card.line) +
                        fmt::format(": ({}, {}, {}) deg/{} in segment {}'s axes (I3 = 1), turned "
                                    "to the ground's",
                                    card.angular_velocity[0], card.angular_velocity[1],
                                    card.angular_velocity[2], T, s + 1));
    Add(initial, Attribute("angular_velocity", Vector(omega[s], "deg/" + T)));
    scenario.statements.push_back(std::move(initial));
  }
}

}  // namespace sled::lang::legacy::mapping
