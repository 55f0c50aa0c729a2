#include "runtime/contact/contact_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace sled::runtime {
namespace {

bool IsEllipsoid(double degree) { return degree == 2.0; }

// x^m, x^(1/m), x^(m-1) and x^(m-2) for the dual exponent m = p / (p - 1) of degree p: for the
// common degree 4 (m = 4/3) by cube and square roots, a few times cheaper than pow and equal to
// it to rounding.
struct DualPowers {
  double degree;
  double m;
  explicit DualPowers(double p) : degree(p), m(p / (p - 1.0)) {}
  bool Quartic() const { return degree == 4.0; }
  double Power(double x) const { return Quartic() ? x * std::cbrt(x) : std::pow(x, m); }
  double Root(double x) const {
    if (!Quartic()) return std::pow(x, 1.0 / m);
    const double root = std::sqrt(x);
    return root * std::sqrt(root);  // x^(3/4)
  }
  double PowerLessOne(double x) const { return Quartic() ? std::cbrt(x) : std::pow(x, m - 1.0); }
  double PowerLessTwo(double x) const {
    if (!Quartic()) return std::pow(x, m - 2.0);
    const double cube_root = std::cbrt(x);
    return 1.0 / (cube_root * cube_root);  // x^(-2/3)
  }
  double HalfPowerLessTwo(double x) const {
    return Quartic() ? 1.0 / std::cbrt(x) : std::pow(x, 0.5 * (m - 2.0));  // x^(-1/3)
  }
};

// The support function h(n) = ||S R^T n||_m of a hyper-ellipsoid of degree p (S the semi-axes,
// m = p / (p - 1) the dual exponent) is what SupportPoint returns as `extent`; its gradient is
// the support point and its Hessian the radii of curvature there. For p = 2 this is the
// ellipsoid's |S R^T n|.
struct Support {
  Vec3 offset;  // support point - centre
  double extent = 0.0;
  Mat3 hessian;  // of h at n (n in its null space)
};

// Components of y relative to its m-norm below this count as this, so the Hessian of a
// hyper-ellipsoid (infinite where its surface is flat) stays finite.
constexpr double kFlatFloor = 1e-9;

Support SupportWithHessian(const EllipsoidShape& shape, const Vec3& n) {
  const Vec3 y = shape.semi_axes.cwiseProduct(shape.rotation.transpose() * n);
  Support out;
  if (IsEllipsoid(shape.degree)) {
    const double k = y.norm();
    const Vec3 w = y / k;
    out.extent = k;
    out.offset = shape.rotation * shape.semi_axes.cwiseProduct(w);
    const Mat3 inner = (Mat3::Identity() - w * w.transpose()) / k;
    const Mat3 g = shape.semi_axes.asDiagonal() * shape.rotation.transpose();
    out.hessian = g.transpose() * inner * g;
    return out;
  }
  const DualPowers powers(shape.degree);
  const double m = powers.m;
  const Vec3 a = y.cwiseAbs();
  const double k = powers.Root(powers.Power(a[0]) + powers.Power(a[1]) + powers.Power(a[2]));
  Vec3 w, curvature;
  for (int i = 0; i < 3; ++i) {
    const double ratio = std::max(a[i] / k, kFlatFloor);
    w[i] = std::copysign(powers.PowerLessOne(ratio), y[i]);
    curvature[i] = powers.PowerLessTwo(ratio);
  }
  out.extent = k;
  out.offset = shape.rotation * shape.semi_axes.cwiseProduct(w);
  const Mat3 inner = (m - 1.0) / k * (Mat3(curvature.asDiagonal()) - w * w.transpose());
  const Mat3 g = shape.semi_axes.asDiagonal() * shape.rotation.transpose();
  out.hessian = g.transpose() * inner * g;
  return out;
}

// Two unit vectors that complete n to a right-handed orthonormal basis.
void TangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  t1 = n.cross(helper).normalized();
  t2 = n.cross(t1);
}

// The area fraction of a disc (or, by an affine map, an ellipse) on the inner side of a line at
// signed distance x (in units of the half-width across the line) from its centre.
double CutFraction(double x) {
  if (x >= 1.0) return 1.0;
  if (x <= -1.0) return 0.0;
  return 0.5 + (x * std::sqrt(1.0 - x * x) + std::asin(x)) / std::numbers::pi;
}

