// The initial state q0, v0. Reference segments take their position, orientation and velocities
// from `initial` (of the body, for its first reference segment, or of the segment); joints take
// their angles. A segment that hangs from a joint may be given an angular velocity: the joint's
// rates are chosen to give it, as far as the joint's free axes allow.
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <Eigen/QR>

#include "compiler/lower/lowering.h"

namespace sled::compiler::lowering {
namespace {

using runtime::JointKind;

struct Given {
  std::optional<Vec3> value;
  SourceRange range;
  void Set(const std::optional<Vec3>& v, const SourceRange& r) {
    if (!v) return;
    value = v;
    range = r;
  }
};

// The initial conditions of one segment, merged in declaration order (later ones win).
struct SegmentStart {
  Given position;
  Given orientation;
  Given velocity;
  Given angular_velocity;
};

// Rz(a0) Ry(a1) Rx(a2) as a quaternion with w >= 0: yaw, pitch, roll for orientations and
// precession, nutation, spin for ball joints.
Eigen::Quaterniond QuaternionZyx(const Vec3& a) {
  Eigen::Quaterniond q = Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitX());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q;
}

// Columns: the child joint frame's angular velocity per unit precession, nutation and spin rate
// (the runtime's EulerRates for R_J = Rz(precession) Ry(nutation) Rx(spin)).
runtime::Mat3 EulerRates(double nutation, double spin) {
  const double sn = std::sin(nutation), cn = std::cos(nutation);
  const double ss = std::sin(spin), cs = std::cos(spin);
  runtime::Mat3 rates;
  rates.col(0) << -sn, ss * cn, cs * cn;
  rates.col(1) << 0, cs, -ss;
  rates.col(2) << 1, 0, 0;
  return rates;
}

void PutQuaternion(std::vector<double>& q, std::size_t at, const Eigen::Quaterniond& quaternion) {
  q[at] = quaternion.w();
  q[at + 1] = quaternion.x();
  q[at + 2] = quaternion.y();
  q[at + 3] = quaternion.z();
}

// The signed angle of `rotation` about the unit `axis`, and how much of it turns about other
// axes (the norm of the rest of its vector part): planar symmetry keeps only the first.
struct AxisAngle {
  double angle = 0.0;
  double off_axis = 0.0;
};
AxisAngle AngleAbout(const Eigen::Quaterniond& rotation, const runtime::Vec3& axis) {
  const double along = rotation.vec().dot(axis);
  return {2.0 * std::atan2(along, rotation.w()), (rotation.vec() - along * axis).norm()};
}

// Tells when planar symmetry drops part of an initial condition.
void NoteOffPlane(Lowering& lowering, const SourceRange& range, double off_plane,
                  const std::string& what) {
  if (!(off_plane > 1e-9)) return;
  lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, range,
                   fmt::format("planar symmetry: the {} leaves the xz plane; only its "
                               "in-plane part is kept",
                               what));
}

// The angular velocity of a held root's base at the start (ground frame): its vehicle's.
runtime::Vec3 BaseAngularVelocity(const runtime::Model& model, const runtime::FrameRef& base) {
  if (base.kind != runtime::FrameRef::Kind::kVehicle) return runtime::Vec3::Zero();
  return model.vehicle_angular_velocity[static_cast<std::size_t>(base.index)];
}

}  // namespace

