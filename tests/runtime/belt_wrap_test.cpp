// Where webbing lies on a wrapped ellipsoid (runtime/restraint/belt_wrap.h), against hand
// geometry: tangent points of a circle from the angle between the centre-to-point line and the
// tangent (acos(r/d)), the polar line of an ellipse, and an arc length integrated by Simpson's
// rule with 2000 intervals.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "runtime/restraint/belt_wrap.h"

namespace sled::runtime {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

WrapSurface Sphere(const Vec3& centre, double radius) {
  return {centre, Eigen::Matrix3d::Identity(), Vec3::Constant(radius)};
}

void ExpectNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, tolerance)
      << "actual (" << actual.transpose() << "), expected (" << expected.transpose() << ")";
}

// The tangent point of a circle (centre c, radius r, in the xz plane) seen from p: at the angle
// of p about c, turned by acos(r / |p - c|) toward the upper side (sign +1 turns
// counter-clockwise, -1 clockwise).
Vec3 CircleTangent(const Vec3& c, double r, const Vec3& p, double sign) {
  const double d = std::hypot(p.x() - c.x(), p.z() - c.z());
  const double angle = std::atan2(p.z() - c.z(), p.x() - c.x()) + sign * std::acos(r / d);
  return c + r * Vec3(std::cos(angle), 0, std::sin(angle));
}

TEST(BeltWrap, SphereWithItsCentreOnTheLineWrapsTheHintedSide) {
  const Wrap wrap =
      WrapOver(Sphere(Vec3::Zero(), 1.0), Vec3(-2, 0, 0), Vec3(2, 0, 0), Vec3::UnitZ());
  ASSERT_TRUE(wrap.contact);
  // From (-2, 0) the tangent touches the unit circle at 60 deg from the x axis: (-1/2, sqrt3/2).
  ExpectNear(wrap.entry, Vec3(-0.5, 0, std::sqrt(3.0) / 2), 1e-14);
  ExpectNear(wrap.exit, Vec3(0.5, 0, std::sqrt(3.0) / 2), 1e-14);
  EXPECT_NEAR(wrap.arc, kPi / 3, 1e-14);
  EXPECT_NEAR(wrap.turning, kPi / 3, 1e-14);
  ExpectNear(wrap.middle, Vec3(0, 0, 1), 1e-14);
  ExpectNear(wrap.tangent, Vec3(1, 0, 0), 1e-14);
  ExpectNear(wrap.side, Vec3(0, 0, 1), 1e-15);
}

TEST(BeltWrap, OffCentreSphere) {
  const Vec3 c(0.5, 0, 0.3), p(-2, 0, 0), q(3, 0, 0);
  const Wrap wrap = WrapOver(Sphere(c, 1.0), p, q, Vec3::UnitZ());
  ASSERT_TRUE(wrap.contact);
  // The centre lies above the line, so the webbing goes over the top, the far side.
  const Vec3 entry = CircleTangent(c, 1.0, p, -1), exit = CircleTangent(c, 1.0, q, +1);
  ExpectNear(wrap.entry, entry, 1e-14);
  ExpectNear(wrap.exit, exit, 1e-14);
  const double sweep = std::atan2(entry.z() - c.z(), entry.x() - c.x()) -
                       std::atan2(exit.z() - c.z(), exit.x() - c.x());
  EXPECT_NEAR(wrap.arc, sweep, 1e-13);
  EXPECT_NEAR(wrap.turning, sweep, 1e-13);
  // The path is tangent at both ends: the spans meet the radius at right angles.
  EXPECT_NEAR((wrap.entry - p).dot(wrap.entry - c), 0.0, 1e-14);
  EXPECT_NEAR((wrap.exit - q).dot(wrap.exit - c), 0.0, 1e-14);
}

