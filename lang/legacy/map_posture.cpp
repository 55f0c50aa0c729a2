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

}  // namespace

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
                        fmt::format(": segment {}'s yaw, pitch and roll ({}, {}, {}) deg {}", s + 1,
                                    card.angles[0], card.angles[1], card.angles[2], from));
    Add(initial, Attribute("angles", Vector(angles, "deg")));
    scenario.statements.push_back(std::move(initial));
  }
}

}  // namespace sled::lang::legacy::mapping
