// What the belts of a Model carry in a Data (runtime/model/data.h holds one BeltState): the
// junctions where webbing passes between spans and their stick or slip, the webbing each span
// holds, the loading histories, and the results of the last evaluation. Sized once by SetUpBelts.
//
// Nothing here changes between two events except the last evaluation's results: a junction's
// mode (stick, slip one way or the other), the webbing it held when it last stuck, the body
// point it sticks to, and each span's loading history change only where an event of
// runtime/restraint/belt_events.h is located, so every evaluation is a function of the state.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "runtime/forces/force_deflection.h"
#include "runtime/restraint/belt_wrap.h"

namespace sled::runtime {

// How webbing passes a junction.
enum class JunctionMode : std::int8_t {
  kStick = 0,           // held, or carried along by the body it lies on
  kSlipIntoSecond = 1,  // slipping from the first span into the second (the second is tighter)
  kSlipIntoFirst = -1,  // slipping from the second span into the first
  kFree = 2,            // no friction: both sides carry one tension, always
};

struct BeltState {
  // --- Junctions, fixed when the Data is made: two spans that exchange webbing, over a wrapped
  // segment (point: the path point) or through a harness tie point (point: -1).
  std::vector<std::int32_t> junction_first;   // the span on the `from` side
  std::vector<std::int32_t> junction_second;  // the span on the `to` side
  std::vector<std::int32_t> junction_point;   // wrapped path point, or -1
  std::vector<std::int32_t> junction_tie;     // tie point, or -1
  std::vector<double> junction_friction;

  // --- Per junction, changed only at events.
  std::vector<JunctionMode> mode;
  // The webbing passed from the first span into the second (unstretched) at the last event: a
  // stuck junction's transfer, less what the body carried since; the slip solver's start.
  std::vector<double> held_transfer;
  // At a wrap that sticks: the body point under the webbing's middle at the last event (segment
  // frame), the webbing's stretch there (1 + mean strain of the two sides), and whether the
  // webbing touched the body then (only then does the body carry it).
  std::vector<Eigen::Vector3d> anchor;
  std::vector<double> carry_stretch;
  std::vector<std::uint8_t> carries;

  // --- Per junction, the last evaluation: the capstan ratio exp(mu theta), the webbing passed
  // from the first span into the second since the start [m], and (from the last event
  // evaluation, belt_events.h) the rate at which the webbing slips over the body or through the
  // ring, from the first span into the second [m/s]: the transfer's rate less what the body
  // carries.
  std::vector<double> junction_ratio;
  std::vector<double> carried_arc;  // a sticking wrap: how far its body carried the webbing [m]
  std::vector<double> transfer;
  std::vector<double> slip_rate;

  // --- Per span.
  std::vector<std::int32_t> span_belt;   // fixed: the belt the span belongs to
  std::vector<double> base_length;       // fixed: unstretched webbing at the start [m]
  std::vector<LoadingHistory> history;   // of its strain; changed only at events
  std::vector<std::uint8_t> hysteresis;  // fixed: the webbing function keeps a history
  std::vector<double> rest_length;       // last evaluation: unstretched webbing [m]
  std::vector<double> length;            // last evaluation: geometric length [m]
  std::vector<double> tension;           // last evaluation [N]
  std::vector<double> strain_rate;       // last event evaluation [1/s]
  std::vector<Eigen::Vector3d> start;    // last evaluation: world ends of the straight part
  std::vector<Eigen::Vector3d> end;

  // --- Per belt, fixed: the webbing's stiffness per unit strain where it starts to pull [N],
  // which extends its tension below zero strain for the slip solver (belt_slip.h).
  std::vector<double> slack_stiffness;

  // --- Per path point. Wraps: the last evaluation's geometry, and the side of the body the
  // webbing lies on (fixed in the segment frame at the start: it decides which way round the
  // body the webbing goes).
  std::vector<Eigen::Vector3d> entry;
  std::vector<Eigen::Vector3d> exit;
  std::vector<double> arc;
  std::vector<double> turning;
  std::vector<std::uint8_t> contact;
  std::vector<double> reach;  // how far the body reaches across the straight line (> 0: contact)
  std::vector<Eigen::Vector3d> middle;
  std::vector<Eigen::Vector3d> tangent;
  std::vector<Eigen::Vector3d> side;
  std::vector<Eigen::Vector3d> side_in_segment;
  std::vector<WrapSection> section;  // last evaluation: for lengths along the surface

  // --- Per belt, last evaluation: the force on its first and last anchor, in the anchor's frame.
  std::vector<Eigen::Vector3d> start_anchor_force;
  std::vector<Eigen::Vector3d> end_anchor_force;

  std::int64_t slip_iterations = 0;  // Newton iterations of the slip solver, for tests

  // Workspace of the rates' central differences (belt_events.cpp), sized once: the positions and
  // their derivative.
  std::vector<double> rate_q, rate_dq;
  std::vector<Eigen::Vector3d> rate_anchor;  // per junction: the body point under the middle
  // Per segment: 1 when the belts' geometry reads its pose (a wrapped segment, an anchor's
  // segment, or an ancestor of one), so the rates move only those.
  std::vector<std::uint8_t> rate_segments;
  // Workspace of the slip solver, sized once (belt_slip.cpp).
  std::vector<std::int32_t> solve_index;  // per junction: its unknown, or -1
  std::vector<double> solve_residual, solve_step, solve_matrix, solve_trial;

  // What changes during a run, for checkpoints (runtime/run/archive.h): the event-time state, and
  // the last evaluation's values.
  template <class Archive>
  void Serialize(Archive& a) {
    a.Field(mode);
    a.Field(held_transfer);
    a.Field(anchor);
    a.Field(carry_stretch);
    a.Field(carries);
    a.Field(junction_ratio);
    a.Field(carried_arc);
    a.Field(transfer);
    a.Field(slip_rate);
    a.Field(history);
    a.Field(rest_length);
    a.Field(length);
    a.Field(tension);
    a.Field(strain_rate);
    a.Field(start);
    a.Field(end);
    a.Field(entry);
    a.Field(exit);
    a.Field(arc);
    a.Field(turning);
    a.Field(contact);
    a.Field(reach);
    a.Field(middle);
    a.Field(tangent);
    a.Field(side);
    a.Field(start_anchor_force);
    a.Field(end_anchor_force);
    a.Field(slip_iterations);
  }
};

}  // namespace sled::runtime
