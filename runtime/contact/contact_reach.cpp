#include "runtime/contact/contact_reach.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "runtime/contact/contact_forces.h"
#include "runtime/dynamics/frame_motion.h"

namespace sled::runtime {
namespace {

// The acceleration of the frame-fixed point at the world position `point`.
Vec3 AccelerationAt(const FrameMotion& frame, const Vec3& point) {
  const Vec3 r = point - frame.origin;
  return frame.acceleration + frame.angular_acceleration.cross(r) +
         frame.angular_velocity.cross(frame.angular_velocity.cross(r));
}

// The acceleration bound is the one at the step start; the step may meet a larger one (another
// contact, a pulse's peak). This factor leaves room for it.
constexpr double kAccelerationMargin = 2.0;

// The time in which a gap closing at `speed` with `acceleration` (both >= 0) closes `reach`:
// the root of reach = speed h + acceleration h^2 / 2, in the form that does not cancel.
double TimeToClose(double reach, double speed, double acceleration) {
  const double denominator = speed + std::sqrt(speed * speed + 2.0 * acceleration * reach);
  return denominator > 0 ? 2.0 * reach / denominator : std::numeric_limits<double>::infinity();
}

double SmallestSemiAxis(const ContactTable& table, std::int32_t e) {
  return table.ellipsoid_semi_axes[static_cast<std::size_t>(e)].minCoeff();
}

bool IsPlanePair(const ContactTable& table, std::size_t k) {
  return table.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid;
}

// The height of pair k's ellipsoid centre over its plane (negative behind it).
double CenterHeight(const ContactTable& table, const ContactState& state, std::size_t k) {
  const auto p = static_cast<std::size_t>(table.pair_second[k]);
  const Vec3& center = state.ellipsoid_center[static_cast<std::size_t>(table.pair_first[k])];
  return state.plane_normal[p].dot(center - state.plane_origin[p]);
}

// Pair k (ellipsoid and plane) with the whole ellipsoid behind the plane over its parallelogram.
bool WhollyBehind(const ContactTable& table, const ContactState& state, std::size_t k) {
  const double height = CenterHeight(table, state, k);
  if (!(height < 0)) return false;
  const EllipsoidShape shape = ShapeOf(table, state, table.pair_first[k]);
  const PlaneShape plane = PlaneOf(state, table.pair_second[k]);
  double front = 0.0;  // how far the ellipsoid reaches towards the plane's front
  SupportPoint(shape, plane.normal, &front);
  if (height + front >= 0) return false;
  const auto [s, t] = ParallelogramCoordinates(plane, shape.center - height * plane.normal);
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

}  // namespace

double ContactStepLimit(const Model& model, const Data& data) {
  const ContactTable& table = model.contacts;
  const ContactState& state = data.contacts;
  double limit = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < table.npair(); ++k) {
    // Touching pairs are bounded too: the error test sees the force only at a step's stages,
    // and a step from the first touch long enough to put every stage past the ellipsoid (wholly
    // behind a plane, where the force is zero) sees none. A ball started 5 cm into its floor
    // (examples/numerics/initial_overlap.sled) fell back through it so at a tolerance of 1e-3.
    const double gap = std::max(state.gap[k], 0.0);
    const auto first = static_cast<std::size_t>(table.pair_first[k]);
    double depth = SmallestSemiAxis(table, table.pair_first[k]);
    const bool plane = IsPlanePair(table, k);
    if (plane && state.behind[k]) continue;  // behind a one-sided plane: never pushed
    if (!plane) depth = std::min(depth, SmallestSemiAxis(table, table.pair_second[k]));
    // The motion of the first surface's material points relative to the second's frame, at the
    // ellipsoid's centre; any point of the ellipsoid is within its bounding radius of it.
    const FrameMotion a = MotionWithAcceleration(data, SurfaceFrame(table, k, 0));
    const FrameMotion b = MotionWithAcceleration(data, SurfaceFrame(table, k, 1));
    const Vec3& center = state.ellipsoid_center[first];
    const Vec3 velocity = VelocityAt(a, center) - VelocityAt(b, center);
    const Vec3 acceleration = AccelerationAt(a, center) - AccelerationAt(b, center);
    const Vec3 spin = a.angular_velocity - b.angular_velocity;
    const double radius = table.ellipsoid_radius[first];
    double speed = 0.0;
    double closing_acceleration = 0.0;
    if (plane) {
      const Vec3& normal = state.plane_normal[static_cast<std::size_t>(table.pair_second[k])];
      speed = std::max(0.0, -normal.dot(velocity));
      closing_acceleration = std::max(0.0, -normal.dot(acceleration));
    } else {
      speed = velocity.norm();
      closing_acceleration = acceleration.norm();
    }
    // The ellipsoid's turning moves its surface by up to |spin| radius; the second frame's
    // turning adds the Coriolis term 2 |w_b| |v| to the gap's second derivative.
    speed += spin.norm() * radius;
    closing_acceleration +=
        ((a.angular_acceleration - b.angular_acceleration).norm() + spin.squaredNorm()) * radius +
        2.0 * b.angular_velocity.norm() * velocity.norm();
    const double reach = gap + kContactReachShare * depth;
    limit = std::min(limit, TimeToClose(reach, speed, kAccelerationMargin * closing_acceleration));
  }
  return limit;
}

void StartContactReach(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  for (std::size_t k = 0; k < table.npair(); ++k) {
    data.contacts.behind[k] = IsPlanePair(table, k) && WhollyBehind(table, data.contacts, k);
  }
}

void WatchContactReach(const Model& model, Data& data) {
  const ContactTable& table = model.contacts;
  ContactState& state = data.contacts;
  for (std::size_t k = 0; k < table.npair(); ++k) {
    ContactLawOverrun& record = state.overrun[k];
    double depth = SmallestSemiAxis(table, table.pair_first[k]);
    if (IsPlanePair(table, k)) {
      const bool behind = WhollyBehind(table, state, k);
      if (behind && !state.behind[k] && record.behind_time < 0) record.behind_time = data.time;
      state.behind[k] = behind ? 1 : 0;
    } else {
      depth = std::min(depth, SmallestSemiAxis(table, table.pair_second[k]));
    }
    if (state.deflection[k] > depth) {
      if (record.deep_time < 0) record.deep_time = data.time;
      record.deepest = std::max(record.deepest, state.deflection[k]);
      record.semi_axis = depth;
    }
  }
}

std::string ContactPairName(const ContactTable& table, std::size_t k) {
  const auto second = static_cast<std::size_t>(table.pair_second[k]);
  const std::string& other =
      IsPlanePair(table, k) ? table.plane_name[second] : table.ellipsoid_name[second];
  return fmt::format("contact `{}` with `{}`",
                     table.ellipsoid_name[static_cast<std::size_t>(table.pair_first[k])], other);
}

std::vector<std::string> ContactReachWarnings(const Model& model, const Data& data) {
  std::vector<std::string> warnings;
  const ContactTable& table = model.contacts;
  for (std::size_t k = 0; k < table.npair(); ++k) {
    const ContactLawOverrun& record = data.contacts.overrun[k];
    if (record.deep_time >= 0) {
      warnings.push_back(fmt::format(
          "warning[W0010]: {}: the deflection passed the smallest semi-axis ({:.4g} mm) at t = "
          "{:.6g} s and reached {:.4g} mm; the force law does not describe so deep a contact "
          "(help: a stiffer force function, or larger ellipsoids; docs/diagnostics/W0010.md)",
          ContactPairName(table, k), 1e3 * record.semi_axis, record.deep_time,
          1e3 * record.deepest));
    }
    if (record.behind_time >= 0) {
      warnings.push_back(fmt::format(
          "warning[W0010]: {}: the ellipsoid went wholly behind the plane at t = {:.6g} s, "
          "where the contact gives no force (help: a stiffer force function, or larger "
          "ellipsoids; docs/diagnostics/W0010.md)",
          ContactPairName(table, k), record.behind_time));
    }
  }
  return warnings;
}

}  // namespace sled::runtime
