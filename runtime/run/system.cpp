#include "runtime/run/system.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "runtime/airbag/airbag_forces.h"
#include "runtime/airbag/free_bag.h"
#include "runtime/contact/contact_forces.h"
#include "runtime/contact/contact_impulse.h"
#include "runtime/contact/contact_reach.h"
#include "runtime/dynamics/constraints.h"
#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"
#include "runtime/forces/atb_unloading.h"
#include "runtime/forces/force_deflection.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"
#include "runtime/forces/joint_hysteresis.h"
#include "runtime/forces/state_owner.h"
#include "runtime/restraint/belts.h"
#include "runtime/run/energy.h"

namespace sled::runtime {

// The points inside each step at which the lock levels' event functions are sampled
// (EventSamples): each costs an evaluation; three found every event of lock_cascade at every
// tolerance of the suite's ladder.
constexpr std::size_t kLockEventSamples = 3;
namespace {

// The angles where a torque function's slope jumps: a table's inner rows, and their mirror
// images when the table describes positive angles only (it is read mirrored below zero). Its
// first and last rows are no kinks: past them the table runs on its end segments' slopes. Nor is
// a row at zero (a neck's signed table, flexion against extension): an axis at rest sits there
// and would stop every step on the integrator's noise (as kTurnResolution keeps the histories
// from turning there, runtime/forces/joint_hysteresis.cpp).
std::vector<double> TableKinks(const FunctionTable& functions, std::int32_t id) {
  std::vector<double> kinks;
  if (id < 0 || functions.kind[static_cast<std::size_t>(id)] != FunctionTable::Kind::kTable) {
    return kinks;
  }
  const auto first = static_cast<std::size_t>(functions.first[static_cast<std::size_t>(id)]);
  const auto count = static_cast<std::size_t>(functions.count[static_cast<std::size_t>(id)]);
  const bool mirrored = !CoversNegative(functions, id);
  for (std::size_t row = first + 1; row + 1 < first + count; ++row) {
    const double x = functions.points_x[row];
    if (x == 0) continue;
    kinks.push_back(x);
    if (mirrored && x > 0) kinks.push_back(-x);
  }
  return kinks;
}

// Whether (t, y) is (t0, y0) but for the work integrals (the components from `controlled` on),
// which feed nothing back.
bool SameState(double t, std::span<const double> y, double t0, std::span<const double> y0,
               std::size_t controlled) {
  const auto count = static_cast<std::ptrdiff_t>(controlled);
  return t == t0 && y.size() == y0.size() && std::equal(y.begin(), y.begin() + count, y0.begin());
}

}  // namespace

MultibodySystem::MultibodySystem(const Model& model, Data& data)
    : model_(model), data_(data), jacobian_(model) {
  CheckDataOf(model, data);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const JointKind kind = model.joint_kind[s];
    if (model.joint_stop_impulse[s] && model.joint_stop[s] > 0 &&
        (kind == JointKind::kPin || kind == JointKind::kBall || kind == JointKind::kSlip)) {
      events_.push_back({EventKind::kStop, s});
    }
    if (model.joint_stop_impulse[s] && model.joint_twist_stop[s] > 0 && kind == JointKind::kBall) {
      events_.push_back({EventKind::kTwistStop, s});
    }
    if (kind != JointKind::kFree &&
        (model.joint_lock_below[s] >= 0 || model.joint_unlock_above[s] >= 0)) {
      events_.push_back({EventKind::kLock, s});
      if (HasSignedLockBand(s)) events_.push_back({EventKind::kLockLower, s});
    }
  }
  for (std::size_t h = 0; h < data.joint_histories.size(); ++h) {
    events_.push_back({EventKind::kJointTurn, h});
  }
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      for (const double row : TableKinks(model.functions, model.joint_function[s][axis])) {
        events_.push_back({EventKind::kJointKink, s, 0.0, row, axis});
      }
    }
  }
  for (std::size_t k = 0; k < model.contacts.npair(); ++k) {
    // First touch and separation: the force law starts (and ends) with a kink that no step
    // should straddle; the impulse option's event marks the touch already.
    events_.push_back(
        {model.contacts.pair_impulse[k] ? EventKind::kContactImpulse : EventKind::kContactTouch,
         k});
    if (data.contacts.hysteresis[k]) events_.push_back({EventKind::kContactTurn, k});
    // (An inertial spike's rows are kinks of the loading curve too.)
    const std::int32_t force = model.contacts.pair_function[k];
    for (const std::int32_t f : {force, AtbSpikeFunction(model.functions, force)}) {
      for (const double row : TableKinks(model.functions, f)) {
        if (row > 0) events_.push_back({EventKind::kContactKink, k, 0.0, row});
      }
    }
  }
  for (std::size_t k = 0; k < model.contacts.npair(); ++k) {
    const auto f = static_cast<std::size_t>(model.contacts.pair_function[k]);
    watches_tables_ = watches_tables_ || model.functions.kind[f] == FunctionTable::Kind::kTable;
  }
  for (std::size_t b = 0; b < model.belts.size(); ++b) {
    const auto f = static_cast<std::size_t>(model.belts.function[b]);
    watches_tables_ = watches_tables_ || model.functions.kind[f] == FunctionTable::Kind::kTable;
  }
  reads_accelerations_ = std::any_of(events_.begin(), events_.end(), [](const Event& event) {
    return event.kind == EventKind::kLock;
  });
  belt_events_ = BeltEvents(model, data);
  for (std::size_t k = 0; k < belt_events_.size(); ++k) events_.push_back({EventKind::kBelt, k});
  const AirbagTable& bags = model.airbags;
  for (std::size_t b = 0; b < bags.size(); ++b) {
    events_.push_back({EventKind::kAirbagFull, b});
    if (bags.deploy_time[b] > model.start_time) {
      events_.push_back({EventKind::kAirbagInflow, b, bags.deploy_time[b]});
    }
    if (bags.free_bag[b] && bags.vent_opening_pressure[b] > 0 && bags.vent_area[b] > 0) {
      events_.push_back({EventKind::kAirbagVent, b});
    }
    const double spent = AirbagInflowEnd(model, b);
    if (std::isfinite(spent) && spent > model.start_time) {
      events_.push_back({EventKind::kAirbagInflow, b, spent});
    }
  }
  // Workspace for impulses, sized once.
  evaluated_y_.assign(StateSize(model), 0.0);
  saved_v_.assign(static_cast<std::size_t>(model.nv), 0.0);
  event_v_.assign(static_cast<std::size_t>(model.nv), 0.0);
  responses_.assign(6, std::vector<double>(static_cast<std::size_t>(model.nv), 0.0));
}

