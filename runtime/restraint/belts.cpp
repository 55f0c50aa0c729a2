#include "runtime/restraint/belts.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"
#include "runtime/forces/table_range.h"
#include "runtime/restraint/belt_events.h"
#include "runtime/restraint/belt_slip.h"
#include "runtime/restraint/belt_wrap.h"

namespace sled::runtime {
namespace {

constexpr int kMaxWrapSweeps = 32;
constexpr double kWrapTolerance = 1e-12;  // [m] change of a tangent point between sweeps

std::size_t Index(std::int32_t value) { return static_cast<std::size_t>(value); }

Mat3 FrameRotation(const Data& data, const FrameRef& frame) {
  switch (frame.kind) {
    case FrameRef::Kind::kSegment:
      return data.rotation[Index(frame.index)];
    case FrameRef::Kind::kVehicle:
      return data.vehicle[Index(frame.index)].rotation;
    case FrameRef::Kind::kGround:
      break;
  }
  return Mat3::Identity();
}

WrapSurface SurfaceOf(const BeltTable& table, const Data& data, std::size_t point) {
  const auto s = Index(table.point_frame[point].index);
  return {data.position[s] + data.rotation[s] * table.point_position[point],
          data.rotation[s] * table.point_axes[point], table.point_semi_axes[point]};
}

// Where the webbing lies along belt b: anchors where they are, wraps by Gauss-Seidel sweeps
// (each wrap between its neighbours' current tangent points, starting from the body's centre)
// until the tangent points settle; then each span's ends and length (its straight part plus half
// the arc at each wrapped end).
void BeltGeometry(const Model& model, Data& data, std::size_t b) {
  const BeltTable& table = model.belts;
  BeltState& state = data.belts;
  const auto first = Index(table.first_point[b]);
  const auto count = Index(table.point_count[b]);
  std::size_t wraps = 0;
  for (std::size_t k = first; k < first + count; ++k) {
    if (table.point_wraps[k]) {
      ++wraps;
      const Vec3 start = SurfaceOf(table, data, k).centre;
      state.entry[k] = state.exit[k] = state.middle[k] = start;
      state.arc[k] = state.turning[k] = 0.0;
      state.contact[k] = 0;
      state.reach[k] = 0.0;
      state.section[k] = WrapSection{};
    } else {
      const Vec3 anchor =
          PointInFrame(data, table.point_frame[k], table.point_position[k]).position;
      state.entry[k] = state.exit[k] = state.middle[k] = anchor;
    }
  }
  const int sweeps = wraps <= 1 ? 1 : kMaxWrapSweeps;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    double change = 0.0;
    for (std::size_t k = first + 1; k + 1 < first + count; ++k) {
      if (!table.point_wraps[k]) continue;
      const auto s = Index(table.point_frame[k].index);
      const Wrap wrap = WrapOver(SurfaceOf(table, data, k), state.exit[k - 1], state.entry[k + 1],
                                 data.rotation[s] * state.side_in_segment[k], false);
      change = std::max(
          {change, (wrap.entry - state.entry[k]).norm(), (wrap.exit - state.exit[k]).norm()});
      state.entry[k] = wrap.entry;
      state.exit[k] = wrap.exit;
      state.turning[k] = wrap.turning;
      state.contact[k] = wrap.contact ? 1 : 0;
      state.reach[k] = wrap.reach;
      state.middle[k] = wrap.middle;
      state.tangent[k] = wrap.tangent;
      state.side[k] = wrap.side;
      state.section[k] = wrap.section;
    }
    if (change <= kWrapTolerance) break;
  }
  // The arcs of the last sweep's wraps (they do not enter the sweeps).
  for (std::size_t k = first + 1; k + 1 < first + count; ++k) {
    if (table.point_wraps[k]) state.arc[k] = WrapArc(state.section[k]);
  }
  const auto first_span = Index(table.first_span(b));
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const std::size_t span = first_span + i, k = first + i;
    state.start[span] = state.exit[k];
    state.end[span] = state.entry[k + 1];
    state.length[span] =
        (state.end[span] - state.start[span]).norm() + 0.5 * (state.arc[k] + state.arc[k + 1]);
  }
}