// The fraction of the cut footprint on the parallelogram: each edge whose distance from the
// footprint's centre `q` is less than the footprint's reach cuts it as a half-plane.
double EdgeWeight(const PlaneShape& plane, const EllipsoidShape& e, double height, double reach,
                  double s, double t) {
  const double uu = plane.edge_u.squaredNorm(), vv = plane.edge_v.squaredNorm();
  const double area = plane.edge_u.cross(plane.edge_v).norm();
  const double width_s = area / std::sqrt(vv);  // distance between the two edges along v
  const double width_t = area / std::sqrt(uu);
  const double inside[4] = {s * width_s, (1.0 - s) * width_s, t * width_t, (1.0 - t) * width_t};
  double weight = 1.0;
  // The cut footprint: points y of the plane (from its centre) with y^T M y <= kappa, M the
  // ellipsoid's quadratic form (the degree-2 form with the same semi-axes for a
  // hyper-ellipsoid).
  const double ratio = reach > 0 ? height / reach : 1.0;
  const double kappa = std::max(0.0, 1.0 - ratio * ratio);
  for (int k = 0; k < 4; ++k) {
    if (inside[k] >= e.radius) continue;  // the footprint cannot reach this edge
    const Vec3& along = k < 2 ? plane.edge_v : plane.edge_u;
    const Vec3 across = plane.normal.cross(along).normalized();  // in the plane, across the edge
    const Vec3 other = plane.normal.cross(across);
    // Half-width of the footprint across the edge: sqrt(kappa (M_p^-1)_11) in the basis
    // (across, other) of the plane.
    const Vec3 y1 = e.rotation.transpose() * across;
    const Vec3 y2 = e.rotation.transpose() * other;
    const Vec3 inv_sq = e.semi_axes.cwiseProduct(e.semi_axes).cwiseInverse();
    const double m11 = y1.cwiseProduct(y1).dot(inv_sq);
    const double m12 = y1.cwiseProduct(y2).dot(inv_sq);
    const double m22 = y2.cwiseProduct(y2).dot(inv_sq);
    const double half_width = std::sqrt(kappa * m22 / (m11 * m22 - m12 * m12));
    if (half_width > 0) {
      weight *= CutFraction(inside[k] / half_width);
    } else if (inside[k] < 0) {
      weight = 0.0;
    }
  }
  return weight;
}

}  // namespace

double BoundingRadius(const Vec3& semi_axes, double degree) {
  // h(n) <= 3^(1/2 - 1/p) max(a) for unit n (norm equivalence), and the box corner bounds it.
  const double largest = semi_axes.maxCoeff();
  if (IsEllipsoid(degree)) return largest;
  return std::min(semi_axes.norm(), largest * std::pow(3.0, 0.5 - 1.0 / degree));
}

Vec3 SupportPoint(const EllipsoidShape& shape, const Vec3& direction, double* extent) {
  const Vec3 y = shape.semi_axes.cwiseProduct(shape.rotation.transpose() * direction);
  Vec3 w;
  double k;
  if (IsEllipsoid(shape.degree)) {
    k = y.norm();
    w = y / k;
  } else {
    const DualPowers powers(shape.degree);
    const Vec3 a = y.cwiseAbs();
    k = powers.Root(powers.Power(a[0]) + powers.Power(a[1]) + powers.Power(a[2]));
    for (int i = 0; i < 3; ++i) w[i] = std::copysign(powers.PowerLessOne(a[i] / k), y[i]);
  }
  if (extent) *extent = k;
  return shape.center + shape.rotation * shape.semi_axes.cwiseProduct(w);
}

namespace {

// How far a hyper-ellipsoid's force point is smoothed: the support point moves as the
// (m - 1)-th power of the direction's components in its axes, a cube root for degree 4, so a
// flat face resting on a plane would swing its deepest point from edge to edge at the least
// tilt. Components below this fraction of the support function are taken linearly instead, so
// the force point moves smoothly across the face (and is its middle when the face is flat).
constexpr double kFaceSmoothing = 0.1;

// Where a surface pushed along -direction takes its force: the support point for an ellipsoid;
// for a hyper-ellipsoid the support point smoothed over its flat faces.
Vec3 ForcePoint(const EllipsoidShape& shape, const Vec3& direction) {
  if (IsEllipsoid(shape.degree)) return SupportPoint(shape, direction, nullptr);
  const Vec3 y = shape.semi_axes.cwiseProduct(shape.rotation.transpose() * direction);
  const DualPowers powers(shape.degree);
  const Vec3 a = y.cwiseAbs();
  const double k = powers.Root(powers.Power(a[0]) + powers.Power(a[1]) + powers.Power(a[2]));
  Vec3 w;
  for (int i = 0; i < 3; ++i) {
    const double r = y[i] / k;
    w[i] = r * powers.HalfPowerLessTwo(r * r + kFaceSmoothing * kFaceSmoothing);
  }
  return shape.center + shape.rotation * shape.semi_axes.cwiseProduct(w);
}

}  // namespace

std::pair<double, double> ParallelogramCoordinates(const PlaneShape& plane, const Vec3& point) {
  const Vec3 d = point - plane.origin;
  const double uu = plane.edge_u.squaredNorm(), uv = plane.edge_u.dot(plane.edge_v);
  const double vv = plane.edge_v.squaredNorm();
  const double du = d.dot(plane.edge_u), dv = d.dot(plane.edge_v);
  const double det = uu * vv - uv * uv;
  return {(du * vv - dv * uv) / det, (dv * uu - du * uv) / det};
}