std::size_t MultibodySystem::ControlledSize() const { return StateSize(model_) - kEnergyStates; }

double MultibodySystem::QuadratureScale(double t, std::span<const double> y) {
  // The integrator asks where it has just evaluated, so data holds that state: a scale needs
  // no new evaluation (a step that lands on its stop may end an ulp from where it evaluated).
  (void)t, (void)y;
  const EnergyBalance& work = data_.energy;
  return std::max({KineticEnergy(model_, data_), std::abs(work.element_work),
                   std::abs(work.constraint_work), std::abs(work.vehicle_work),
                   std::abs(work.applied_work)});
}

std::size_t MultibodySystem::size() const { return StateSize(model_); }

void MultibodySystem::Load(double t, std::span<const double> y) {
  evaluated_ = false;
  LoadState(data_, t, y);
}

bool MultibodySystem::EvaluateElements(double t, std::span<const double> y) {
  const auto controlled = static_cast<std::ptrdiff_t>(ControlledSize());
  if (evaluated_ && SameState(t, y, evaluated_t_, evaluated_y_, ControlledSize())) {
    // The work integrals feed nothing back: a state that differs from the evaluated one only in
    // them (a method sets its quadratures after the end derivative) needs no new Forward.
    if (!std::equal(y.begin() + controlled, y.end(), evaluated_y_.begin() + controlled)) {
      LoadState(data_, t, y);
      std::copy(y.begin() + controlled, y.end(), evaluated_y_.begin() + controlled);
    }
    return true;
  }
  Load(t, y);
  failure_ = Failure{};
  ForwardElements(model_, data_);
  evaluated_ = true;
  accelerated_ = false;
  evaluated_t_ = t;
  std::copy(y.begin(), y.end(), evaluated_y_.begin());
  return true;
}