// The span next to an anchor, and whether the anchor is at the span's start.
std::pair<std::size_t, bool> SpanAtAnchor(const BeltTable& table, std::size_t point) {
  std::size_t b = 0;
  while (b + 1 < table.size() && Index(table.first_point[b + 1]) <= point) ++b;
  const bool at_start = point == Index(table.first_point[b]);
  const auto span = Index(table.first_span(b)) + (at_start ? 0 : Index(table.span_count(b)) - 1);
  return {span, at_start};
}

// The angle the webbing turns passing through a tie point from one span into the other.
double TieTurning(const Model& model, const BeltState& state, std::size_t tie) {
  const auto [span_in, in_at_start] =
      SpanAtAnchor(model.belts, Index(model.belts.tie_points[tie][0]));
  const auto [span_out, out_at_start] =
      SpanAtAnchor(model.belts, Index(model.belts.tie_points[tie][1]));
  const Vec3 along_in = state.end[span_in] - state.start[span_in];
  const Vec3 along_out = state.end[span_out] - state.start[span_out];
  if (along_in.norm() <= 0 || along_out.norm() <= 0) return 0.0;
  // Arriving toward the tie point along the first span, leaving away from it along the second.
  const Vec3 in = (in_at_start ? -along_in : along_in).normalized();
  const Vec3 out = (out_at_start ? along_out : -along_out).normalized();
  return std::acos(std::clamp(in.dot(out), -1.0, 1.0));
}

// The webbing's stiffness per unit strain where it starts to pull: the slope at zero strain, or
// where the function first rises; the slip solver extends the tension below zero strain with it.
double SlackStiffness(const FunctionTable& functions, std::int32_t function) {
  const double slope = FunctionSlope(functions, function, 0.0);
  if (slope > 0) return slope;
  for (int k = 1; k <= 1000; ++k) {
    const double strain = 1e-3 * k;
    const double force = EvaluateFunction(functions, function, strain);
    if (force > 0) return force / strain;
  }
  return 1.0;  // a webbing that never pulls: any positive value keeps the solver regular
}

}  // namespace

double StrainAtTension(const FunctionTable& functions, std::int32_t function, double tension) {
  if (!(tension > 0)) return 0.0;
  // The first crossing within a strain of 1: found to 1e-3 by a scan, then bisected.
  constexpr int kScan = 1000;
  for (int k = 1; k <= kScan; ++k) {
    double high = static_cast<double>(k) / kScan;
    if (EvaluateFunction(functions, function, high) < tension) continue;
    double low = static_cast<double>(k - 1) / kScan;
    for (int i = 0; i < 100 && high - low > 1e-15; ++i) {
      const double mid = 0.5 * (low + high);
      (EvaluateFunction(functions, function, mid) >= tension ? high : low) = mid;
    }
    return high;
  }
  return -1.0;
}

void WatchBeltTables(const Model& model, Data& data) {
  const BeltTable& table = model.belts;
  BeltState& state = data.belts;
  for (std::size_t span = 0; span < state.rest_length.size(); ++span) {
    const double strain = state.length[span] / state.rest_length[span] - 1.0;
    const std::size_t belt = Index(state.span_belt[span]);
    // Taut webbing past its table's rows runs on the extrapolation (runtime/forces/table_range.h).
    if (strain > 0) {
      RecordTableArgument(model.functions, table.function[belt], data.time, strain,
                          data.table_watch.belt[belt]);
    }
  }
}

