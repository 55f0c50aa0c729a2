// The multibody equations as an OdeSystem for the integrators: state y = [q; v; w; W] (data.h):
// w the auxiliary states of force elements (an airbag's gas; Model::nw of them), W the energy
// balance's work integrals (runtime/run/energy.h), quadratures outside the error control. Joint
// stops with the impulse option, joint locking and first contacts with the impulse option are
// events: the integrator locates them inside the step, and HandleEvent applies the impulse or
// switches the joint's lock state. An airbag's gas equations switch when its envelope becomes full
// and when its inflator starts and stops: events too, which only stop the step there.
#pragma once

#include "runtime/dynamics/multibody_jacobian.h"
#include "runtime/integrate/ode.h"
#include "runtime/model/data.h"
#include "runtime/restraint/belt_events.h"

namespace sled::runtime {

class MultibodySystem : public OdeSystem {
 public:
  MultibodySystem(const Model& model, Data& data);

  std::size_t size() const override;
  std::size_t ControlledSize() const override;
  // The energy the work integrals are measured against: the largest of the kinetic energy and
  // the work integrals' magnitudes at (t, y), the terms the energy balance is reported against.
  double QuadratureScale(double t, std::span<const double> y) override;
  bool Derivative(double t, std::span<const double> y, std::span<double> dy) override;
  std::vector<std::size_t> VectorGroups() const override;
  // The force elements' stiffness and damping through the tree (multibody_jacobian.h).
  bool StructuredJacobianAt(double t, std::span<const double> y, std::span<const double> dy,
                            double step, StructuredJacobian& jacobian) override;
  std::size_t StructuredRank() const override;
  // Unit quaternions and loop constraints: y moved back onto its manifold (by the drift only).
  void Project(double t, std::span<double> y) override { ProjectState(t, y); }
  void ProjectState(double t, std::span<double> y);
  // After an accepted step: only watches the tables of contacts and belts for arguments past
  // their rows (runtime/forces/table_range.h), a report; every history changes at events.
  void CommitStep(double t, std::span<const double> y) override;
  // No step longer than an approaching contact pair allows (runtime/contact/contact_reach.h).
  // Called at every step start from a state just evaluated, it also watches each pair's
  // deflection against what its force law describes.
  double StepLimit(double t, std::span<const double> y) override;
  std::string FailureReason() const override;

  std::size_t EventCount() const override { return events_.size(); }
  // Three points inside each step when a joint locks or unlocks at a torque level: a constraint
  // torque passes a level and comes back within a step that its ends do not show.
  std::size_t EventSamples() const override;
  int EventDirection(std::size_t k) const override;
  void Events(double t, std::span<const double> y, std::span<double> g) override;
  EventEffect HandleEvent(std::size_t k, int direction, double t, std::span<double> y) override;

  // Loads (t, y) into data and runs Forward there, unless the last Forward was at exactly this
  // (t, y) with nothing changed since: then data already holds its results. An output row on a
  // step end reads the evaluation the step made there. False (failure() says why) on failure.
  bool Evaluate(double t, std::span<const double> y);
  // The same without the joints' torques and the accelerations (ForwardElements): what the
  // event functions and the histories' switches read. A later Evaluate at the same (t, y)
  // completes it.
  bool EvaluateElements(double t, std::span<const double> y);

  // Copies a state vector into data (q, v, w, the work integrals, time) and back.
  void Load(double t, std::span<const double> y);
  void Store(std::span<double> y) const;

  const Failure& failure() const { return failure_; }