bool MultibodySystem::Evaluate(double t, std::span<const double> y) {
  EvaluateElements(t, y);
  if (accelerated_) return true;
  if (!ForwardAccelerations(model_, data_, &failure_)) {
    failure_.time = t;
    evaluated_ = false;
    return false;
  }
  accelerated_ = true;
  return true;
}

void MultibodySystem::Store(std::span<double> y) const { StoreState(data_, y); }

bool MultibodySystem::Derivative(double t, std::span<const double> y, std::span<double> dy) {
  if (!Evaluate(t, y)) return false;
  if (data_.airbags.failed_bag >= 0) {
    const auto b = static_cast<std::size_t>(data_.airbags.failed_bag);
    failure_.time = t;
    failure_.where = model_.airbags.name[b];
    failure_.cause = "the segments inside the airbag leave its gas no volume";
    failure_.source = model_.airbags.source[b];
    return false;
  }
  const auto nq = static_cast<std::size_t>(model_.nq);
  PositionDerivative(model_, data_.q, data_.v, data_.locked, dy.first(nq));
  auto rates =
      std::copy(data_.vdot.begin(), data_.vdot.end(), dy.begin() + static_cast<std::ptrdiff_t>(nq));
  if (data_.settling_damping > 0.0) {
    // -c M v as a generalized force is -c v in the accelerations; it keeps J v = 0 of the loops.
    for (std::size_t i = 0; i < data_.v.size(); ++i)
      dy[nq + i] -= data_.settling_damping * data_.v[i];
  }
  rates = std::copy(data_.wdot.begin(), data_.wdot.end(), rates);
  const SegmentPower power = PowerIntoSegments(model_, data_);
  // The applied loads' work is a term of its own, not the force elements'.
  rates[0] = power.elements - data_.applied_power;
  rates[1] = power.constraints;
  rates[2] = data_.vehicle_power;
  rates[3] = data_.applied_power;
  for (std::size_t i = 0; i < dy.size(); ++i) {
    if (!std::isfinite(dy[i])) {
      failure_.time = t;
      failure_.cause = "the state derivative is not finite";
      NameStateOwner(model_, i, failure_);
      if (failure_.where.empty() && power.not_finite >= 0) {
        const auto s = static_cast<std::size_t>(power.not_finite);
        failure_.where = model_.segment_name[s];
        failure_.source = model_.segment_source[s];
        failure_.cause = "the power the forces deliver to it is not finite";
      }
      return false;
    }
  }
  return true;
}

bool MultibodySystem::StructuredJacobianAt(double t, std::span<const double> y,
                                           std::span<const double> dy, double step,
                                           StructuredJacobian& jacobian) {
  (void)dy;
  // Form moves data_ through other states: an evaluation still to be completed by its
  // accelerations cannot be completed from what it leaves.
  if (!accelerated_) Invalidate();
  failure_ = Failure{};
  if (jacobian_.Form(data_, t, y, step, jacobian, &failure_)) return true;
  failure_.time = t;
  if (failure_.cause.empty()) failure_.cause = "the Jacobian of the force elements failed";
  return false;
}

// At least one column, so the methods take this structured Jacobian (N alone when no element
// is stiff) rather than a dense one.
std::size_t MultibodySystem::StructuredRank() const {
  return std::max<std::size_t>(jacobian_.max_rank(), 1);
}

