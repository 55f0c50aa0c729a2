#include "compiler/check/initial_pose.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "lang/geometry/small_vectors.h"
#include "runtime/contact/contact_geometry.h"

namespace sled::compiler {
namespace {

using lang::geometry::Add;
using lang::geometry::Apply;
using lang::geometry::ApplyTransposed;
using lang::geometry::Multiply;
using lang::geometry::Sub;
using lang::geometry::Transpose;

Mat3 RotationAbout(const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return {{{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
           {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
           {t * x * z - s * y, t * y * z + s * x, t * z * z + c}}};
}

// The rotation a joint's angles make, from the child's joint frame to the parent's (R_J, as the
// runtime): about the pin axis for pin joints (given in the parent segment, so turned into the
// joint frame first); none for slip joints, which slide; and precession about z, nutation about
// the new y, spin about the new x (z-y-x) for ball and Euler joints.
Mat3 JointRotation(const Joint& joint, const Vec3& angles) {
  if (joint.type == JointType::kSlip) return Mat3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  if (joint.type == JointType::kPin) {
    return RotationAbout(
        ApplyTransposed(RotationFromYawPitchRoll(joint.axes_in_parent), joint.axis), angles[0]);
  }
  return Multiply(
      Multiply(RotationAbout({0, 0, 1}, angles[0]), RotationAbout({0, 1, 0}, angles[1])),
      RotationAbout({1, 0, 0}, angles[2]));
}

Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

int HoldingConstraintOf(const CheckedScenario& scenario, int segment) {
  // A weld first (it holds the orientation too), then a fixed point.
  for (const Constraint::Kind kind : {Constraint::Kind::kWelded, Constraint::Kind::kFixedPoint}) {
    for (std::size_t c = 0; c < scenario.constraints.size(); ++c) {
      const Constraint& constraint = scenario.constraints[c];
      if (constraint.kind != kind) continue;
      const bool first = constraint.first.kind == FrameRef::Kind::kSegment &&
                         constraint.first.index == segment &&
                         constraint.second.kind != FrameRef::Kind::kSegment;
      const bool second = constraint.second.kind == FrameRef::Kind::kSegment &&
                          constraint.second.index == segment &&
                          constraint.first.kind != FrameRef::Kind::kSegment;
      if (first || second) return static_cast<int>(c);
    }
  }
  return -1;
}

Mat3 RotationFromYawPitchRoll(const Vec3& ypr) {
  const double cy = std::cos(ypr[0]), sy = std::sin(ypr[0]);
  const double cp = std::cos(ypr[1]), sp = std::sin(ypr[1]);
  const double cr = std::cos(ypr[2]), sr = std::sin(ypr[2]);
  const Mat3 yaw{{{cy, -sy, 0}, {sy, cy, 0}, {0, 0, 1}}};
  const Mat3 pitch{{{cp, 0, sp}, {0, 1, 0}, {-sp, 0, cp}}};
  const Mat3 roll{{{1, 0, 0}, {0, cr, -sr}, {0, sr, cr}}};
  return Multiply(Multiply(yaw, pitch), roll);
}

Pose InitialPoses::Of(const FrameRef& frame) const {
  if (frame.kind == FrameRef::Kind::kSegment && frame.index >= 0 &&
      static_cast<std::size_t>(frame.index) < segments.size()) {
    return segments[static_cast<std::size_t>(frame.index)];
  }
  if (frame.kind == FrameRef::Kind::kVehicle && frame.index >= 0 &&
      static_cast<std::size_t>(frame.index) < vehicles.size()) {
    return vehicles[static_cast<std::size_t>(frame.index)];
  }
  return Pose{};
}

namespace {

// The holding constraint's point in the base and in the root, and the base.
struct Hold {
  FrameRef base;
  Vec3 in_base{};
  Vec3 in_root{};
};
std::optional<Hold> HoldOf(const CheckedScenario& scenario, int root) {
  const int c = HoldingConstraintOf(scenario, root);
  if (c < 0) return std::nullopt;
  const Constraint& constraint = scenario.constraints[static_cast<std::size_t>(c)];
  const bool root_first = constraint.first.kind == FrameRef::Kind::kSegment;
  return Hold{root_first ? constraint.second : constraint.first,
              root_first ? constraint.point_in_second : constraint.point_in_first,
              root_first ? constraint.point_in_first : constraint.point_in_second};
}

}  // namespace

std::optional<Vec3> HeldRootPosition(const CheckedScenario& scenario, const InitialPoses& poses,
                                     int root) {
  const std::optional<Hold> hold = HoldOf(scenario, root);
  if (!hold) return std::nullopt;
  const Pose base = poses.Of(hold->base);
  const Pose& segment = poses.segments[static_cast<std::size_t>(root)];
  return Sub(Add(base.position, Apply(base.rotation, hold->in_base)),
             Apply(segment.rotation, hold->in_root));
}

std::optional<Vec3> HeldPoint(const CheckedScenario& scenario, const InitialPoses& poses,
                              int root) {
  const std::optional<Hold> hold = HoldOf(scenario, root);
  if (!hold) return std::nullopt;
  const Pose base = poses.Of(hold->base);
  return Add(base.position, Apply(base.rotation, hold->in_base));
}

std::optional<Vec3> HeldRootVelocity(const CheckedScenario& scenario, const InitialPoses& poses,
                                     int root, const Vec3& angular_velocity) {
  const std::optional<Hold> hold = HoldOf(scenario, root);
  if (!hold) return std::nullopt;
  const Pose base = poses.Of(hold->base);
  const Pose& segment = poses.segments[static_cast<std::size_t>(root)];
  const Vec3 pivot = *HeldPoint(scenario, poses, root);
  Vec3 pivot_velocity{};
  if (hold->base.kind == FrameRef::Kind::kVehicle) {
    const auto v = static_cast<std::size_t>(hold->base.index);
    pivot_velocity = Add(poses.vehicle_velocities[v],
                         Cross(poses.vehicle_angular_velocities[v], Sub(pivot, base.position)));
  }
  return Add(pivot_velocity, Cross(angular_velocity, Sub(segment.position, pivot)));
}

InitialPoses ComputeInitialPoses(const CheckedScenario& scenario) {
  InitialPoses poses;
  poses.segments.resize(scenario.segments.size());
  poses.vehicles.resize(scenario.vehicles.size());
  poses.vehicle_velocities.resize(scenario.vehicles.size());
  poses.vehicle_angular_velocities.resize(scenario.vehicles.size());
  for (std::size_t v = 0; v < scenario.vehicles.size(); ++v) {
    poses.vehicles[v].position = scenario.vehicles[v].position;
    poses.vehicles[v].rotation = RotationFromYawPitchRoll(scenario.vehicles[v].orientation);
    poses.vehicle_velocities[v] = scenario.vehicles[v].velocity;
  }
  // Reference segments take the initial conditions of their body or of themselves.
  for (const InitialCondition& initial : scenario.initial_conditions) {
    std::vector<int> targets;
    if (initial.kind == InitialCondition::Kind::kBody && initial.index >= 0) {
      const Body& body = scenario.bodies[static_cast<std::size_t>(initial.index)];
      if (!body.reference_segments.empty()) targets.push_back(body.reference_segments[0]);
    } else if (initial.kind == InitialCondition::Kind::kSegment) {
      targets.push_back(initial.index);
    } else if (initial.kind == InitialCondition::Kind::kVehicle && initial.index >= 0) {
      Pose& pose = poses.vehicles[static_cast<std::size_t>(initial.index)];
      if (initial.position) pose.position = *initial.position;
      if (initial.orientation) pose.rotation = RotationFromYawPitchRoll(*initial.orientation);
      const auto v = static_cast<std::size_t>(initial.index);
      if (initial.velocity) poses.vehicle_velocities[v] = *initial.velocity;
      if (initial.angular_velocity) poses.vehicle_angular_velocities[v] = *initial.angular_velocity;
    }
    for (int segment : targets) {
      if (segment < 0) continue;
      Pose& pose = poses.segments[static_cast<std::size_t>(segment)];
      if (initial.position) pose.position = *initial.position;
      if (initial.orientation) pose.rotation = RotationFromYawPitchRoll(*initial.orientation);
    }
  }
  // Walk each tree from its roots: a child's joint frame coincides with its parent's.
  std::vector<std::vector<int>> children(scenario.segments.size());
  for (std::size_t j = 0; j < scenario.joints.size(); ++j) {
    const Joint& joint = scenario.joints[j];
    if (joint.parent >= 0 && joint.child >= 0 && joint.type != JointType::kNull) {
      children[static_cast<std::size_t>(joint.parent)].push_back(static_cast<int>(j));
    }
  }
  // Initial joint angles, where given.
  std::vector<Vec3> joint_angles(scenario.joints.size(), Vec3{});
  for (const InitialCondition& initial : scenario.initial_conditions) {
    if (initial.kind == InitialCondition::Kind::kJoint && initial.joint_angles &&
        initial.index >= 0) {
      joint_angles[static_cast<std::size_t>(initial.index)] = *initial.joint_angles;
    }
  }
  std::vector<bool> placed(scenario.segments.size(), false);
  std::vector<int> stack;
  for (const Body& body : scenario.bodies) {
    for (int root : body.reference_segments) {
      if (root < 0 || placed[static_cast<std::size_t>(root)]) continue;
      placed[static_cast<std::size_t>(root)] = true;
      stack.push_back(root);
      // A root held at a point of the ground or a vehicle is where that point puts it, turned
      // as its initial orientation says (the runtime's joint to its base).
      if (const std::optional<Vec3> held = HeldRootPosition(scenario, poses, root)) {
        poses.segments[static_cast<std::size_t>(root)].position = *held;
      }
    }
  }
  while (!stack.empty()) {
    const int parent = stack.back();
    stack.pop_back();
    const Pose& parent_pose = poses.segments[static_cast<std::size_t>(parent)];
    for (int joint_index : children[static_cast<std::size_t>(parent)]) {
      const Joint& joint = scenario.joints[static_cast<std::size_t>(joint_index)];
      if (placed[static_cast<std::size_t>(joint.child)]) continue;
      Pose& child = poses.segments[static_cast<std::size_t>(joint.child)];
      const Mat3 joint_frame =
          Multiply(Multiply(parent_pose.rotation, RotationFromYawPitchRoll(joint.axes_in_parent)),
                   JointRotation(joint, joint_angles[static_cast<std::size_t>(joint_index)]));
      child.rotation =
          Multiply(joint_frame, Transpose(RotationFromYawPitchRoll(joint.axes_in_child)));
      child.position =
          Sub(Add(parent_pose.position, Apply(parent_pose.rotation, joint.location_in_parent)),
              Apply(child.rotation, joint.location_in_child));
      placed[static_cast<std::size_t>(joint.child)] = true;
      stack.push_back(joint.child);
    }
  }
  return poses;
}

double InitialPenetration(const CheckedScenario& scenario, const InitialPoses& poses,
                          const Contact& contact) {
  auto shape_of = [&](int index) {
    const Ellipsoid& e = scenario.ellipsoids[static_cast<std::size_t>(index)];
    const Pose frame = poses.Of(e.frame);
    runtime::EllipsoidShape shape;
    shape.center = ToEigen(Add(frame.position, Apply(frame.rotation, e.center)));
    shape.rotation = ToEigen(Multiply(frame.rotation, RotationFromYawPitchRoll(e.orientation)));
    shape.semi_axes = ToEigen(e.semi_axes);
    shape.degree = e.degree;
    shape.radius = runtime::BoundingRadius(shape.semi_axes, e.degree);
    return shape;
  };
  if (contact.first.kind != SurfaceRef::Kind::kEllipsoid) return 0.0;
  const runtime::EllipsoidShape first = shape_of(contact.first.index);
  if (contact.second.kind == SurfaceRef::Kind::kPlane) {
    const Plane& plane = scenario.planes[static_cast<std::size_t>(contact.second.index)];
    const Pose frame = poses.Of(plane.frame);
    std::array<runtime::Vec3, 3> p;
    for (std::size_t i = 0; i < 3; ++i) {
      p[i] = ToEigen(Add(frame.position, Apply(frame.rotation, plane.corners[i])));
    }
    runtime::PlaneShape shape{p[0], p[1] - p[0], p[2] - p[0], (p[1] - p[0]).cross(p[2] - p[0])};
    if (!(shape.normal.norm() > 0)) return 0.0;
    shape.normal.normalize();
    const runtime::ContactGeometry geometry = runtime::PlaneEllipsoid(shape, first);
    return geometry.touching && geometry.weight > 0 ? geometry.deflection : 0.0;
  }
  const runtime::EllipsoidShape second = shape_of(contact.second.index);
  runtime::Vec3 direction = second.center - first.center;
  const runtime::ContactGeometry geometry = runtime::EllipsoidEllipsoid(first, second, direction);
  return geometry.deflection;
}

}  // namespace sled::compiler
