#include "runtime/dynamics/joint.h"

#include <cmath>

namespace sled::runtime {

Mat3 EulerRotation(double precession, double nutation, double spin) {
  return (Eigen::AngleAxisd(precession, Vec3::UnitZ()) *
          Eigen::AngleAxisd(nutation, Vec3::UnitY()) * Eigen::AngleAxisd(spin, Vec3::UnitX()))
      .toRotationMatrix();
}

Mat3 EulerRates(double nutation, double spin) {
  const double sn = std::sin(nutation), cn = std::cos(nutation);
  const double ss = std::sin(spin), cs = std::cos(spin);
  Mat3 rates;
  rates.col(0) << -sn, ss * cn, cs * cn;  // precession: z seen from the spun, nutated frame
  rates.col(1) << 0, cs, -ss;             // nutation: y seen from the spun frame
  rates.col(2) << 1, 0, 0;                // spin: x
  return rates;
}

Eigen::Quaterniond QuaternionAt(std::span<const double> q, std::size_t address) {
  return Eigen::Quaterniond(q[address], q[address + 1], q[address + 2], q[address + 3]);
}

int ActiveAxes(const Model& model, std::size_t s, std::uint8_t locked, int axes[6]) {
  const int dof = model.v_count[s];
  int count = 0;
  switch (model.joint_kind[s]) {
    case JointKind::kFree:
      for (int k = 0; k < 6; ++k) axes[count++] = k;
      return count;
    case JointKind::kPlanar:
      for (int k = 0; k < 3; ++k) axes[count++] = k;
      return count;
    case JointKind::kEuler:
      for (int k = 0; k < 3; ++k) {
        if (!(locked & (1u << k))) axes[count++] = k;
      }
      return count;
    default:
      // Ball, pin and slip lock as a whole.
      if (locked != 0) return 0;
      for (int k = 0; k < dof; ++k) axes[count++] = k;
      return count;
  }
}

bool SubspaceDependsOnPosition(JointKind kind) {
  return kind == JointKind::kEuler || kind == JointKind::kPlanar;
}

void ComputeJointSubspace(const Model& model, std::size_t s, std::span<const double> q,
                          std::uint8_t locked, MotionSubspace& subspace) {
  int axes[6];
  const int count = ActiveAxes(model, s, locked, axes);
  subspace.resize(6, count);
  const Mat3& frame_child = model.joint_frame_in_child[s];
  const Vec3& point_child = model.joint_point_in_child[s];
  // Angular joint columns in the segment frame: the segment turns about the joint point, so its
  // centre of mass moves with p x w (p: the joint point in the segment frame).
  auto set_angular = [&](int column, const Vec3& axis_child) {
    subspace.col(column).head<3>() = axis_child;
    subspace.col(column).tail<3>() = point_child.cross(axis_child);
  };
  switch (model.joint_kind[s]) {
    case JointKind::kFree:
      subspace.setIdentity();
      return;
    case JointKind::kBall:
      // The velocity coordinates are w in the segment frame.
      for (int c = 0; c < count; ++c) set_angular(c, Vec3::Unit(axes[c]));
      return;
    case JointKind::kPin:
      if (count == 1) set_angular(0, frame_child * model.joint_axis[s]);
      return;
    case JointKind::kSlip:
      if (count == 1) {
        subspace.col(0).head<3>().setZero();
        subspace.col(0).tail<3>() = frame_child * model.joint_axis[s];
      }
      return;
    case JointKind::kPlanar: {
      // x and z in base axes, then the turn about y: the segment sees the base's x and z axes
      // turned by -angle.
      const auto qa = static_cast<std::size_t>(model.q_address[s]);
      const Mat3 base_to_child =
          Eigen::AngleAxisd(q[qa + 2], Vec3::UnitY()).toRotationMatrix().transpose();
      subspace.setZero();
      subspace.col(0).tail<3>() = base_to_child.col(0);
      subspace.col(1).tail<3>() = base_to_child.col(2);
      subspace(1, 2) = 1.0;
      return;
    }
    case JointKind::kEuler: {
      const auto qa = static_cast<std::size_t>(model.q_address[s]);
      const Mat3 rates = EulerRates(q[qa + 1], q[qa + 2]);
      for (int c = 0; c < count; ++c) set_angular(c, frame_child * rates.col(axes[c]));
      return;
    }
  }
}

void ComputeJointPose(const Model& model, std::size_t s, std::span<const double> q,
                      std::span<const double> v, std::uint8_t locked, JointMotion& motion) {
  const auto qa = static_cast<std::size_t>(model.q_address[s]);
  motion.translation.setZero();
  motion.bias.setZero();
  switch (model.joint_kind[s]) {
    case JointKind::kFree:
      motion.rotation = QuaternionAt(q, qa + 3).normalized().toRotationMatrix();
      motion.translation = Vec3(q[qa], q[qa + 1], q[qa + 2]);
      return;
    case JointKind::kBall:
      motion.rotation = QuaternionAt(q, qa).normalized().toRotationMatrix();
      return;
    case JointKind::kPin:
      motion.rotation = Eigen::AngleAxisd(q[qa], model.joint_axis[s]).toRotationMatrix();
      return;
    case JointKind::kSlip:
      motion.rotation.setIdentity();
      motion.translation = model.joint_axis[s] * q[qa];
      return;
    case JointKind::kPlanar: {
      // The subspace turns with the segment: Sdot qdot = -w x (the linear part).
      const auto va = static_cast<std::size_t>(model.v_address[s]);
      motion.rotation = Eigen::AngleAxisd(q[qa + 2], Vec3::UnitY()).toRotationMatrix();
      motion.translation = Vec3(q[qa], 0.0, q[qa + 1]);
      const Vec3 linear = motion.rotation.transpose() * Vec3(v[va], 0.0, v[va + 1]);
      motion.bias.tail<3>() = -Vec3(0.0, v[va + 2], 0.0).cross(linear);
      return;
    }
    case JointKind::kEuler: {
      const auto va = static_cast<std::size_t>(model.v_address[s]);
      const double precession = q[qa], nutation = q[qa + 1], spin = q[qa + 2];
      motion.rotation = EulerRotation(precession, nutation, spin);
      // Sdot * qdot: the rate columns turn as nutation and spin change.
      const double sn = std::sin(nutation), cn = std::cos(nutation);
      const double ss = std::sin(spin), cs = std::cos(spin);
      const double dp = (locked & 1u) ? 0.0 : v[va];
      const double dn = (locked & 2u) ? 0.0 : v[va + 1];
      const double ds = (locked & 4u) ? 0.0 : v[va + 2];
      const Vec3 d_precession_column(-cn * dn, -ss * sn * dn + cs * cn * ds,
                                     -cs * sn * dn - ss * cn * ds);
      const Vec3 d_nutation_column(0, -ss * ds, -cs * ds);
      const Vec3 w_dot =
          model.joint_frame_in_child[s] * (d_precession_column * dp + d_nutation_column * dn);
      motion.bias.head<3>() = w_dot;
      motion.bias.tail<3>() = model.joint_point_in_child[s].cross(w_dot);
      return;
    }
  }
}

void ComputeJointMotion(const Model& model, std::size_t s, std::span<const double> q,
                        std::span<const double> v, std::uint8_t locked, JointMotion& motion) {
  ComputeJointPose(model, s, q, v, locked, motion);
  ComputeJointSubspace(model, s, q, locked, motion.subspace);
}

void PositionDerivative(const Model& model, std::span<const double> q, std::span<const double> v,
                        std::span<const std::uint8_t> locked, std::span<double> qdot) {
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    switch (model.joint_kind[s]) {
      case JointKind::kFree: {
        const Eigen::Quaterniond quaternion = QuaternionAt(q, qa + 3);
        const Vec3 w(v[va], v[va + 1], v[va + 2]);
        const Vec3 velocity_body(v[va + 3], v[va + 4], v[va + 5]);
        const Vec3 velocity_world = quaternion.normalized() * velocity_body;
        for (int k = 0; k < 3; ++k) qdot[qa + k] = velocity_world[k];
        // qdot = 1/2 q (0, w): w is in the segment frame.
        const Eigen::Quaterniond rate = quaternion * Eigen::Quaterniond(0, w.x(), w.y(), w.z());
        qdot[qa + 3] = 0.5 * rate.w();
        qdot[qa + 4] = 0.5 * rate.x();
        qdot[qa + 5] = 0.5 * rate.y();
        qdot[qa + 6] = 0.5 * rate.z();
        break;
      }
      case JointKind::kBall: {
        if (locked[s] != 0) {
          for (int k = 0; k < 4; ++k) qdot[qa + k] = 0.0;
          break;
        }
        // The velocity is w of the segment relative to its parent, in the segment frame; the
        // quaternion describes the child joint frame, so turn w into that frame first.
        const Vec3 w_child(v[va], v[va + 1], v[va + 2]);
        const Vec3 w_joint = model.joint_frame_in_child[s].transpose() * w_child;
        const Eigen::Quaterniond rate =
            QuaternionAt(q, qa) * Eigen::Quaterniond(0, w_joint.x(), w_joint.y(), w_joint.z());
        qdot[qa] = 0.5 * rate.w();
        qdot[qa + 1] = 0.5 * rate.x();
        qdot[qa + 2] = 0.5 * rate.y();
        qdot[qa + 3] = 0.5 * rate.z();
        break;
      }
      case JointKind::kPin:
      case JointKind::kSlip:
        qdot[qa] = locked[s] != 0 ? 0.0 : v[va];
        break;
      case JointKind::kEuler:
        for (int k = 0; k < 3; ++k) qdot[qa + k] = (locked[s] & (1u << k)) ? 0.0 : v[va + k];
        break;
      case JointKind::kPlanar:
        for (int k = 0; k < 3; ++k) qdot[qa + k] = v[va + k];
        break;
    }
  }
}

}  // namespace sled::runtime