std::vector<std::size_t> MultibodySystem::VectorGroups() const {
  // Angular and linear velocities are physical 3-vectors: one decay rate each.
  std::vector<std::size_t> groups;
  const auto nq = static_cast<std::size_t>(model_.nq);
  for (std::size_t s = 0; s < model_.nsegment(); ++s) {
    const auto va = nq + static_cast<std::size_t>(model_.v_address[s]);
    if (model_.joint_kind[s] == JointKind::kFree) {
      groups.push_back(va);
      groups.push_back(va + 3);
    } else if (model_.joint_kind[s] == JointKind::kBall) {
      groups.push_back(va);
    }
  }
  return groups;
}

void MultibodySystem::ProjectState(double t, std::span<double> y) {
  // Unit quaternions: the integrators move them off the unit sphere by the local error.
  for (std::size_t s = 0; s < model_.nsegment(); ++s) {
    std::size_t address = static_cast<std::size_t>(model_.q_address[s]);
    if (model_.joint_kind[s] == JointKind::kFree) address += 3;
    if (model_.joint_kind[s] != JointKind::kFree && model_.joint_kind[s] != JointKind::kBall) {
      continue;
    }
    double norm = 0.0;
    for (std::size_t k = 0; k < 4; ++k) norm += y[address + k] * y[address + k];
    norm = std::sqrt(norm);
    if (norm > 0) {
      for (std::size_t k = 0; k < 4; ++k) y[address + k] /= norm;
    }
  }
  // Loop constraints: back onto the constraint manifold, so loops stay closed to rounding.
  if (model_.nconstraint() > 0) {
    Invalidate();
    ProjectConstraints(model_, data_, t, y, &failure_);
  }
}

double MultibodySystem::StepLimit(double t, std::span<const double> y) {
  if (model_.contacts.npair() == 0 || !Evaluate(t, y)) {
    return std::numeric_limits<double>::infinity();  // (a failed evaluation fails the step)
  }
  WatchContactReach(model_, data_);
  return ContactStepLimit(model_, data_);
}

void MultibodySystem::CommitStep(double t, std::span<const double> y) {
  if (!watches_tables_) return;
  // The integrator commits the state it last evaluated (a step's end before the projection):
  // the kinematics, the placed surfaces and the belts are still those of y.
  const bool evaluated =
      evaluated_ && SameState(t, y, evaluated_t_, evaluated_y_, ControlledSize());
  if (!evaluated) {
    Load(t, y);
    ComputeKinematics(model_, data_);
    PlaceContactSurfaces(model_, data_);
  }
  WatchContactTables(model_, data_);
  if (model_.belts.size() > 0) {
    if (!evaluated) EvaluateBelts(model_, data_);
    WatchBeltTables(model_, data_);
  }
}

std::uint8_t MultibodySystem::LockableAxes(std::size_t s) const {
  const std::uint8_t all = 7;  // ball, pin and slip lock whole; Euler per axis (bits 0-2)
  // Axes locked from the start stay locked for good unless the joint can unlock.
  const std::uint8_t permanent = model_.joint_unlock_above[s] < 0 ? model_.joint_locked[s] : 0;
  return static_cast<std::uint8_t>(all & ~permanent);
}

double MultibodySystem::JointTorqueMagnitude(std::size_t s) const {
  const auto va = static_cast<std::size_t>(model_.v_address[s]);
  const auto dof = static_cast<std::size_t>(model_.v_count[s]);
  const std::uint8_t lockable = LockableAxes(s);
  const bool locked = (data_.locked[s] & lockable) != 0;
  if (!locked) {
    double sum = 0.0;
    for (std::size_t k = 0; k < dof; ++k) {
      sum += data_.generalized_force[va + k] * data_.generalized_force[va + k];
    }
    return std::sqrt(sum);
  }
  // The constraint torque about the joint point, in the segment frame, along the locked axes.
  const Vec6& wrench = data_.joint_wrench[s];
  const Vec3 torque = wrench.head<3>() - model_.joint_point_in_child[s].cross(wrench.tail<3>());
  JointMotion motion;
  int axes[6];
  const int free_count = ActiveAxes(model_, s, 0, axes);
  ComputeJointMotion(model_, s, data_.q, data_.v, 0, motion);
  double sum = 0.0;
  for (int c = 0; c < free_count; ++c) {
    if (!(data_.locked[s] & (1u << axes[c])) && model_.joint_kind[s] == JointKind::kEuler) continue;
    const Vec3 axis = motion.subspace.col(c).head<3>();
    if (axis.squaredNorm() > 0) sum += std::pow(torque.dot(axis.normalized()), 2);
  }
  return std::sqrt(sum);
}

