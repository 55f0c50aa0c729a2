// The accumulated terms of a run's energy balance (runtime/run/energy.h computes the powers).
#pragma once

namespace sled::runtime {

// The accumulated terms of the balance; Data holds one (data.energy); the
// integrator carries the work integrals with the state.
struct EnergyBalance {
  double initial = 0.0;          // KE + PE at the start
  double element_work = 0.0;     // integral of SegmentPower::elements
  double constraint_work = 0.0;  // integral of SegmentPower::constraints
  double vehicle_work = 0.0;     // integral of the power elements deliver to vehicles
  double applied_work = 0.0;     // integral of the applied loads' power into the segments
  double impulses = 0.0;         // kinetic energy gained at impulsive events (negative: lost)

  // Work the force elements took from the segments and vehicles: stored + dissipated.
  double Absorbed() const { return -element_work - vehicle_work; }
  // Work the prescribed motion did on the occupant, through the elements and constraints.
  double PrescribedWork() const { return constraint_work - vehicle_work; }
  // KE + PE + absorbed - prescribed - applied - impulses - initial: zero for an exact
  // integration.
  double Residual(double kinetic, double potential) const {
    return kinetic + potential + Absorbed() - PrescribedWork() - applied_work - impulses - initial;
  }
};

}  // namespace sled::runtime