TEST(BeltWrap, TheArcMeasuredLaterIsTheArcMeasuredAtOnce) {
  // BeltGeometry wraps without the arc while the tangent points settle, then measures the last
  // wrap's: the same length, to the bit, and nothing else changes.
  const Vec3 c(0.5, 0, 0.3), p(-2, 0, 0), q(3, 0, 0);
  WrapSurface surface = Sphere(c, 1.0);
  surface.semi_axes = Vec3(1.0, 0.7, 1.3);
  const Wrap measured = WrapOver(surface, p, q, Vec3::UnitZ());
  const Wrap later = WrapOver(surface, p, q, Vec3::UnitZ(), false);
  ASSERT_TRUE(measured.contact);
  EXPECT_GT(measured.arc, 0.0);
  EXPECT_EQ(later.arc, 0.0);
  EXPECT_EQ(WrapArc(later.section), measured.arc);
  EXPECT_EQ(later.entry, measured.entry);
  EXPECT_EQ(later.exit, measured.exit);
  EXPECT_EQ(later.turning, measured.turning);
  EXPECT_EQ(WrapArc(WrapSection{}), 0.0);
}

TEST(BeltWrap, CentreBeyondTheLineWrapsTheFarSide) {
  // A lap belt: anchors below and behind, the body above the line; the webbing lies over it.
  const Vec3 c(0, 0, 0.5), p(-2, 0, 0), q(2, 0, 0);
  const Wrap wrap = WrapOver(Sphere(c, 1.0), p, q, Vec3::UnitZ());
  ASSERT_TRUE(wrap.contact);
  ExpectNear(wrap.entry, CircleTangent(c, 1.0, p, -1), 1e-14);
  ExpectNear(wrap.exit, CircleTangent(c, 1.0, q, +1), 1e-14);
  // Symmetric: the arc runs from the entry's angle about the centre down to the exit's.
  const double entry_angle = std::atan2(wrap.entry.z() - c.z(), wrap.entry.x() - c.x());
  EXPECT_NEAR(wrap.arc, 2 * entry_angle - kPi, 1e-13);
  ExpectNear(wrap.middle, Vec3(0, 0, 1.5), 1e-14);
}

TEST(BeltWrap, EllipseByItsPolarLine) {
  // x^2/4 + z^2 = 1 seen from (-4, 0): the polar line x (-4) / 4 = 1 meets it at x = -1.
  const WrapSurface ellipsoid{Vec3::Zero(), Eigen::Matrix3d::Identity(), Vec3(2, 1, 1)};
  const Wrap wrap = WrapOver(ellipsoid, Vec3(-4, 0, 0), Vec3(4, 0, 0), Vec3::UnitZ());
  ASSERT_TRUE(wrap.contact);
  ExpectNear(wrap.entry, Vec3(-1, 0, std::sqrt(3.0) / 2), 1e-14);
  ExpectNear(wrap.exit, Vec3(1, 0, std::sqrt(3.0) / 2), 1e-14);
  // Arc from parameter 120 deg to 60 deg of (2 cos t, sin t), by Simpson's rule.
  const int n = 2000;
  const double t0 = kPi / 3, t1 = 2 * kPi / 3, h = (t1 - t0) / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + k * h;
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += w * std::sqrt(4 * std::sin(t) * std::sin(t) + std::cos(t) * std::cos(t));
  }
  EXPECT_NEAR(wrap.arc, sum * h / 3, 1e-12);
  // The spans rise at atan((sqrt3/2) / 3) and fall at the same angle.
  EXPECT_NEAR(wrap.turning, 2 * std::atan(std::sqrt(3.0) / 2 / 3), 1e-14);
}

