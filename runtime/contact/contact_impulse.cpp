#include "runtime/contact/contact_impulse.h"

#include <algorithm>

#include "runtime/contact/contact_forces.h"
#include "runtime/dynamics/dynamics.h"
#include "runtime/forces/forces.h"

namespace sled::runtime {
namespace {

// Impacts slower than this [m/s] get no impulse: the force law takes them, so a bouncing body
// comes to rest on its contact instead of bouncing ever more often (with restitution e the
// bounces of a dropped body would otherwise never end: a Zeno sequence of events).
constexpr double kImpulseSpeed = 1e-2;

// n . (velocity of the first surface - velocity of the second) at the point: > 0 separating.
double SeparationSpeed(const Model& model, const Data& data, std::size_t k, const Vec3& point,
                       const Vec3& normal) {
  return normal.dot(SurfacePointVelocity(model, data, k, 0, point) -
                    SurfacePointVelocity(model, data, k, 1, point));
}

}  // namespace

bool ApplyContactImpulse(const Model& model, Data& data, std::size_t k) {
  const ContactTable& table = model.contacts;
  ContactState& state = data.contacts;
  ComputeKinematics(model, data);
  PlaceContactSurfaces(model, data);
  const ContactGeometry g = PairGeometry(model, data, k);
  const double closing = -SeparationSpeed(model, data, k, g.point, g.normal);
  state.engaged[k] = 1;  // the force law takes the contact, until the event of separation
  if (!(closing > kImpulseSpeed)) return true;

  // The velocity response to a unit impulse along the normal (on the first surface; its
  // opposite on the second): M^-1 J^T n, from one articulated-body pass without velocity.
  std::copy(data.v.begin(), data.v.end(), state.saved_v.begin());
  std::fill(data.v.begin(), data.v.end(), 0.0);
  ComputeKinematics(model, data);
  for (auto& wrench : data.external) wrench.setZero();
  std::fill(data.generalized_force.begin(), data.generalized_force.end(), 0.0);
  const auto first = static_cast<std::size_t>(table.pair_first[k]);
  const FrameRef first_frame = table.ellipsoid_frame[first];
  const auto second = static_cast<std::size_t>(table.pair_second[k]);
  const FrameRef second_frame = table.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid
                                    ? table.plane_frame[second]
                                    : table.ellipsoid_frame[second];
  if (first_frame.kind == FrameRef::Kind::kSegment) {
    AddPointForce(data, static_cast<std::size_t>(first_frame.index), g.point, g.normal);
  }
  if (second_frame.kind == FrameRef::Kind::kSegment) {
    AddPointForce(data, static_cast<std::size_t>(second_frame.index), g.point, -g.normal);
  }
  Failure ignored;
  const bool solved = ComputeAccelerations(model, data, &ignored);
  std::copy(data.vdot.begin(), data.vdot.end(), state.response.begin());

  // The separation speed one unit of impulse adds: with the response as velocity, less what a
  // moving vehicle contributes on its own (data.v is zero here).
  const double vehicles_alone = SeparationSpeed(model, data, k, g.point, g.normal);
  std::copy(state.response.begin(), state.response.end(), data.v.begin());
  ComputeKinematics(model, data);
  const double per_unit = SeparationSpeed(model, data, k, g.point, g.normal) - vehicles_alone;

  const double restitution = table.pair_restitution[k];
  const double impulse = solved && per_unit > 0 ? (1.0 + restitution) * closing / per_unit : 0.0;
  for (std::size_t i = 0; i < data.v.size(); ++i) {
    data.v[i] = state.saved_v[i] + impulse * state.response[i];
  }
  // Surfaces that rebound part at once: the force law waits for their next touch, an impact
  // of its own. (Their separation is not an event: it happens where this one is.)
  if (impulse > 0 && restitution > 0) state.engaged[k] = 0;
  ComputeKinematics(model, data);
  return solved && per_unit > 0;
}

}  // namespace sled::runtime