void LowerInitialState(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  runtime::Model& model = lowering.model();
  std::vector<SegmentStart> starts(scenario.segments.size());
  std::vector<std::optional<Vec3>> angles(scenario.joints.size());
  for (const InitialCondition& initial : scenario.initial_conditions) {
    int target = -1;
    switch (initial.kind) {
      case InitialCondition::Kind::kBody: {
        const Body& body = scenario.bodies.at(static_cast<std::size_t>(initial.index));
        if (!body.reference_segments.empty()) target = body.reference_segments.front();
        break;
      }
      case InitialCondition::Kind::kSegment:
        target = initial.index;
        break;
      case InitialCondition::Kind::kJoint: {
        // A null joint's angles are refused by the checker (E0421).
        if (!initial.joint_angles || lowering.joint(initial.index).type == JointType::kNull) break;
        angles[static_cast<std::size_t>(initial.index)] = initial.joint_angles;
        break;
      }
      case InitialCondition::Kind::kVehicle:
        break;  // LowerScene
    }
    if (target < 0) continue;
    SegmentStart& start = starts[static_cast<std::size_t>(target)];
    lowering.segment(target);
    start.position.Set(initial.position, initial.range);
    start.orientation.Set(initial.orientation, initial.range);
    start.velocity.Set(initial.velocity, initial.range);
    start.angular_velocity.Set(initial.angular_velocity, initial.range);
  }

  model.q0.assign(static_cast<std::size_t>(model.nq), 0.0);
  model.v0.assign(static_cast<std::size_t>(model.nv), 0.0);
  // Angular velocity of each segment in the world frame, to give a child's relative rate.
  std::vector<runtime::Vec3> w_world(model.nsegment(), runtime::Vec3::Zero());
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const int old = lowering.old_index[s];
    const SegmentStart& start = starts[static_cast<std::size_t>(old)];
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const JointKind kind = model.joint_kind[s];
    if (kind == JointKind::kFree) {
      const Vec3 p = start.position.value.value_or(Vec3{});
      const Eigen::Quaterniond quaternion = QuaternionZyx(start.orientation.value.value_or(Vec3{}));
      for (std::size_t k = 0; k < 3; ++k) model.q0[qa + k] = p[k];
      PutQuaternion(model.q0, qa + 3, quaternion);
      // Given in the world frame; the state holds them in the segment frame.
      const runtime::Mat3 r_ws = quaternion.toRotationMatrix();
      w_world[s] = ToEigen(start.angular_velocity.value.value_or(Vec3{}));
      const runtime::Vec3 w_s = r_ws.transpose() * w_world[s];
      const runtime::Vec3 v_s = r_ws.transpose() * ToEigen(start.velocity.value.value_or(Vec3{}));
      for (std::size_t k = 0; k < 3; ++k) {
        model.v0[va + k] = w_s[k];
        model.v0[va + 3 + k] = v_s[k];
      }
      continue;
    }

    if (kind == JointKind::kPlanar) {
      // x, z and the turn about y, with their rates, all in ground axes.
      const Vec3 p = start.position.value.value_or(Vec3{});
      const AxisAngle turn = AngleAbout(QuaternionZyx(start.orientation.value.value_or(Vec3{})),
                                        runtime::Vec3::UnitY());
      const Vec3 v = start.velocity.value.value_or(Vec3{});
      const Vec3 w = start.angular_velocity.value.value_or(Vec3{});
      model.q0[qa] = p[0];
      model.q0[qa + 1] = p[2];
      model.q0[qa + 2] = turn.angle;
      model.v0[va] = v[0];
      model.v0[va + 1] = v[2];
      model.v0[va + 2] = w[1];
      w_world[s] = runtime::Vec3(0.0, w[1], 0.0);
      NoteOffPlane(lowering, start.position.range, std::abs(p[1]),
                   fmt::format("initial position of `{}`", model.segment_name[s]));
      NoteOffPlane(lowering, start.orientation.range, turn.off_axis,
                   fmt::format("initial orientation of `{}`", model.segment_name[s]));
      NoteOffPlane(lowering, start.velocity.range, std::abs(v[1]),
                   fmt::format("initial velocity of `{}`", model.segment_name[s]));
      NoteOffPlane(lowering, start.angular_velocity.range, std::hypot(w[0], w[2]),
                   fmt::format("initial angular velocity of `{}`", model.segment_name[s]));
      continue;
    }

    if (lowering.joint_above[s] < 0 && kind == JointKind::kPin) {
      // A held root under planar symmetry: the turn about the plane's normal.
      const runtime::Mat3 r_ws =
          QuaternionZyx(start.orientation.value.value_or(Vec3{})).toRotationMatrix();
      const runtime::FrameRef& base = model.segment_base[s];
      const runtime::Mat3 r_wb =
          base.kind == runtime::FrameRef::Kind::kVehicle
              ? ToEigen(lowering.poses.vehicles[static_cast<std::size_t>(base.index)].rotation)
              : runtime::Mat3::Identity();
      const runtime::Vec3& axis = model.joint_axis[s];
      const AxisAngle turn = AngleAbout(Eigen::Quaterniond(r_wb.transpose() * r_ws), axis);
      model.q0[qa] = turn.angle;
      const runtime::Vec3 w_base = BaseAngularVelocity(model, base);
      // A welded root (its joint locked for good) turns with its base.
      const bool welded = model.joint_locked[s] != 0;
      const runtime::Vec3 w =
          start.angular_velocity.value && !welded ? ToEigen(*start.angular_velocity.value) : w_base;
      model.v0[va] = (r_wb * axis).dot(w - w_base);
      w_world[s] = w_base + model.v0[va] * (r_wb * axis);
      NoteOffPlane(lowering, start.orientation.range, turn.off_axis,
                   fmt::format("initial orientation of `{}`", model.segment_name[s]));
      NoteOffPlane(lowering, start.angular_velocity.range, (w - w_world[s]).norm(),
                   fmt::format("initial angular velocity of `{}`", model.segment_name[s]));
      continue;
    }

    if (lowering.joint_above[s] < 0) {
      // A root held at a base point by a ball joint: its orientation relative to the base.
      const runtime::Mat3 r_ws =
          QuaternionZyx(start.orientation.value.value_or(Vec3{})).toRotationMatrix();
      const runtime::FrameRef& base = model.segment_base[s];
      const runtime::Mat3 r_wb =
          base.kind == runtime::FrameRef::Kind::kVehicle
              ? model.vehicle_orientation[static_cast<std::size_t>(base.index)]
              : runtime::Mat3::Identity();
      const Eigen::Quaterniond relative(r_wb.transpose() * r_ws);
      PutQuaternion(model.q0, qa,
                    relative.w() < 0 ? Eigen::Quaterniond(-relative.coeffs()) : relative);
      // The joint's rate is relative to the base: a root that is given no angular velocity
      // turns with its vehicle.
      const runtime::Vec3 w_base = BaseAngularVelocity(model, base);
      // A welded root (its joint locked for good) turns with its base.
      const bool welded = model.joint_locked[s] != 0;
      w_world[s] =
          start.angular_velocity.value && !welded ? ToEigen(*start.angular_velocity.value) : w_base;
      const runtime::Vec3 w_s = r_ws.transpose() * (w_world[s] - w_base);
      for (std::size_t k = 0; k < 3; ++k) model.v0[va + k] = w_s[k];
      continue;
    }
    const int j = lowering.joint_above[s];
    const Joint& joint = lowering.joint(j);
    const Vec3 a = angles[static_cast<std::size_t>(j)].value_or(Vec3{});
    switch (kind) {
      case JointKind::kBall:
        PutQuaternion(model.q0, qa, QuaternionZyx(a));
        break;
      case JointKind::kEuler:
        for (std::size_t k = 0; k < 3; ++k) model.q0[qa + k] = a[k];
        break;
      case JointKind::kPin:
        if (joint.type == JointType::kBall || joint.type == JointType::kEuler) {
          // A ball or Euler joint made a pin by planar symmetry: its angles' turn about the pin.
          const AxisAngle turn = AngleAbout(QuaternionZyx(a), model.joint_axis[s]);
          model.q0[qa] = turn.angle;
          NoteOffPlane(lowering, SourceRange{}, turn.off_axis,
                       fmt::format("initial angles of joint `{}`", joint.name));
        } else {
          model.q0[qa] = a[0];
        }
        break;
      case JointKind::kSlip:
        model.q0[qa] = a[0];
        break;
      case JointKind::kFree:
      case JointKind::kPlanar:
        break;
    }

    // The checker refuses a position, orientation or velocity here (E0421): the joint decides
    // them.
    const std::string& name = model.segment_name[s];
    // The joint's velocity columns: the segment's angular velocity relative to its parent, in
    // the segment frame, per unit rate of each free axis.
    const std::uint8_t locked = model.joint_locked[s];
    const runtime::Mat3& frame_in_child = model.joint_frame_in_child[s];
    Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> columns(3, 0);
    std::vector<int> axes;
    if (kind == JointKind::kBall && locked == 0) {
      columns = runtime::Mat3::Identity();
      axes = {0, 1, 2};
    } else if (kind == JointKind::kPin && locked == 0) {
      columns = frame_in_child * model.joint_axis[s];
      axes = {0};
    } else if (kind == JointKind::kEuler) {
      const runtime::Mat3 rates = frame_in_child * EulerRates(a[1], a[2]);
      for (int k = 0; k < 3; ++k) {
        if (locked & (1u << k)) continue;
        columns.conservativeResize(3, columns.cols() + 1);
        columns.col(columns.cols() - 1) = rates.col(k);
        axes.push_back(k);
      }
    }
    const int parent = model.segment_parent[s];
    const runtime::Mat3 r_ws =
        ToEigen(lowering.poses.segments[static_cast<std::size_t>(old)].rotation);
    if (start.angular_velocity.value) {
      const runtime::Vec3 target = ToEigen(*start.angular_velocity.value);
      const runtime::Vec3 w_relative =
          r_ws.transpose() * (target - w_world[static_cast<std::size_t>(parent)]);
      Eigen::VectorXd rates = Eigen::VectorXd::Zero(columns.cols());
      if (columns.cols() > 0) rates = columns.colPivHouseholderQr().solve(w_relative);
      for (std::size_t k = 0; k < axes.size(); ++k) {
        model.v0[va + static_cast<std::size_t>(axes[k])] = rates[static_cast<Eigen::Index>(k)];
      }
      const double miss = (columns * rates - w_relative).norm();
      if (!(miss <= 1e-9 * std::max(1.0, w_relative.norm()))) {
        lowering.AddNote(
            lang::DiagnosticKind::kSimulatedApproximately, start.angular_velocity.range,
            fmt::format("the initial angular velocity of `{}` is matched only in part: it "
                        "hangs from {} joint `{}`{}, which cannot turn it that way relative to "
                        "`{}`",
                        name, runtime::JointKindName(kind), joint.name,
                        locked != 0 ? " (locked)" : "",
                        model.segment_name[static_cast<std::size_t>(parent)]));
      }
    }
    runtime::Vec3 w_relative = runtime::Vec3::Zero();
    for (std::size_t k = 0; k < axes.size(); ++k) {
      w_relative += columns.col(static_cast<Eigen::Index>(k)) *
                    model.v0[va + static_cast<std::size_t>(axes[k])];
    }
    w_world[s] = w_world[static_cast<std::size_t>(parent)] + r_ws * w_relative;
  }
}

}  // namespace sled::compiler::lowering
