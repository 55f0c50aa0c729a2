#include "runtime/restraint/belt_events.h"

#include <algorithm>

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"
#include "runtime/forces/atb_unloading.h"
#include "runtime/forces/force_deflection.h"
#include "runtime/restraint/belt_slip.h"
#include "runtime/restraint/belts.h"

namespace sled::runtime {
namespace {

// The time step of the geometry's central differences [s]: small next to any belt's time
// scale, large enough that the rounding of the positions (1e-16 m) stays below 1e-9 of a rate.
constexpr double kRateStep = 1e-6;
// How far from zero the rates put a strain rate that is zero [1/s]: the rounding of two lengths
// over kRateStep (the central differences of whole belt evaluations, slip solves included, were
// measured up to 3.3e-9 on the flagship's lap belt at its turn).
// A span turned this close to its turn has its largest strain off by about rate^2 / (2 strain
// acceleration), far below anything a tolerance can see.
constexpr double kRateNoise = 1e-8;

std::size_t Index(std::int32_t value) { return static_cast<std::size_t>(value); }

bool Slips(JunctionMode mode) {
  return mode == JunctionMode::kSlipIntoFirst || mode == JunctionMode::kSlipIntoSecond;
}

double Strain(const BeltState& state, std::size_t span) {
  return state.length[span] / state.rest_length[span] - 1.0;
}

// Whether the span's turn events need its strain rate now: while it loads beyond its largest
// strain, and always under ATB's law, which turns below it too.
bool WatchesRate(const Model& model, const BeltState& state, std::size_t span) {
  if (!state.hysteresis[span]) return false;
  const std::int32_t function = model.belts.function[Index(state.span_belt[span])];
  return AtbReturnFunction(model.functions, function) >= 0 ||
         Strain(state, span) > state.history[span].max_deflection;
}

// The span's turn event function (force_deflection.h): its strain rate while it loads beyond
// its largest strain (and ATB's turns below it); 1 when nothing can turn its history.
double TurnFunction(const Model& model, const BeltState& state, std::size_t span) {
  if (!state.hysteresis[span]) return 1.0;
  return TurnEventFunction(model.functions, model.belts.function[Index(state.span_belt[span])],
                           Strain(state, span), state.strain_rate[span], state.history[span]);
}

double Extended(const Model& model, const BeltState& state, std::size_t span) {
  return SpanForceAt(model, state, span, state.rest_length[span]).extended;
}

// The kinematics of `data` the central differences move (ComputeKinematics), to and from `copy`:
// same sizes both ways, so no allocation after the first (SetUpBelts).
template <typename From, typename To>
void CopyKinematics(From& from, To& to) {
  to.vehicle = from.vehicle;
  to.rotation = from.rotation;
  to.position = from.position;
  to.parent_to_child = from.parent_to_child;
  to.subspace = from.subspace;
  to.subspace_locked = from.subspace_locked;
  to.velocity = from.velocity;
  to.bias_acceleration = from.bias_acceleration;
}

// The geometry's rates (UpdateBeltRates), kept in a working copy's vectors that the geometry
// does not write, the copy being thrown away after: per span the length's rate, per junction the
// capstan ratio's, the carried arc's, the arc's from the webbing's middle to rate_anchor, and
// the transfer's.
struct GeometryRates {
  std::vector<double>& length;
  std::vector<double>& ratio;
  std::vector<double>& carried;
  std::vector<double>& anchor_arc;
  std::vector<double>& transfer;
};

GeometryRates RatesIn(BeltState& work) {
  return {work.strain_rate, work.slip_rate, work.solve_trial, work.solve_residual, work.solve_step};
}

}  // namespace

void SizeBeltRatesCopy(Data& data) {
  CopyKinematics(data, data.belt_rates_copy);
  data.belt_rates_copy.belts = data.belts;
}

std::vector<BeltEvent> BeltEvents(const Model& model, const Data& data) {
  (void)model;
  const BeltState& state = data.belts;
  std::vector<BeltEvent> events;
  for (std::size_t j = 0; j < state.mode.size(); ++j) {
    if (state.mode[j] == JunctionMode::kFree) continue;
    events.push_back({BeltEventKind::kSlipIntoFirst, j});
    events.push_back({BeltEventKind::kSlipIntoSecond, j});
    events.push_back({BeltEventKind::kStop, j});
    if (state.junction_point[j] >= 0) events.push_back({BeltEventKind::kContact, j});
  }
  for (std::size_t span = 0; span < state.hysteresis.size(); ++span) {
    if (state.hysteresis[span]) events.push_back({BeltEventKind::kTurn, span});
  }
  return events;
}

void UpdateBeltRates(const Model& model, Data& data) {
  BeltState& state = data.belts;
  bool needed = false;
  for (std::size_t j = 0; j < state.mode.size() && !needed; ++j) needed = Slips(state.mode[j]);
  for (std::size_t span = 0; span < state.hysteresis.size() && !needed; ++span) {
    needed = WatchesRate(model, state, span);
  }
  if (!needed) return;
  // The body point under each wrap's middle now: how far the body carries the webbing is how
  // far that point moves along it.
  const BeltTable& table = model.belts;
  for (std::size_t j = 0; j < state.mode.size(); ++j) {
    const std::int32_t point = state.junction_point[j];
    if (point < 0) continue;
    const auto s = Index(table.point_frame[Index(point)].index);
    state.rate_anchor[j] =
        data.rotation[s].transpose() * (state.middle[Index(point)] - data.position[s]);
  }
  // The geometry's rates: each span's length, each junction's capstan ratio, the arc its body
  // carried and the arc from the webbing's middle to that body point, by central differences a
  // half step back and ahead along the motion (q +- h/2 qdot, the vehicles at those times),
  // without the slip solve; then back where Forward left them.
  const double t = data.time;
  Data::BeltRatesCopy& copy = data.belt_rates_copy;
  CopyKinematics(data, copy);
  copy.belts = data.belts;
  std::copy(data.q.begin(), data.q.end(), state.rate_q.begin());
  PositionDerivative(model, data.q, data.v, data.locked, state.rate_dq);
  const GeometryRates differences = RatesIn(state);
  for (const double sign : {-1.0, 1.0}) {
    for (std::size_t i = 0; i < data.q.size(); ++i) {
      data.q[i] = state.rate_q[i] + sign * 0.5 * kRateStep * state.rate_dq[i];
    }
    data.time = t + sign * 0.5 * kRateStep;
    ComputeKinematics(model, data, state.rate_segments);
    EvaluateBeltGeometry(model, data);
    // After the back point each rate holds minus its value there, after the point ahead the rate.
    auto difference = [sign](double& rate, double value) {
      rate = sign < 0 ? -value : (rate + value) / kRateStep;
    };
    for (std::size_t span = 0; span < state.length.size(); ++span) {
      difference(differences.length[span], state.length[span]);
    }
    for (std::size_t j = 0; j < state.transfer.size(); ++j) {
      difference(differences.ratio[j], state.junction_ratio[j]);
      difference(differences.carried[j], state.carried_arc[j]);
      difference(differences.anchor_arc[j], CarriedLength(model, data, j, state.rate_anchor[j]));
    }
  }
  // Back to Forward's evaluation; the working copy, with the rates, goes to `copy`.
  std::copy(state.rate_q.begin(), state.rate_q.end(), data.q.begin());
  data.time = t;
  std::swap(data.belts, copy.belts);  // (the vectors' buffers: no second copy)
  CopyKinematics(copy, data);
  const GeometryRates rates = RatesIn(copy.belts);
  BeltState& now = data.belts;
  // The transfers' rates from the slip equations' derivative, then each junction's slip (its
  // transfer less the webbing its body carries, over the webbing's stretch) and each span's
  // strain (its length over its rest length, which the transfers change).
  TransferRates(model, now, rates.length, rates.ratio, rates.carried, rates.transfer);
  for (std::size_t j = 0; j < now.transfer.size(); ++j) {
    const auto a = Index(now.junction_first[j]), c = Index(now.junction_second[j]);
    double slip_rate = rates.transfer[j];
    const std::int32_t point = now.junction_point[j];
    if (point >= 0 && now.contact[Index(point)]) {
      const double stretch =
          0.5 * (now.length[a] / now.rest_length[a] + now.length[c] / now.rest_length[c]);
      slip_rate -= rates.anchor_arc[j] / std::max(stretch, 1e-3);
    }
    now.slip_rate[j] = slip_rate;
  }
  for (std::size_t span = 0; span < now.length.size(); ++span) {
    double rest_rate = 0.0;
    for (std::size_t j = 0; j < now.transfer.size(); ++j) {
      if (Index(now.junction_first[j]) == span) rest_rate -= rates.transfer[j];
      if (Index(now.junction_second[j]) == span) rest_rate += rates.transfer[j];
    }
    const double rest = now.rest_length[span];
    now.strain_rate[span] =
        rates.length[span] / rest - now.length[span] * rest_rate / (rest * rest);
  }
}

double BeltEventFunction(const Model& model, const Data& data, const BeltEvent& event) {
  const BeltState& state = data.belts;
  if (event.kind == BeltEventKind::kTurn) {
    return TurnFunction(model, state, event.index);
  }
  const std::size_t j = event.index;
  const JunctionMode mode = state.mode[j];
  const std::size_t a = Index(state.junction_first[j]), c = Index(state.junction_second[j]);
  switch (event.kind) {
    case BeltEventKind::kSlipIntoFirst:
      if (mode != JunctionMode::kStick) return 1.0;
      return CapstanBound(state.junction_ratio[j], Extended(model, state, c)) -
             Extended(model, state, a);
    case BeltEventKind::kSlipIntoSecond:
      if (mode != JunctionMode::kStick) return 1.0;
      return CapstanBound(state.junction_ratio[j], Extended(model, state, a)) -
             Extended(model, state, c);
    case BeltEventKind::kStop:
      if (mode == JunctionMode::kSlipIntoSecond) return state.slip_rate[j];
      if (mode == JunctionMode::kSlipIntoFirst) return -state.slip_rate[j];
      return 1.0;
    case BeltEventKind::kContact: {
      if (mode != JunctionMode::kStick) return 1.0;
      const double reach = state.reach[Index(state.junction_point[j])];
      return state.carries[j] ? reach : -reach;
    }
    case BeltEventKind::kTurn:
      break;
  }
  return 1.0;
}

void HandleBeltEvent(const Model& model, Data& data, const BeltEvent& event, int direction) {
  if (direction > 0) return;
  BeltState& state = data.belts;
  if (event.kind == BeltEventKind::kTurn) {
    // Every span that is at its turn turns here, not only the event's: spans that turn together
    // (the two spans of a lap belt round a pelvis it slides over) reach their roots within the
    // locator's tolerance of each other, and one left out (its rate a rounding above zero here)
    // would start the next step with its rate a rounding below zero, where no fall through
    // zero is ever seen: it would go on along its loading curve while it unloads. On the
    // flagship at 1e-9 that took the lap belt's second span off its unloading curve for 11 ms.
    UpdateBeltRates(model, data);
    for (std::size_t span = 0; span < state.hysteresis.size(); ++span) {
      const bool turning = TurnFunction(model, state, span) <= kRateNoise;
      if (span != event.index && !turning) continue;
      UpdateLoadingHistory(model.functions, model.belts.function[Index(state.span_belt[span])],
                           Strain(state, span), state.history[span]);
    }
    return;
  }
  const std::size_t j = event.index;
  switch (event.kind) {
    case BeltEventKind::kSlipIntoFirst:
      state.mode[j] = JunctionMode::kSlipIntoFirst;
      break;
    case BeltEventKind::kSlipIntoSecond:
      state.mode[j] = JunctionMode::kSlipIntoSecond;
      break;
    case BeltEventKind::kStop:
    case BeltEventKind::kContact:
      state.mode[j] = JunctionMode::kStick;
      AnchorJunction(model, data, j);
      break;
    case BeltEventKind::kTurn:
      break;
  }
  state.held_transfer[j] = state.transfer[j];
}

}  // namespace sled::runtime