 private:
  // kAirbagFull (an airbag's envelope becomes full, or stops being full) and kAirbagInflow (its
  // inflator starts or stops at `time`) switch the bag's mode where its gas equations change,
  // so no step straddles the jump in their rates. kAirbagVent: ATB's free bag's gauge pressure
  // passes its vent's opening pressure, where the vent's flow jumps; it only stops the step there.
  // kContactTouch: a pair without the impulse option touches or separates (its gap passes
  // zero), where the force law has a kink; it only stops the step there.
  // kContactTurn: a hysteretic contact pair's deflection turns while it loads (its largest
  // deflection, and with it the unloading curve, is set there). kBelt: a belt's junction sticks
  // or slips, a wrap re-anchors, a span's strain turns (runtime/restraint/belt_events.h).
  // kJointTurn: a hysteretic joint axis's angle turns while it loads
  // (runtime/forces/joint_hysteresis.h). kJointKink and kContactKink: a joint axis's angle or a
  // contact pair's deflection passes an inner row of its tabulated torque or force function,
  // where the slope jumps (a stop's table going from 0 to 30,000 N*m/rad, a foam's from 100 to
  // 167 N/mm); they only stop the step there, so that no step's stages straddle the kink.
  // kLock: a locked joint's constraint torque passes its unlock level, or an unlocked joint's
  // torque enters its lock band (|torque| < lock_below). For a joint with one axis (pin, slip)
  // the band has two edges, each a signed event function that no step can jump: kLock is the
  // upper edge (lock_below - torque), kLockLower the lower one (lock_below + torque). A swing
  // through the whole band within one step changes their signs at the step's ends, where
  // lock_below - |torque| was negative at both.
  enum class EventKind {
    kStop,
    kTwistStop,
    kLock,
    kLockLower,
    kContactImpulse,
    kContactTouch,
    kContactTurn,
    kContactKink,
    kJointTurn,
    kJointKink,
    kBelt,
    kAirbagFull,
    kAirbagInflow,
    kAirbagVent
  };
  struct Event {
    EventKind kind;
    std::size_t segment;   // the joint's (child) segment; for the contact events the pair; for
                           // kBelt the index into belt_events_; for kJointTurn the history;
                           // for the airbag events the bag
    double time = 0.0;     // kAirbagInflow
    double row = 0.0;      // kJointKink, kContactKink: the row's angle or deflection
    std::size_t axis = 0;  // kJointKink: the joint's axis (0..2, as Model::joint_function)
  };

  // The impulse or lock switch of event k, on data_'s state.
  void ApplyEvent(std::size_t k, int direction);
  // Sets v so that, for each direction d_i (a vector over the joint's velocity coordinates),
  // d_i . v_joint takes the value target_i, by a generalized impulse on the joint: the impulse
  // passes through the whole system, so momentum is kept.
  void ApplyJointImpulse(std::size_t segment, const SmallMatrix& directions,
                         const SmallVector& targets);
  // M^-1 tau for a generalized force on one joint's coordinates (an articulated-body pass with
  // no velocity and no applied force). Leaves data's velocities as they were.
  void UnitResponse(std::size_t segment, const SmallVector& force, std::vector<double>& response);
  // The torque the joint's characteristic applies (unlocked) or the constraint torque it carries
  // about its joint point (locked), as a magnitude.
  double JointTorqueMagnitude(std::size_t segment) const;
  // True when the joint's unlocked torque has one component with a sign (pin, slip): its lock
  // band then has the two signed edges kLock and kLockLower.
  bool HasSignedLockBand(std::size_t segment) const;
  // Locks the joint's lockable axes with a plastic impulse (kLock, kLockLower).
  void LockJoint(std::size_t segment);
  std::uint8_t LockableAxes(std::size_t segment) const;

  // Forgets the last evaluation (data was changed some other way).
  void Invalidate() { evaluated_ = false; }

  const Model& model_;
  Data& data_;
  Failure failure_;
  // The (t, y) of the last successful Forward, while data still holds its results.
  bool evaluated_ = false;
  bool accelerated_ = false;  // and its accelerations too (not only EvaluateElements)
  double evaluated_t_ = 0.0;
  std::vector<double> evaluated_y_;
  std::vector<Event> events_;
  std::vector<BeltEvent> belt_events_;
  bool reads_accelerations_ = false;            // a lock level's event (kLock) is among events_
  bool watches_tables_ = false;                 // some contact or belt has a tabulated function
  std::vector<double> saved_v_;                 // scratch for UnitResponse
  std::vector<double> event_v_;                 // velocities before an event's impulse
  std::vector<std::vector<double>> responses_;  // up to six unit responses, nv each
  MultibodyJacobian jacobian_;
};

}  // namespace sled::runtime