ContactGeometry PlaneEllipsoid(const PlaneShape& plane, const EllipsoidShape& ellipsoid) {
  ContactGeometry out;
  out.normal = plane.normal;
  double reach = 0.0;
  out.deepest_first = SupportPoint(ellipsoid, -plane.normal, &reach);
  out.deepest_second = out.deepest_first;
  const double height = plane.normal.dot(ellipsoid.center - plane.origin);
  out.deflection = reach - height;
  // The crossing of the plane by the line from the centre to the force point (the deepest
  // point of an ellipsoid).
  const Vec3 force_point = ForcePoint(ellipsoid, -plane.normal);
  const double along = plane.normal.dot(ellipsoid.center - force_point);
  const Vec3 q = ellipsoid.center + (height / along) * (force_point - ellipsoid.center);
  const auto [s, t] = ParallelogramCoordinates(plane, q);
  out.point = plane.origin + std::clamp(s, 0.0, 1.0) * plane.edge_u +
              std::clamp(t, 0.0, 1.0) * plane.edge_v;
  // Only an ellipsoid with a part in front of the plane is pushed (the plane is one-sided).
  if (!(out.deflection > 0) || !(height > -reach)) return out;
  out.weight = EdgeWeight(plane, ellipsoid, height, reach, s, t);
  out.touching = out.weight > 0;
  return out;
}

namespace {

// The overlap o(n) = h_first(n) + h_second(-n) - n . d, with the deepest points.
struct Overlap {
  double value;
  Vec3 first_point;   // deepest point of the first surface along n
  Vec3 second_point;  // deepest point of the second along -n
};

Overlap OverlapAlong(const EllipsoidShape& a, const EllipsoidShape& b, const Vec3& n) {
  Overlap o;
  o.first_point = SupportPoint(a, n, nullptr);
  o.second_point = SupportPoint(b, -n, nullptr);
  o.value = n.dot(o.first_point - o.second_point);
  return o;
}

constexpr int kMaxIterations = 40;
constexpr int kMaxHalvings = 12;
constexpr double kMaxTurn = 0.5;  // the largest change of the normal in one step [rad]

}  // namespace

ContactGeometry EllipsoidEllipsoid(const EllipsoidShape& first, const EllipsoidShape& second,
                                   Vec3& direction) {
  const Vec3 d = second.center - first.center;
  Vec3 n = direction;
  if (!(n.squaredNorm() > 0.5)) n = d.squaredNorm() > 0 ? Vec3(d.normalized()) : Vec3::UnitX();
  n.normalize();
  const double scale = first.radius + second.radius;
  Overlap current = OverlapAlong(first, second, n);
  // Newton's method on the unit sphere for the least overlap: the gradient of o is the vector
  // between the deepest points (its tangential part vanishes at the common normal) and the
  // Hessian the sum of the radii of curvature less o itself, made positive definite when the
  // overlap is deep; each step is halved until o decreases.
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    Vec3 t1, t2;
    TangentBasis(n, t1, t2);
    const Vec3 gradient = current.first_point - current.second_point;
    const Eigen::Vector2d g(t1.dot(gradient), t2.dot(gradient));
    if (g.norm() <= 1e-13 * scale) break;
    const Mat3 curvature =
        SupportWithHessian(first, n).hessian + SupportWithHessian(second, -n).hessian;
    Eigen::Matrix2d j;
    j << t1.dot(curvature * t1), t1.dot(curvature * t2), t2.dot(curvature * t1),
        t2.dot(curvature * t2);
    j -= current.value * Eigen::Matrix2d::Identity();
    // The smallest eigenvalue of the symmetric 2x2 matrix; shift it up to a positive floor.
    const double mean = 0.5 * (j(0, 0) + j(1, 1));
    const double spread = std::hypot(0.5 * (j(0, 0) - j(1, 1)), j(0, 1));
    const double floor = 1e-3 * scale;
    if (mean - spread < floor) j += (floor - (mean - spread)) * Eigen::Matrix2d::Identity();
    Eigen::Vector2d step = -j.inverse() * g;
    if (step.norm() > kMaxTurn) step *= kMaxTurn / step.norm();
    bool improved = false;
    const double previous = current.value;
    for (int halving = 0; halving < kMaxHalvings; ++halving) {
      const Vec3 trial = (n + step[0] * t1 + step[1] * t2).normalized();
      const Overlap next = OverlapAlong(first, second, trial);
      if (next.value <= current.value) {
        improved = next.value < current.value || halving > 0;
        n = trial;
        current = next;
        break;
      }
      step *= 0.5;
    }
    // Converged to rounding: the step no longer lowers the overlap measurably.
    if (!improved || step.norm() < 1e-14 || previous - current.value <= 1e-15 * scale) break;
  }
  direction = n;
  ContactGeometry out;
  out.deflection = current.value;
  out.normal = -n;
  out.deepest_first = current.first_point;
  out.deepest_second = current.second_point;
  out.point = IsEllipsoid(first.degree) && IsEllipsoid(second.degree)
                  ? 0.5 * (current.first_point + current.second_point)
                  : 0.5 * (ForcePoint(first, n) + ForcePoint(second, -n));
  out.touching = out.deflection > 0;
  return out;
}

}  // namespace sled::runtime