bool MultibodySystem::HasSignedLockBand(std::size_t s) const {
  return model_.joint_lock_below[s] >= 0 && model_.v_count[s] == 1;
}

int MultibodySystem::EventDirection(std::size_t k) const {
  // A loading history turns, and a belt's junction slips, sticks or re-anchors, only where its
  // function falls through zero (HandleEvent); where it rises again (as a turn function does by
  // a jump to 1 once the deflection is below its largest, or a rounding after the turn) nothing
  // changes, and the step need not stop (on the flagship 17 such stops, each with a retake).
  const EventKind kind = events_[k].kind;
  return kind == EventKind::kContactTurn || kind == EventKind::kJointTurn ||
                 kind == EventKind::kBelt
             ? -1
             : 0;
}

std::size_t MultibodySystem::EventSamples() const {
  return reads_accelerations_ ? kLockEventSamples : 0;
}

void MultibodySystem::Events(double t, std::span<const double> y, std::span<double> g) {
  // Only a lock level reads what the accelerations give (a locked joint's constraint torque).
  if (reads_accelerations_) {
    Evaluate(t, y);
  } else {
    EvaluateElements(t, y);
  }
  if (!belt_events_.empty()) UpdateBeltRates(model_, data_);
  std::size_t angle_segment = model_.nsegment();
  std::array<double, 3> axis_angles{};
  for (std::size_t k = 0; k < events_.size(); ++k) {
    if (events_[k].kind == EventKind::kContactImpulse ||
        events_[k].kind == EventKind::kContactTouch) {
      g[k] = data_.contacts.gap[events_[k].segment];  // > 0 while the surfaces are apart
      continue;
    }
    if (events_[k].kind == EventKind::kBelt) {
      g[k] = BeltEventFunction(model_, data_, belt_events_[events_[k].segment]);
      continue;
    }
    if (events_[k].kind == EventKind::kContactTurn) {
      // The deflection rate while the pair loads beyond its largest deflection (it falls through
      // zero where the deflection turns), and ATB's turns below it; 1 when nothing can turn the
      // history. The signed deflection is minus the gap (below zero: apart).
      const std::size_t pair = events_[k].segment;
      const ContactState& contacts = data_.contacts;
      g[k] = TurnEventFunction(model_.functions, model_.contacts.pair_function[pair],
                               -contacts.gap[pair], contacts.rate[pair], contacts.history[pair]);
      continue;
    }
    if (events_[k].kind == EventKind::kJointTurn) {
      g[k] = JointTurnFunction(model_, data_, events_[k].segment);
      continue;
    }
    if (events_[k].kind == EventKind::kJointKink) {
      // A joint's table rows are consecutive events: its angles are computed once.
      const Event& kink = events_[k];
      if (kink.segment != angle_segment) {
        angle_segment = kink.segment;
        axis_angles = JointAxisAngles(model_, data_, kink.segment);
      }
      g[k] = axis_angles[kink.axis] - kink.row;
      continue;
    }
    if (events_[k].kind == EventKind::kContactKink) {
      // (The deflection is 0 while the pair is apart.)
      g[k] = data_.contacts.deflection[events_[k].segment] - events_[k].row;
      continue;
    }
    if (events_[k].kind == EventKind::kAirbagFull) {
      g[k] = AirbagFullnessEvent(model_, data_, events_[k].segment);
      continue;
    }
    if (events_[k].kind == EventKind::kAirbagInflow) {
      g[k] = t - events_[k].time;
      continue;
    }
    if (events_[k].kind == EventKind::kAirbagVent) {
      const std::size_t b = events_[k].segment;
      g[k] = data_.airbags.pressure[b] - model_.airbags.ambient_pressure[b] -
             model_.airbags.vent_opening_pressure[b];
      continue;
    }
    const std::size_t s = events_[k].segment;
    const auto qa = static_cast<std::size_t>(model_.q_address[s]);
    const auto va = static_cast<std::size_t>(model_.v_address[s]);
    switch (events_[k].kind) {
      case EventKind::kStop: {
        // Positive inside the range of motion, negative past the stop.
        const double angle =
            model_.joint_kind[s] == JointKind::kBall
                ? DecomposeSwingTwist(QuaternionAt(data_.q, qa).normalized()).flexure
                : std::abs(data_.q[qa]);
        g[k] = model_.joint_stop[s] - angle;
        break;
      }
      case EventKind::kTwistStop:
        g[k] = model_.joint_twist_stop[s] -
               std::abs(DecomposeSwingTwist(QuaternionAt(data_.q, qa).normalized()).twist);
        break;
      case EventKind::kLock: {
        const bool locked = (data_.locked[s] & LockableAxes(s)) != 0;
        // Rises through zero when an unlocked joint's torque enters its lock band (from above,
        // for a signed band), or a locked joint's constraint torque exceeds its unlock level.
        if (locked) {
          g[k] = model_.joint_unlock_above[s] >= 0
                     ? JointTorqueMagnitude(s) - model_.joint_unlock_above[s]
                     : -1.0;
        } else if (model_.joint_lock_below[s] < 0) {
          g[k] = -1.0;
        } else if (HasSignedLockBand(s)) {
          g[k] = model_.joint_lock_below[s] - data_.generalized_force[va];
        } else {
          g[k] = model_.joint_lock_below[s] - JointTorqueMagnitude(s);
        }
        break;
      }
      case EventKind::kLockLower: {
        // Rises through zero when an unlocked joint's signed torque enters its band from below.
        const bool locked = (data_.locked[s] & LockableAxes(s)) != 0;
        g[k] = locked ? -1.0 : model_.joint_lock_below[s] + data_.generalized_force[va];
        break;
      }
      case EventKind::kContactImpulse:
      case EventKind::kContactTouch:
      case EventKind::kContactTurn:
      case EventKind::kContactKink:
      case EventKind::kJointTurn:
      case EventKind::kJointKink:
      case EventKind::kBelt:
      case EventKind::kAirbagFull:
      case EventKind::kAirbagInflow:
      case EventKind::kAirbagVent:
        break;
    }
  }
}