double CarriedLength(const Model& model, const Data& data, std::size_t j, const Vec3& anchor) {
  const BeltState& state = data.belts;
  const std::int32_t point = state.junction_point[j];
  if (point < 0) return 0.0;
  const auto k = Index(point);
  const auto s = Index(model.belts.point_frame[k].index);
  return ArcFromMiddle(state.section[k], data.position[s] + data.rotation[s] * anchor);
}

void EvaluateBelts(const Model& model, Data& data) {
  EvaluateBeltGeometry(model, data);
  ResolveSlip(model, data.belts);
}

void EvaluateBeltGeometry(const Model& model, Data& data) {
  const BeltTable& table = model.belts;
  BeltState& state = data.belts;
  for (std::size_t b = 0; b < table.size(); ++b) BeltGeometry(model, data, b);
  for (std::size_t j = 0; j < state.junction_first.size(); ++j) {
    const std::int32_t point = state.junction_point[j];
    const double turning = point >= 0 ? state.turning[Index(point)]
                                      : TieTurning(model, state, Index(state.junction_tie[j]));
    state.junction_ratio[j] = std::exp(state.junction_friction[j] * turning);
    // How far the body under a sticking wrap has carried the webbing along its surface since
    // the junction stuck (the slip solver turns it into unstretched webbing).
    const bool carried = state.mode[j] == JunctionMode::kStick && point >= 0 && state.carries[j];
    state.carried_arc[j] = carried ? CarriedLength(model, data, j, state.anchor[j]) : 0.0;
  }
}

void AnchorJunction(const Model& model, Data& data, std::size_t j) {
  BeltState& state = data.belts;
  const std::int32_t point = state.junction_point[j];
  if (point < 0) return;
  const auto k = Index(point);
  const auto s = Index(model.belts.point_frame[k].index);
  const auto a = Index(state.junction_first[j]), c = Index(state.junction_second[j]);
  state.anchor[j] = data.rotation[s].transpose() * (state.middle[k] - data.position[s]);
  state.carry_stretch[j] = std::max(
      0.5 * (state.length[a] / state.rest_length[a] + state.length[c] / state.rest_length[c]),
      1e-3);
  state.carries[j] = state.contact[k];
}

