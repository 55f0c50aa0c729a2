// The CVS force–deflection law of a contact: loading along the contact's function, unloading
// along a curve that returns only part of the stored energy and ends at a permanent deflection.
// The curve is fixed by the largest deflection reached, which is committed after accepted steps
// only (CommitDeflection), so the force within a step is a function of the state alone.
#pragma once

#include <cstdint>

namespace sled::runtime {

struct FunctionTable;

// The unloading curve from the largest deflection so far: zero at `permanent`, `max_force` at
// `max_deflection`, F = max_force x^exponent in between, with x the fraction of the way from the
// permanent deflection to the largest one. `max_deflection` 0: never loaded.
struct LoadingHistory {
  double max_deflection = 0.0;
  double max_force = 0.0;
  double permanent = 0.0;
  double exponent = 1.0;
};

// True when the function's unloading differs from its loading (energy loss or permanent set):
// only such contacts keep a history.
bool HasHysteresis(const FunctionTable& functions, std::int32_t function);

// The elastic (non-damping) contact force at a deflection > 0: the loading function beyond the
// largest deflection so far, the unloading curve below it.
double ElasticForce(const FunctionTable& functions, std::int32_t function, double deflection,
                    const LoadingHistory& history);

// The history after an accepted step that ended at `deflection`: a new largest deflection fixes a
// new unloading curve, whose area is (1 - energy_loss) of the loading work up to it and which
// ends at permanent_set times the largest deflection.
LoadingHistory CommitDeflection(const FunctionTable& functions, std::int32_t function,
                                double deflection, const LoadingHistory& history);

}  // namespace sled::runtime