void MultibodySystem::UnitResponse(std::size_t s, const SmallVector& force,
                                   std::vector<double>& response) {
  std::copy(data_.v.begin(), data_.v.end(), saved_v_.begin());
  std::fill(data_.v.begin(), data_.v.end(), 0.0);
  ComputeKinematics(model_, data_);
  for (auto& wrench : data_.external) wrench.setZero();
  std::fill(data_.generalized_force.begin(), data_.generalized_force.end(), 0.0);
  const auto va = static_cast<std::size_t>(model_.v_address[s]);
  for (Eigen::Index k = 0; k < force.size(); ++k) {
    data_.generalized_force[va + static_cast<std::size_t>(k)] = force[k];
  }
  Failure ignored;
  ComputeAccelerations(model_, data_, &ignored);
  std::copy(data_.vdot.begin(), data_.vdot.end(), response.begin());
  std::copy(saved_v_.begin(), saved_v_.end(), data_.v.begin());
}

void MultibodySystem::ApplyJointImpulse(std::size_t s, const SmallMatrix& directions,
                                        const SmallVector& targets) {
  const auto va = static_cast<std::size_t>(model_.v_address[s]);
  const auto dof = static_cast<Eigen::Index>(model_.v_count[s]);
  const Eigen::Index count = directions.cols();
  SmallMatrix coupling(count, count);
  SmallVector current(count);
  for (Eigen::Index i = 0; i < count; ++i) {
    UnitResponse(s, directions.col(i), responses_[static_cast<std::size_t>(i)]);
  }
  for (Eigen::Index i = 0; i < count; ++i) {
    current[i] = 0.0;
    for (Eigen::Index d = 0; d < dof; ++d) {
      current[i] += directions(d, i) * data_.v[va + static_cast<std::size_t>(d)];
    }
    for (Eigen::Index j = 0; j < count; ++j) {
      double value = 0.0;
      for (Eigen::Index d = 0; d < dof; ++d) {
        value += directions(d, i) *
                 responses_[static_cast<std::size_t>(j)][va + static_cast<std::size_t>(d)];
      }
      coupling(i, j) = value;
    }
  }
  const SmallVector impulse = coupling.partialPivLu().solve(targets - current);
  for (Eigen::Index j = 0; j < count; ++j) {
    const auto& response = responses_[static_cast<std::size_t>(j)];
    for (std::size_t k = 0; k < data_.v.size(); ++k) data_.v[k] += response[k] * impulse[j];
  }
}

