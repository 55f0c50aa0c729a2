#include "runtime/contact/contact_forces.h"

#include <algorithm>
#include <cmath>

#include "runtime/contact/contact_reach.h"
#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/mirror.h"
#include "runtime/forces/atb_unloading.h"
#include "runtime/forces/force_deflection.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"
#include "runtime/forces/table_range.h"
#include "runtime/run/energy.h"

namespace sled::runtime {
namespace {

// Coulomb friction as a smooth function of the sliding speed: full friction well above this
// speed [m/s], so the equations stay Lipschitz for the integrators (as the joints' Coulomb
// torque). A static tangential load below full friction creeps at v0 atanh(load / (mu N)).
constexpr double kFrictionSpeed = 1e-2;

// Mirror symmetry: a contact between a segment that stands for its right twin and one that does
// not (in the plane) stands for the twin's contact too, which the Model leaves out; the segment
// in the plane feels both pushes, the second the mirror image (about y = mirror_plane_y) of the
// first, at the mirror image of its point.
void AddTwinContactForce(const Model& model, Data& data, const FrameRef& first,
                         const FrameRef& second, const Vec3& point, const Vec3& force_on_first) {
  if (first.kind != FrameRef::Kind::kSegment || second.kind != FrameRef::Kind::kSegment) return;
  const double first_weight = MirrorWeight(model, static_cast<std::size_t>(first.index));
  const double second_weight = MirrorWeight(model, static_cast<std::size_t>(second.index));
  if (first_weight == second_weight) return;
  const bool first_in_plane = first_weight < second_weight;
  const FrameRef& in_plane = first_in_plane ? first : second;
  const Vec3 force = first_in_plane ? force_on_first : Vec3(-force_on_first);
  const Vec3 image(point.x(), 2.0 * model.mirror_plane_y - point.y(), point.z());
  AddPointForce(data, static_cast<std::size_t>(in_plane.index), image, MirrorWorldVector(force));
}

// Pair k's geometry when the bounding spheres may meet; otherwise `touching` false and a gap
// that is a lower bound of the true one (positive).
ContactGeometry BoundedGeometry(const Model& model, Data& data, std::size_t k) {
  const ContactTable& table = model.contacts;
  const ContactState& state = data.contacts;
  const auto first = static_cast<std::size_t>(table.pair_first[k]);
  const Vec3& center = state.ellipsoid_center[first];
  const double radius = table.ellipsoid_radius[first];
  ContactGeometry apart;
  if (table.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid) {
    const auto p = static_cast<std::size_t>(table.pair_second[k]);
    const double height = state.plane_normal[p].dot(center - state.plane_origin[p]);
    // Above the plane by more than the bounding radius, or wholly behind it.
    if (height > radius || height < -radius) {
      apart.deflection = -std::abs(height) + radius;
      return apart;
    }
  } else {
    const auto second = static_cast<std::size_t>(table.pair_second[k]);
    const double distance = (state.ellipsoid_center[second] - center).norm();
    const double clearance = distance - radius - table.ellipsoid_radius[second];
    if (clearance > 0) {
      apart.deflection = -clearance;
      return apart;
    }
  }
  return PairGeometry(model, data, k);
}

// ATB's rate-dependent terms of pair k (FUNC_RATE_DEP): F2(d) F3(d') + F4(d'), d' the
// deflection rate; 0 for a pair without them (or a Model built without the arrays).
double RateDependentForce(const Model& model, std::size_t k, double deflection, double rate) {
  const ContactTable& table = model.contacts;
  double force = 0.0;
  if (k < table.pair_rate_scaled_force.size() && table.pair_rate_scaled_force[k] >= 0) {
    force += EvaluateFunction(model.functions, table.pair_rate_scaled_force[k], deflection) *
             EvaluateFunction(model.functions, table.pair_rate_scale[k], rate);
  }
  if (k < table.pair_rate_force.size() && table.pair_rate_force[k] >= 0) {
    force += EvaluateFunction(model.functions, table.pair_rate_force[k], rate);
  }
  return force;
}

}  // namespace

EllipsoidShape ShapeOf(const ContactTable& table, const ContactState& state, std::int32_t e) {
  const auto i = static_cast<std::size_t>(e);
  EllipsoidShape shape;
  shape.center = state.ellipsoid_center[i];
  shape.rotation = state.ellipsoid_rotation[i];
  shape.semi_axes = table.ellipsoid_semi_axes[i];
  shape.degree = table.ellipsoid_degree[i];
  shape.radius = table.ellipsoid_radius[i];
  return shape;
}

PlaneShape PlaneOf(const ContactState& state, std::int32_t p) {
  const auto i = static_cast<std::size_t>(p);
  return {state.plane_origin[i], state.plane_edge_u[i], state.plane_edge_v[i],
          state.plane_normal[i]};
}

FrameRef SurfaceFrame(const ContactTable& table, std::size_t k, int side) {
  if (side == 0) return table.ellipsoid_frame[static_cast<std::size_t>(table.pair_first[k])];
  const auto second = static_cast<std::size_t>(table.pair_second[k]);
  return table.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid
             ? table.plane_frame[second]
             : table.ellipsoid_frame[second];
}

void PlaceContactSurfaces(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  ContactState& state = data.contacts;
  for (std::size_t e = 0; e < table.nellipsoid(); ++e) {
    const FrameMotion frame = MotionOf(data, table.ellipsoid_frame[e]);
    state.ellipsoid_center[e] = frame.origin + frame.rotation * table.ellipsoid_center[e];
    state.ellipsoid_rotation[e] = frame.rotation * table.ellipsoid_axes[e];
  }
  for (std::size_t p = 0; p < table.nplane(); ++p) {
    const FrameMotion frame = MotionOf(data, table.plane_frame[p]);
    state.plane_origin[p] = frame.origin + frame.rotation * table.plane_origin[p];
    state.plane_edge_u[p] = frame.rotation * table.plane_edge_u[p];
    state.plane_edge_v[p] = frame.rotation * table.plane_edge_v[p];
    state.plane_normal[p] = frame.rotation * table.plane_normal[p];
  }
}

ContactGeometry PairGeometry(const Model& model, Data& data, std::size_t k) {
  const ContactTable& table = model.contacts;
  ContactState& state = data.contacts;
  const EllipsoidShape first = ShapeOf(table, state, table.pair_first[k]);
  if (table.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid) {
    return PlaneEllipsoid(PlaneOf(state, table.pair_second[k]), first);
  }
  return EllipsoidEllipsoid(first, ShapeOf(table, state, table.pair_second[k]),
                            state.search_direction[k]);
}

Vec3 SurfacePointVelocity(const Model& model, const Data& data, std::size_t k, int side,
                          const Vec3& point) {
  return VelocityAt(MotionOf(data, SurfaceFrame(model.contacts, k, side)), point);
}

void AccumulateContactForces(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  ContactState& state = data.contacts;
  PlaceContactSurfaces(model, data);
  for (std::size_t k = 0; k < table.npair(); ++k) {
    const ContactGeometry g = BoundedGeometry(model, data, k);
    // Off a plane's edges or behind it counts as apart, whatever the overlap of the surfaces.
    state.gap[k] = g.touching ? -g.deflection
                   : g.deflection <= 0
                       ? -g.deflection
                       : table.ellipsoid_radius[static_cast<std::size_t>(table.pair_first[k])];
    if (!g.touching || !state.engaged[k]) {
      state.deflection[k] = 0.0;
      state.normal_force[k] = 0.0;
      state.force[k].setZero();
      state.rate[k] = 0.0;
      continue;
    }
    // Relative motion of the material points at the contact point: the deflection rate and
    // the sliding velocity of the first surface on the second.
    const Vec3 relative = SurfacePointVelocity(model, data, k, 0, g.point) -
                          SurfacePointVelocity(model, data, k, 1, g.point);
    const double rate = -g.normal.dot(relative);
    const double elastic = LoadingUnloadingForce(model.functions, table.pair_function[k],
                                                 g.deflection, state.history[k]);
    const double depth = table.pair_damping_depth[k];
    const double ramp = depth > 0 ? std::min(1.0, g.deflection / depth) : 1.0;
    const double normal_force =
        std::max(0.0, g.weight * (elastic + RateDependentForce(model, k, g.deflection, rate) +
                                  ramp * table.pair_damping[k] * rate));
    Vec3 force = normal_force * g.normal;
    const double mu = table.pair_friction[k];
    if (mu > 0 && normal_force > 0) {
      const Vec3 sliding = relative - g.normal.dot(relative) * g.normal;
      const double speed = sliding.norm();
      // mu N tanh(speed / v0) against the sliding direction; tanh(x)/x -> 1 as x -> 0.
      const double per_speed = speed > 1e-12 * kFrictionSpeed
                                   ? std::tanh(speed / kFrictionSpeed) / speed
                                   : 1.0 / kFrictionSpeed;
      force -= mu * normal_force * per_speed * sliding;
    }
    state.deflection[k] = g.deflection;
    state.rate[k] = 0.0;
    // The rate the turn events watch: beyond the largest deflection, and everywhere under ATB's
    // law, which also turns below it.
    if (state.hysteresis[k] && (g.deflection > state.history[k].max_deflection ||
                                AtbReturnFunction(model.functions, table.pair_function[k]) >= 0)) {
      state.rate[k] = -g.normal.dot(SurfacePointVelocity(model, data, k, 0, g.deepest_first) -
                                    SurfacePointVelocity(model, data, k, 1, g.deepest_second));
    }
    state.normal_force[k] = normal_force;
    state.force[k] = force;
    state.point[k] = g.point;
    state.normal[k] = g.normal;
    const FrameRef first = SurfaceFrame(table, k, 0);
    const FrameRef second = SurfaceFrame(table, k, 1);
    // A left twin's contact stands for its right twin's too (for the vehicle's work).
    const FrameRef& body = first.kind == FrameRef::Kind::kSegment ? first : second;
    const double weight = body.kind == FrameRef::Kind::kSegment
                              ? MirrorWeight(model, static_cast<std::size_t>(body.index))
                              : 1.0;
    AddFrameForce(data, first, g.point, force, weight);
    AddFrameForce(data, second, g.point, -force, weight);
    AddTwinContactForce(model, data, first, second, g.point, force);
  }
}

void SetUpContacts(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  if (table.npair() == 0) return;
  ComputeKinematics(model, data);
  PlaceContactSurfaces(model, data);
  ContactState& state = data.contacts;
  StartContactReach(model, data);
  for (std::size_t k = 0; k < table.npair(); ++k) {
    if (!table.pair_impulse[k] && !state.hysteresis[k]) continue;
    const ContactGeometry g = BoundedGeometry(model, data, k);
    if (table.pair_impulse[k]) state.engaged[k] = g.touching ? 1 : 0;
    if (state.hysteresis[k] && g.touching) {
      UpdateLoadingHistory(model.functions, table.pair_function[k], g.deflection, state.history[k]);
    }
  }
  WatchContactTables(model, data);
}

void WatchContactTables(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  for (std::size_t k = 0; k < table.npair(); ++k) {
    const std::int32_t f = table.pair_function[k];
    if (model.functions.kind[static_cast<std::size_t>(f)] != FunctionTable::Kind::kTable) continue;
    // A deflection past the table's rows runs on its extrapolation: the run reports it.
    const ContactGeometry g = BoundedGeometry(model, data, k);
    if (g.touching) {
      RecordTableArgument(model.functions, f, data.time, g.deflection, data.table_watch.contact[k]);
    }
  }
}

void TurnContactHistory(const Model& model, Data& data, std::size_t k) {
  ContactState& state = data.contacts;
  // ATB's law also turns where the pair comes apart unloading (at zero deflection).
  const bool atb = AtbReturnFunction(model.functions, model.contacts.pair_function[k]) >= 0;
  if (!(state.deflection[k] > 0) && !atb) return;
  UpdateLoadingHistory(model.functions, model.contacts.pair_function[k], state.deflection[k],
                       state.history[k]);
}

}  // namespace sled::runtime