TEST(BeltWrap, TurningTheWholeSceneTurnsTheWrap) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.4, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.7, Vec3(1, 1, 0).normalized()))
          .toRotationMatrix();
  const Eigen::Matrix3d axes = Eigen::AngleAxisd(0.3, Vec3::UnitY()).toRotationMatrix();
  const WrapSurface plain{Vec3(0.1, 0, 0.2), axes, Vec3(0.2, 0.15, 0.1)};
  const WrapSurface turned{turn * plain.centre, turn * axes, plain.semi_axes};
  const Vec3 p(-0.5, 0.1, 0), q(0.6, -0.2, 0.05);
  const Wrap a = WrapOver(plain, p, q, Vec3::UnitZ());
  const Wrap b = WrapOver(turned, turn * p, turn * q, turn * Vec3::UnitZ());
  ASSERT_TRUE(a.contact && b.contact);
  ExpectNear(b.entry, turn * a.entry, 1e-14);
  ExpectNear(b.exit, turn * a.exit, 1e-14);
  EXPECT_NEAR(b.arc, a.arc, 1e-14);
  EXPECT_NEAR(b.turning, a.turning, 1e-14);
  // Tangent points really are on the surface and the spans tangent to it.
  const Eigen::Matrix3d form =
      axes * plain.semi_axes.cwiseInverse().cwiseAbs2().asDiagonal() * axes.transpose();
  for (const Vec3& point : {a.entry, a.exit}) {
    EXPECT_NEAR((point - plain.centre).dot(form * (point - plain.centre)), 1.0, 1e-13);
  }
  EXPECT_NEAR((a.entry - p).dot(form * (a.entry - plain.centre)), 0.0, 1e-13);
  EXPECT_NEAR((q - a.exit).dot(form * (a.exit - plain.centre)), 0.0, 1e-13);
}

TEST(BeltWrap, BodyBelowTheLineLeavesTheWebbingStraight) {
  const Wrap wrap =
      WrapOver(Sphere(Vec3(0.3, 0, -2), 1.0), Vec3(-2, 0, 0), Vec3(2, 0, 0), Vec3::UnitZ());
  EXPECT_FALSE(wrap.contact);
  ExpectNear(wrap.entry, Vec3(0.3, 0, 0), 1e-15);  // the body's top, projected on the line
  ExpectNear(wrap.exit, wrap.entry, 0.0);
  EXPECT_EQ(wrap.arc, 0.0);
  EXPECT_EQ(wrap.turning, 0.0);
  ExpectNear(wrap.side, Vec3(0, 0, 1), 1e-15);  // the hint holds across the line
}

TEST(BeltWrap, LengthIsContinuousWhenContactIsMadeOrLost) {
  auto length = [](double depth) {
    const Vec3 p(-2, 0, 0), q(2, 0, 0);
    const Wrap wrap = WrapOver(Sphere(Vec3(0, 0, -1 + depth), 1.0), p, q, Vec3::UnitZ());
    return (wrap.entry - p).norm() + wrap.arc + (q - wrap.exit).norm();
  };
  EXPECT_NEAR(length(-1e-9), 4.0, 1e-15);
  // Touching by 1e-8 m adds about 2 (2 delta)^1.5 / 3 sqrt(r) ... far below 1e-10 m.
  EXPECT_NEAR(length(1e-8), 4.0, 1e-10);
  EXPECT_GE(length(1e-8), 4.0 - 1e-15);
  EXPECT_GT(length(1e-3), length(1e-4));
}

TEST(BeltWrap, SegmentWithoutEllipsoidIsAFixedPoint) {
  const WrapSurface point{Vec3(0, 0, 1), Eigen::Matrix3d::Identity(), Vec3::Zero()};
  const Wrap wrap = WrapOver(point, Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3::UnitZ());
  EXPECT_TRUE(wrap.contact);
  ExpectNear(wrap.entry, Vec3(0, 0, 1), 0.0);
  ExpectNear(wrap.exit, Vec3(0, 0, 1), 0.0);
  EXPECT_NEAR(wrap.turning, kPi / 2, 1e-15);
}

TEST(BeltWrap, AnchorInsideTheBodyUsesTheNearestPointAlongTheRay) {
  const Wrap wrap =
      WrapOver(Sphere(Vec3::Zero(), 1.0), Vec3(-0.5, 0, 0.5), Vec3(3, 0, 0), Vec3::UnitZ());
  ASSERT_TRUE(wrap.contact);
  ExpectNear(wrap.entry, Vec3(-1, 0, 1) / std::sqrt(2.0), 1e-14);
  ExpectNear(wrap.exit, CircleTangent(Vec3::Zero(), 1.0, Vec3(3, 0, 0), +1), 1e-14);
}

}  // namespace
}  // namespace sled::runtime