OdeSystem::EventEffect MultibodySystem::HandleEvent(std::size_t k, int direction, double t,
                                                    std::span<double> y) {
  Invalidate();
  if (events_[k].kind == EventKind::kAirbagFull) {
    const std::size_t b = events_[k].segment;
    data_.airbags.full[b] = direction > 0 ? 1 : 0;
    if (!model_.airbags.free_bag[b] || direction <= 0) return EventEffect::kModeChanged;
    // ATB's free bag is full: its motion starts where the envelope sits, as its frame moves.
    Load(t, y);
    ComputeKinematics(model_, data_);
    StartFreeBag(model_, data_, b);
    Store(y);
    return EventEffect::kStateChanged;
  }
  if (events_[k].kind == EventKind::kAirbagInflow) {
    // Just past the event's time (which it may have been located a hair before).
    data_.airbags.inflow_phase[events_[k].segment] =
        AirbagInflowPhase(model_, events_[k].segment, std::max(t, events_[k].time));
    return EventEffect::kModeChanged;
  }
  if (events_[k].kind == EventKind::kBelt) {
    if (direction < 0 && EvaluateElements(t, y)) {
      HandleBeltEvent(model_, data_, belt_events_[events_[k].segment], direction);
      Invalidate();
    }
    return EventEffect::kModeChanged;
  }
  if (events_[k].kind == EventKind::kContactTouch || events_[k].kind == EventKind::kJointKink ||
      events_[k].kind == EventKind::kContactKink || events_[k].kind == EventKind::kAirbagVent) {
    return EventEffect::kModeChanged;
  }
  if (events_[k].kind == EventKind::kContactTurn) {
    if (direction < 0 && EvaluateElements(t, y)) {
      TurnContactHistory(model_, data_, events_[k].segment);
      Invalidate();
    }
    return EventEffect::kModeChanged;
  }
  if (events_[k].kind == EventKind::kJointTurn) {
    if (direction < 0 && EvaluateElements(t, y)) {
      TurnJointHistory(model_, data_, events_[k].segment);
      Invalidate();
    }
    return EventEffect::kModeChanged;
  }
  if (events_[k].kind == EventKind::kContactImpulse && direction > 0) {
    data_.contacts.engaged[events_[k].segment] = 0;  // apart: the next touch is an impact
    return EventEffect::kModeChanged;
  }
  Load(t, y);
  // The kinetic energy the impulse adds (or, mostly, takes), for the energy balance.
  ComputeKinematics(model_, data_);
  const double before = KineticEnergy(model_, data_);
  std::copy(data_.v.begin(), data_.v.end(), event_v_.begin());
  ApplyEvent(k, direction);
  ComputeKinematics(model_, data_);
  data_.energy.impulses += KineticEnergy(model_, data_) - before;
  Store(y);
  // Impulses change velocities only.
  return std::equal(data_.v.begin(), data_.v.end(), event_v_.begin()) ? EventEffect::kModeChanged
                                                                      : EventEffect::kStateChanged;
}