void SetUpBelts(const Model& model, Data& data) {
  const BeltTable& table = model.belts;
  BeltState& state = data.belts;
  const std::size_t spans = table.nspan(), points = table.npoint();
  state = BeltState{};
  state.span_belt.resize(spans);
  state.base_length.assign(spans, 0.0);
  state.rest_length.assign(spans, 0.0);
  state.history.assign(spans, LoadingHistory{});
  state.hysteresis.assign(spans, 0);
  state.length.assign(spans, 0.0);
  state.tension.assign(spans, 0.0);
  state.strain_rate.assign(spans, 0.0);
  state.start.assign(spans, Vec3::Zero());
  state.end.assign(spans, Vec3::Zero());
  for (auto* v : {&state.entry, &state.exit, &state.middle, &state.tangent, &state.side,
                  &state.side_in_segment}) {
    v->assign(points, Vec3::Zero());
  }
  state.section.assign(points, WrapSection{});
  state.arc.assign(points, 0.0);
  state.turning.assign(points, 0.0);
  state.reach.assign(points, 0.0);
  state.contact.assign(points, 0);
  state.start_anchor_force.assign(table.size(), Vec3::Zero());
  state.end_anchor_force.assign(table.size(), Vec3::Zero());
  state.slack_stiffness.assign(table.size(), 1.0);
  state.rate_q.assign(static_cast<std::size_t>(model.nq), 0.0);
  state.rate_dq.assign(static_cast<std::size_t>(model.nq), 0.0);
  state.rate_segments.assign(model.nsegment(), 0);
  for (const FrameRef& frame : table.point_frame) {
    if (frame.kind != FrameRef::Kind::kSegment) continue;
    for (std::int32_t s = frame.index; s >= 0 && !state.rate_segments[Index(s)];
         s = model.segment_parent[Index(s)]) {
      state.rate_segments[Index(s)] = 1;
    }
  }
  for (std::size_t b = 0; b < table.size(); ++b) {
    const auto first = Index(table.first_point[b]), first_span = Index(table.first_span(b));
    for (std::size_t i = 0; i < Index(table.span_count(b)); ++i) {
      state.span_belt[first_span + i] = static_cast<std::int32_t>(b);
      state.hysteresis[first_span + i] = HasHysteresis(model.functions, table.function[b]) ? 1 : 0;
    }
    for (std::size_t k = first + 1; k + 1 < first + Index(table.point_count[b]); ++k) {
      if (!table.point_wraps[k]) continue;
      const auto i = static_cast<std::int32_t>(first_span + (k - first));
      state.junction_first.push_back(i - 1);
      state.junction_second.push_back(i);
      state.junction_point.push_back(static_cast<std::int32_t>(k));
      state.junction_tie.push_back(-1);
      state.junction_friction.push_back(table.friction[b]);
    }
    state.slack_stiffness[b] = SlackStiffness(model.functions, table.function[b]);
  }
  for (std::size_t t = 0; t < table.tie_points.size(); ++t) {
    state.junction_first.push_back(
        static_cast<std::int32_t>(SpanAtAnchor(table, Index(table.tie_points[t][0])).first));
    state.junction_second.push_back(
        static_cast<std::int32_t>(SpanAtAnchor(table, Index(table.tie_points[t][1])).first));
    state.junction_point.push_back(-1);
    state.junction_tie.push_back(static_cast<std::int32_t>(t));
    state.junction_friction.push_back(table.harness_friction[Index(table.tie_harness[t])]);
  }
  const std::size_t junctions = state.junction_first.size();
  state.junction_ratio.assign(junctions, 1.0);
  state.transfer.assign(junctions, 0.0);
  state.slip_rate.assign(junctions, 0.0);
  state.rate_anchor.assign(junctions, Vec3::Zero());
  state.held_transfer.assign(junctions, 0.0);
  state.anchor.assign(junctions, Vec3::Zero());
  state.carry_stretch.assign(junctions, 1.0);
  state.carried_arc.assign(junctions, 0.0);
  state.carries.assign(junctions, 0);
  state.mode.assign(junctions, JunctionMode::kStick);
  for (std::size_t j = 0; j < junctions; ++j) {
    if (!(state.junction_friction[j] > 0)) state.mode[j] = JunctionMode::kFree;
  }
  SizeSlipSolver(state);
  if (table.size() == 0) return;

  // Fit at the initial state. Each body is wrapped on the side facing away from the line between
  // its neighbours (anchors, or the centres of the neighbouring wrapped bodies): the path says the
  // webbing lies over the body. The side is kept in the segment frame: it turns with the body.
  ComputeKinematics(model, data);
  for (std::size_t b = 0; b < table.size(); ++b) {
    const auto first = Index(table.first_point[b]);
    auto reference = [&](std::size_t k) {
      return table.point_wraps[k]
                 ? SurfaceOf(table, data, k).centre
                 : PointInFrame(data, table.point_frame[k], table.point_position[k]).position;
    };
    for (std::size_t k = first + 1; k + 1 < first + Index(table.point_count[b]); ++k) {
      if (!table.point_wraps[k]) continue;
      const Vec3 from = reference(k - 1), to = reference(k + 1), centre = reference(k);
      Vec3 along = to - from;
      along = along.norm() > 0 ? Vec3(along.normalized()) : Vec3::UnitX();
      const Vec3 away = (centre - from) - (centre - from).dot(along) * along;
      // A centre on the line: over the top (world z), or x for a vertical line.
      const Vec3 up = std::abs(along.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
      const auto s = Index(table.point_frame[k].index);
      state.side_in_segment[k] = data.rotation[s].transpose() * (away.norm() > 1e-12 ? away : up);
    }
    BeltGeometry(model, data, b);
    const double strain = StrainAtTension(model.functions, table.function[b], table.pretension[b]);
    const double stretch = 1.0 + std::max(strain, 0.0);
    double total = 0.0;
    const auto first_span = Index(table.first_span(b));
    const auto span_count = Index(table.span_count(b));
    for (std::size_t i = 0; i < span_count; ++i) total += state.length[first_span + i];
    for (std::size_t i = 0; i < span_count; ++i) {
      const std::size_t span = first_span + i;
      const double share =
          total > 0 ? state.length[span] / total : 1.0 / static_cast<double>(span_count);
      state.base_length[span] =
          std::max(state.length[span] / stretch + table.slack[b] * share, 1e-9);
      UpdateLoadingHistory(model.functions, table.function[b], std::max(strain, 0.0),
                           state.history[span]);
    }
  }
  EvaluateBelts(model, data);
  for (std::size_t j = 0; j < junctions; ++j) AnchorJunction(model, data, j);
  SizeBeltRatesCopy(data);
}

void ComputeBeltForces(const Model& model, Data& data) {
  const BeltTable& table = model.belts;
  if (table.size() == 0) return;
  EvaluateBelts(model, data);
  BeltState& state = data.belts;
  for (std::size_t b = 0; b < table.size(); ++b) {
    const auto first = Index(table.first_point[b]), first_span = Index(table.first_span(b));
    const auto spans = Index(table.span_count(b));
    state.start_anchor_force[b].setZero();
    state.end_anchor_force[b].setZero();
    for (std::size_t i = 0; i < spans; ++i) {
      const std::size_t span = first_span + i;
      const Vec3 along = state.end[span] - state.start[span];
      const double tension = state.tension[span];
      if (!(tension > 0) || !(along.norm() > 0)) continue;
      // Tension pulls each end toward the other.
      const Vec3 force = tension * along.normalized();
      for (const auto& [k, f, at] : {std::tuple(first + i, force, state.start[span]),
                                     std::tuple(first + i + 1, Vec3(-force), state.end[span])}) {
        const FrameRef& frame = table.point_frame[k];
        const bool pressed = !table.point_wraps[k] || state.contact[k];
        if (pressed) AddFrameForce(data, frame, at, f);
      }
      if (i == 0) state.start_anchor_force[b] = force;
      if (i + 1 == spans) state.end_anchor_force[b] = -force;
    }
    state.start_anchor_force[b] =
        FrameRotation(data, table.point_frame[first]).transpose() * state.start_anchor_force[b];
    state.end_anchor_force[b] = FrameRotation(data, table.point_frame[first + spans]).transpose() *
                                state.end_anchor_force[b];
  }
}

void AppendBeltChannelNames(const Model& model, std::size_t belt, const std::string& label,
                            std::vector<std::string>& names) {
  for (std::int32_t i = 0; i < model.belts.span_count(belt); ++i) {
    names.push_back(fmt::format("{}.belt_force.span{} [N]", label, i + 1));
  }
  for (const char* end : {"start", "end"}) {
    for (const char* axis : {"x", "y", "z"}) {
      names.push_back(fmt::format("{}.belt_force.{}.{} [N]", label, end, axis));
    }
  }
}

std::size_t WriteBeltChannels(const Model& model, const Data& data, std::size_t belt,
                              std::span<double> values) {
  std::size_t column = 0;
  const auto first_span = Index(model.belts.first_span(belt));
  for (std::size_t i = 0; i < Index(model.belts.span_count(belt)); ++i) {
    values[column++] = data.belts.tension[first_span + i];
  }
  for (const Vec3* force :
       {&data.belts.start_anchor_force[belt], &data.belts.end_anchor_force[belt]}) {
    for (int axis = 0; axis < 3; ++axis) values[column++] = (*force)[axis];
  }
  return column;
}

}  // namespace sled::runtime
