// Spatial (6-D) algebra in body coordinates, Featherstone's convention: a motion vector is
// [angular; linear], a force vector [moment; force], both expressed in a segment's frame with
// the segment's centre of mass as origin.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sled::runtime {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
// Up to six columns without heap allocation: a joint's active axes and the small matrices of
// the articulated-body recursion.
using MotionSubspace = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// The motion cross product v x m (how a motion vector m changes seen from a frame moving with v).
inline Vec6 CrossMotion(const Vec6& v, const Vec6& m) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(m.head<3>());
  out.tail<3>() = v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return out;
}

// The force cross product v x* f.
inline Vec6 CrossForce(const Vec6& v, const Vec6& f) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(f.head<3>()) + v.tail<3>().cross(f.tail<3>());
  out.tail<3>() = v.head<3>().cross(f.tail<3>());
  return out;
}

// The transform of motion vectors from a parent frame P to a child frame C, where E rotates
// parent coordinates into child coordinates (E = R_PC^T) and r is the child origin in parent
// coordinates: X m = [E w; E (v - r x w)].
struct Transform {
  Eigen::Matrix3d E = Eigen::Matrix3d::Identity();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();

  Vec6 ApplyMotion(const Vec6& m) const {
    Vec6 out;
    out.head<3>() = E * m.head<3>();
    out.tail<3>() = E * (m.tail<3>() - r.cross(m.head<3>()));
    return out;
  }
  // X^T f: a force in child coordinates expressed in parent coordinates.
  Vec6 TransposeApplyForce(const Vec6& f) const {
    Vec6 out;
    const Eigen::Vector3d force = E.transpose() * f.tail<3>();
    out.head<3>() = E.transpose() * f.head<3>() + r.cross(force);
    out.tail<3>() = force;
    return out;
  }
  // X^T I X: a symmetric spatial inertia (or articulated inertia) in child coordinates,
  // expressed in parent coordinates. Done in 3x3 blocks, a fraction of the work of the 6x6
  // products: with I = [A B; B^T C] rotated to A', B', C' and r~ the cross-product matrix of r,
  // the shift gives [A' - B' r~ + r~ B'^T - r~ C' r~,  Z;  Z^T,  C'] with Z = B' + r~ C'. The
  // top-left block is A' + (r~ B'^T)^T + r~ Z^T, and each r~ M is a cross product per column.
  Mat6 TransposeApplyInertia(const Mat6& inertia) const {
    Mat6 out = Mat6::Zero();
    AddTransposeApplyInertia(inertia, out);
    return out;
  }
  // out += X^T I X, for summing children's inertias into their parent's.
  void AddTransposeApplyInertia(const Mat6& inertia, Mat6& out) const {
    const Eigen::Matrix3d Et = E.transpose();
    const Eigen::Matrix3d A = Et * inertia.topLeftCorner<3, 3>() * E;
    const Eigen::Matrix3d B = Et * inertia.topRightCorner<3, 3>() * E;
    const Eigen::Matrix3d C = Et * inertia.bottomRightCorner<3, 3>() * E;
    Eigen::Matrix3d top_right, top_left;
    for (int j = 0; j < 3; ++j) top_right.col(j) = B.col(j) + r.cross(C.col(j));
    // Row j of (r~ B'^T)^T is r x (row j of B'); column j of r~ Z^T is r x (row j of Z).
    for (int j = 0; j < 3; ++j) top_left.row(j) = r.cross(B.row(j).transpose()).transpose();
    for (int j = 0; j < 3; ++j) top_left.col(j) += r.cross(top_right.row(j).transpose());
    top_left += A;
    // The result is symmetric in exact arithmetic; symmetrising keeps rounding from growing
    // along long chains (a 30-segment chain lost five digits without it).
    out.topLeftCorner<3, 3>() += 0.5 * (top_left + top_left.transpose());
    out.topRightCorner<3, 3>() += top_right;
    out.bottomLeftCorner<3, 3>() += top_right.transpose();
    out.bottomRightCorner<3, 3>() += 0.5 * (C + C.transpose());
  }
  // out += X^T I X for I = [-p~ K p~, p~ K; -K p~, K]: a translational inertia K (symmetric)
  // acting at the point p of the child frame, which is all that passes through a ball joint at
  // p. In parent coordinates it has the same form, with K' = E^T K E at q = r + E^T p.
  void AddTransposeApplyPointInertia(const Eigen::Matrix3d& K, const Eigen::Vector3d& p,
                                     Mat6& out) const {
    const Eigen::Matrix3d K_parent = E.transpose() * K * E;
    const Eigen::Vector3d q = r + E.transpose() * p;
    Eigen::Matrix3d top_right, top_left;  // q~ K' and -q~ K' q~
    for (int j = 0; j < 3; ++j) top_right.col(j) = q.cross(K_parent.col(j));
    // Column j of -q~ K' q~ = (q~ K')(q~)^T is q x (row j of q~ K').
    for (int j = 0; j < 3; ++j) top_left.col(j) = q.cross(top_right.row(j).transpose());
    out.topLeftCorner<3, 3>() += 0.5 * (top_left + top_left.transpose());
    out.topRightCorner<3, 3>() += top_right;
    out.bottomLeftCorner<3, 3>() += top_right.transpose();
    out.bottomRightCorner<3, 3>() += 0.5 * (K_parent + K_parent.transpose());
  }
  Mat6 Matrix() const {
    Mat6 x = Mat6::Zero();
    x.topLeftCorner<3, 3>() = E;
    x.bottomRightCorner<3, 3>() = E;
    x.bottomLeftCorner<3, 3>() = -E * Skew(r);
    return x;
  }
};

}  // namespace sled::runtime