void MultibodySystem::ApplyEvent(std::size_t k, int direction) {
  if (events_[k].kind == EventKind::kContactImpulse) {
    if (direction < 0) ApplyContactImpulse(model_, data_, events_[k].segment);  // touching
    return;
  }
  const std::size_t s = events_[k].segment;
  const auto qa = static_cast<std::size_t>(model_.q_address[s]);
  const auto va = static_cast<std::size_t>(model_.v_address[s]);
  const double restitution = model_.joint_restitution[s];
  switch (events_[k].kind) {
    case EventKind::kStop:
    case EventKind::kTwistStop: {
      if (direction > 0) break;  // moving back into range: nothing to do
      SmallMatrix direction_vector;
      if (model_.joint_kind[s] == JointKind::kBall) {
        // The direction that opens the stop: the flexure axis (or z for twist), in the
        // segment frame, where the ball joint's velocities live.
        const Eigen::Quaterniond rotation = QuaternionAt(data_.q, qa).normalized();
        const SwingTwist angles = DecomposeSwingTwist(rotation);
        Vec3 axis = events_[k].kind == EventKind::kStop
                        ? Vec3(rotation.toRotationMatrix().transpose() * angles.flexure_axis)
                        : Vec3(Vec3::UnitZ() * (angles.twist >= 0 ? 1.0 : -1.0));
        axis = model_.joint_frame_in_child[s] * axis;
        direction_vector = axis;
      } else {
        direction_vector = SmallMatrix::Constant(1, 1, data_.q[qa] >= 0 ? 1.0 : -1.0);
      }
      // Only an impact into the stop rebounds.
      double closing = 0.0;
      for (Eigen::Index d = 0; d < direction_vector.rows(); ++d) {
        closing += direction_vector(d, 0) * data_.v[va + static_cast<std::size_t>(d)];
      }
      if (closing <= 0) break;
      ApplyJointImpulse(s, direction_vector, SmallVector::Constant(1, -restitution * closing));
      break;
    }
    case EventKind::kLock: {
      if (direction < 0) break;
      const std::uint8_t lockable = LockableAxes(s);
      if (data_.locked[s] & lockable) {
        data_.locked[s] = static_cast<std::uint8_t>(data_.locked[s] & ~lockable);  // unlock
        break;
      }
      LockJoint(s);
      break;
    }
    case EventKind::kLockLower:
      if (direction > 0 && (data_.locked[s] & LockableAxes(s)) == 0) LockJoint(s);
      break;
    case EventKind::kContactImpulse:
    case EventKind::kContactTouch:
    case EventKind::kContactTurn:
    case EventKind::kContactKink:
    case EventKind::kJointTurn:
    case EventKind::kJointKink:
    case EventKind::kBelt:
    case EventKind::kAirbagFull:
    case EventKind::kAirbagInflow:
    case EventKind::kAirbagVent:
      break;
  }
}

void MultibodySystem::LockJoint(std::size_t s) {
  // A plastic impulse stops the joint's relative motion on the axes that lock.
  const auto va = static_cast<std::size_t>(model_.v_address[s]);
  int axes[6];
  const int count = ActiveAxes(model_, s, data_.locked[s], axes);
  SmallMatrix directions = SmallMatrix::Zero(model_.v_count[s], count);
  for (int c = 0; c < count; ++c) directions(axes[c], c) = 1.0;
  ApplyJointImpulse(s, directions, SmallVector::Zero(count));
  data_.locked[s] = static_cast<std::uint8_t>(data_.locked[s] | LockableAxes(s));
  for (int c = 0; c < count; ++c) data_.v[va + static_cast<std::size_t>(axes[c])] = 0.0;
}

std::string MultibodySystem::FailureReason() const {
  if (failure_.where.empty()) return failure_.cause;
  return fmt::format("{}: {}", failure_.where, failure_.cause);
}

}  // namespace sled::runtime
