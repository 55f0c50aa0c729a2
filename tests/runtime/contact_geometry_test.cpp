// Contact geometry (runtime/contact/contact_geometry.h) against values worked out by hand: the
// plane–ellipsoid deflection and point, spheres against the exact answer, ellipsoid pairs
// against a brute-force search over directions, the finite plane's edges against the area of a
// circular segment, and hyper-ellipsoids against the ellipsoid (degree 2) and the box.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "runtime/contact/contact_geometry.h"

namespace sled::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

Mat3 AboutX(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix(); }
Mat3 AboutY(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitY()).toRotationMatrix(); }

EllipsoidShape Shape(const Vec3& center, const Vec3& semi_axes, const Mat3& rotation,
                     double degree = 2.0) {
  EllipsoidShape shape;
  shape.center = center;
  shape.rotation = rotation;
  shape.semi_axes = semi_axes;
  shape.degree = degree;
  shape.radius = BoundingRadius(semi_axes, degree);
  return shape;
}

// The floor z = 0 over [x0, x0 + size] x [y0, y0 + size], normal +z.
PlaneShape Floor(double x0 = -1, double y0 = -1, double size = 2) {
  PlaneShape plane;
  plane.origin = Vec3(x0, y0, 0);
  plane.edge_u = Vec3(size, 0, 0);
  plane.edge_v = Vec3(0, size, 0);
  plane.normal = Vec3::UnitZ();
  return plane;
}

TEST(PlaneEllipsoid, TurnedEllipsoidReachesDownByItsMiddleAxis) {
  // Turned 90 deg about x, the ellipsoid's y axis (0.2) points up: it reaches 0.2 below its
  // centre, 0.05 past the floor, straight under the centre.
  const ContactGeometry g =
      PlaneEllipsoid(Floor(), Shape(Vec3(0.1, 0.2, 0.15), Vec3(0.1, 0.2, 0.3), AboutX(kPi / 2)));
  EXPECT_TRUE(g.touching);
  EXPECT_NEAR(g.deflection, 0.05, 1e-15);
  EXPECT_NEAR((g.point - Vec3(0.1, 0.2, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((g.normal - Vec3::UnitZ()).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(g.weight, 1.0);
}

TEST(PlaneEllipsoid, TiltedEllipsoidTouchesOffCentre) {
  // Semi-axes (0.3, 0.1, 0.1) pitched 30 deg about y. By hand: the extent along z is
  // sqrt((0.3 sin 30)^2 + (0.1 cos 30)^2) = sqrt(0.03); the deepest point lies
  // R diag(a^2) R^T z / sqrt(0.03) below the centre, 0.2 to +x; the line from the centre to it
  // crosses z = 0 at 0.15 / sqrt(0.03) of the way, x = 0.2 * 0.15 / sqrt(0.03).
  const double reach = std::sqrt(0.03);
  const ContactGeometry g =
      PlaneEllipsoid(Floor(), Shape(Vec3(0, 0, 0.15), Vec3(0.3, 0.1, 0.1), AboutY(kPi / 6)));
  EXPECT_NEAR(g.deflection, reach - 0.15, 1e-15);
  EXPECT_NEAR(g.point.x(), 0.2 * 0.15 / reach, 1e-14);
  EXPECT_NEAR(g.point.y(), 0, 1e-15);
  EXPECT_NEAR(g.point.z(), 0, 1e-15);
}

TEST(PlaneEllipsoid, ClearOfThePlaneIsApartWithItsHeight) {
  const ContactGeometry g =
      PlaneEllipsoid(Floor(), Shape(Vec3(0, 0, 0.35), Vec3(0.1, 0.1, 0.3), Mat3::Identity()));
  EXPECT_FALSE(g.touching);
  EXPECT_NEAR(g.deflection, -0.05, 1e-15);
}

TEST(PlaneEllipsoid, WhollyBehindThePlaneIsNoContact) {
  const ContactGeometry g =
      PlaneEllipsoid(Floor(), Shape(Vec3(0, 0, -0.31), Vec3(0.1, 0.1, 0.3), Mat3::Identity()));
  EXPECT_FALSE(g.touching);
}

// Area fraction of a disc of radius r beyond a chord at distance h from the centre (the
// circular segment: r^2 acos(h/r) - h sqrt(r^2 - h^2), over pi r^2).
double SegmentFraction(double h, double r) {
  return (r * r * std::acos(h / r) - h * std::sqrt(r * r - h * h)) / (kPi * r * r);
}

TEST(PlaneEllipsoid, EdgesFadeTheForceByTheShareOfTheFootprint) {
  // A sphere of radius 0.1 sunk 0.02 into the floor [0, 1]^2 cuts a disc of radius
  // sqrt(0.1^2 - 0.08^2) = 0.06.
  const PlaneShape floor = Floor(0, 0, 1);
  const double r = 0.06;
  auto at = [&](double x, double y) {
    return PlaneEllipsoid(floor, Shape(Vec3(x, y, 0.08), Vec3(0.1, 0.1, 0.1), Mat3::Identity()));
  };
  EXPECT_DOUBLE_EQ(at(0.5, 0.5).weight, 1.0);
  EXPECT_DOUBLE_EQ(at(0.07, 0.5).weight, 1.0);  // clear of the edge by more than the disc
  EXPECT_NEAR(at(0.0, 0.5).weight, 0.5, 1e-15);
  EXPECT_NEAR(at(0.03, 0.5).weight, 1 - SegmentFraction(0.03, r), 1e-12);
  EXPECT_NEAR(at(-0.03, 0.5).weight, SegmentFraction(0.03, r), 1e-12);
  EXPECT_NEAR(at(0.5, 0.98).weight, 1 - SegmentFraction(0.02, r), 1e-12);  // the far edge
  EXPECT_NEAR(at(0.0, 0.0).weight, 0.25, 1e-12);                           // a corner
  EXPECT_FALSE(at(-0.07, 0.5).touching);
  EXPECT_EQ(at(-0.07, 0.5).weight, 0.0);
  // Hanging over the edge, the force acts on the edge.
  EXPECT_NEAR((at(-0.03, 0.5).point - Vec3(0, 0.5, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(at(-0.03, 0.5).deflection, 0.02, 1e-15);
}

TEST(PlaneEllipsoid, FootprintOfAnEllipsoidIsAnEllipse) {
  // Semi-axes (0.2, 0.1, 0.1), sunk 0.02: the cut ellipse has half-widths 0.2 * 0.6 along x and
  // 0.1 * 0.6 along y. Centred on the edge x = 0, half of it is on the floor; 0.06 inside the
  // edge x = 0 it is 1 - segment(0.06 / 0.12).
  const PlaneShape floor = Floor(0, 0, 1);
  const Vec3 axes(0.2, 0.1, 0.1);
  auto at = [&](double x) {
    return PlaneEllipsoid(floor, Shape(Vec3(x, 0.5, 0.08), axes, Mat3::Identity())).weight;
  };
  EXPECT_NEAR(at(0.0), 0.5, 1e-15);
  EXPECT_NEAR(at(0.06), 1 - SegmentFraction(0.5, 1.0), 1e-12);
}

TEST(EllipsoidEllipsoid, SpheresOverlapByTheirRadiiLessTheDistance) {
  const Vec3 a(0.01, -0.02, 0.03), b(0.13, 0.03, 0.0);
  const double ra = 0.1, rb = 0.05;
  const Vec3 d = b - a;
  Vec3 warm = Vec3::UnitY();  // a poor start
  const ContactGeometry g = EllipsoidEllipsoid(Shape(a, Vec3::Constant(ra), Mat3::Identity()),
                                               Shape(b, Vec3::Constant(rb), AboutX(0.3)), warm);
  EXPECT_TRUE(g.touching);
  EXPECT_NEAR(g.deflection, ra + rb - d.norm(), 1e-13);
  EXPECT_NEAR((g.normal + d.normalized()).norm(), 0, 1e-9);
  const Vec3 midway = 0.5 * ((a + ra * d.normalized()) + (b - rb * d.normalized()));
  EXPECT_NEAR((g.point - midway).norm(), 0, 1e-10);
  EXPECT_NEAR((warm - d.normalized()).norm(), 0, 1e-9);
}

TEST(EllipsoidEllipsoid, SeparatedSpheresGiveMinusTheirDistance) {
  Vec3 warm = Vec3::Zero();
  const ContactGeometry g =
      EllipsoidEllipsoid(Shape(Vec3::Zero(), Vec3::Constant(0.1), Mat3::Identity()),
                         Shape(Vec3(0.3, 0.1, 0), Vec3::Constant(0.1), Mat3::Identity()), warm);
  EXPECT_FALSE(g.touching);
  EXPECT_NEAR(g.deflection, 0.2 - std::hypot(0.3, 0.1), 1e-13);
}

TEST(EllipsoidEllipsoid, AlignedEllipsoidsOverlapAlongTheirAxes) {
  Vec3 warm = Vec3::Zero();
  const ContactGeometry g =
      EllipsoidEllipsoid(Shape(Vec3::Zero(), Vec3(0.3, 0.1, 0.15), Mat3::Identity()),
                         Shape(Vec3(0.45, 0, 0), Vec3(0.2, 0.12, 0.05), Mat3::Identity()), warm);
  EXPECT_NEAR(g.deflection, 0.05, 1e-14);
  EXPECT_NEAR((g.normal + Vec3::UnitX()).norm(), 0, 1e-12);
  EXPECT_NEAR((g.point - Vec3(0.275, 0, 0)).norm(), 0, 1e-12);
}

// The least overlap h_a(n) + h_b(-n) - n.d over a fine grid of directions (independent of the
// Newton search), refined on a finer grid around the best.
double BruteForceOverlap(const EllipsoidShape& a, const EllipsoidShape& b) {
  const Vec3 d = b.center - a.center;
  auto overlap = [&](double theta, double phi) {
    const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    double ha = 0, hb = 0;
    SupportPoint(a, n, &ha);
    SupportPoint(b, -n, &hb);
    return ha + hb - n.dot(d);
  };
  double best = 1e9, best_theta = 0, best_phi = 0;
  for (int i = 0; i <= 400; ++i) {
    for (int j = 0; j < 800; ++j) {
      const double theta = kPi * i / 400, phi = 2 * kPi * j / 800;
      const double o = overlap(theta, phi);
      if (o < best) best = o, best_theta = theta, best_phi = phi;
    }
  }
  const double span = kPi / 400;
  for (int i = -100; i <= 100; ++i) {
    for (int j = -100; j <= 100; ++j) {
      best = std::min(best, overlap(best_theta + span * i / 100, best_phi + 2 * span * j / 100));
    }
  }
  return best;
}

TEST(EllipsoidEllipsoid, TurnedEllipsoidsMatchABruteForceSearch) {
  const EllipsoidShape a = Shape(Vec3(0, 0, 0), Vec3(0.25, 0.1, 0.08), AboutY(0.4) * AboutX(0.2));
  for (const double gap : {0.25, 0.3, 0.36}) {
    const EllipsoidShape b =
        Shape(Vec3(gap, 0.05, 0.04), Vec3(0.12, 0.2, 0.06), AboutX(1.0) * AboutY(-0.3));
    Vec3 warm = Vec3::Zero();
    const ContactGeometry g = EllipsoidEllipsoid(a, b, warm);
    const double sampled = BruteForceOverlap(a, b);
    EXPECT_LE(g.deflection, sampled + 1e-12) << gap;
    EXPECT_NEAR(g.deflection, sampled, 1e-8) << gap;
    // At the common normal the deepest points lie on one line along it.
    double ha = 0, hb = 0;
    const Vec3 pa = SupportPoint(a, warm, &ha);
    const Vec3 pb = SupportPoint(b, -warm, &hb);
    EXPECT_NEAR((pa - pb).cross(warm).norm(), 0, 1e-12) << gap;
  }
}

TEST(EllipsoidEllipsoid, AHugeSphereActsAsAPlane) {
  // A sphere of radius 1e4 m whose top is the plane z = 0: its surface departs from the plane
  // by x^2 / (2 R) = 2e-6 m at the contact point x = 0.2 of the tilted ellipsoid.
  const double big = 1e4;
  const EllipsoidShape tilted = Shape(Vec3(0, 0, 0.15), Vec3(0.3, 0.1, 0.1), AboutY(kPi / 6));
  Vec3 warm = Vec3::Zero();
  const ContactGeometry g = EllipsoidEllipsoid(
      tilted, Shape(Vec3(0, 0, -big), Vec3::Constant(big), Mat3::Identity()), warm);
  const ContactGeometry plane = PlaneEllipsoid(Floor(), tilted);
  EXPECT_NEAR(g.deflection, plane.deflection, 3e-6);
  EXPECT_NEAR((g.normal - Vec3::UnitZ()).norm(), 0, 1e-4);
}

TEST(HyperEllipsoid, DegreeTwoIsTheEllipsoid) {
  const Vec3 axes(0.3, 0.1, 0.2);
  const Mat3 turn = AboutY(0.7) * AboutX(-0.4);
  for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(0.3, -0.5, 0.8), Vec3(-0.2, 0.1, -1)}) {
    const Vec3 n = direction.normalized();
    double h2 = 0, hh = 0;
    const Vec3 p2 = SupportPoint(Shape(Vec3::Zero(), axes, turn, 2.0), n, &h2);
    const Vec3 ph = SupportPoint(Shape(Vec3::Zero(), axes, turn, 2.0 + 1e-9), n, &hh);
    EXPECT_NEAR(h2, hh, 1e-9);
    EXPECT_NEAR((p2 - ph).norm(), 0, 1e-8);
  }
  const PlaneShape floor = Floor();
  const ContactGeometry e = PlaneEllipsoid(floor, Shape(Vec3(0, 0, 0.1), axes, turn, 2.0));
  const ContactGeometry h = PlaneEllipsoid(floor, Shape(Vec3(0, 0, 0.1), axes, turn, 2 + 1e-9));
  EXPECT_NEAR(e.deflection, h.deflection, 1e-9);
  EXPECT_NEAR((e.point - h.point).norm(), 0, 1e-8);
}

TEST(HyperEllipsoid, HighDegreeIsNearlyABox) {
  // Degree p, semi-axes a: the support point along (1, 1, 1) is a 3^(-1/p) (1, 1, 1); a box
  // face rests flat on a plane: the extent straight down is the semi-axis.
  const double a = 0.1, p = 32;
  double h = 0;
  const Vec3 corner = SupportPoint(Shape(Vec3::Zero(), Vec3::Constant(a), Mat3::Identity(), p),
                                   Vec3::Ones().normalized(), &h);
  EXPECT_NEAR((corner - Vec3::Constant(a * std::pow(3.0, -1.0 / p))).norm(), 0, 1e-14);
  EXPECT_NEAR(h, std::sqrt(3.0) * a * std::pow(3.0, -1.0 / p), 1e-14);
  const ContactGeometry g =
      PlaneEllipsoid(Floor(), Shape(Vec3(0, 0, 0.19), Vec3(0.3, 0.2, 0.2), Mat3::Identity(), 8));
  EXPECT_NEAR(g.deflection, 0.01, 1e-15);
  // Two boxy ellipsoids face to face overlap by their semi-axes less the distance; offset
  // sideways, as a brute-force search finds.
  const EllipsoidShape slab = Shape(Vec3::Zero(), Vec3(0.1, 0.2, 0.2), Mat3::Identity(), 6);
  Vec3 warm = Vec3::Zero();
  const ContactGeometry pair = EllipsoidEllipsoid(
      slab, Shape(Vec3(0.18, 0, 0), Vec3(0.1, 0.1, 0.1), Mat3::Identity(), 4), warm);
  EXPECT_NEAR(pair.deflection, 0.02, 1e-12);
  const EllipsoidShape offset = Shape(Vec3(0.18, 0.01, -0.02), Vec3(0.1, 0.1, 0.1), AboutX(0.3), 4);
  warm = Vec3::Zero();
  // The sampled minimum is an upper bound; near flat faces it converges slowly with the grid.
  const double sampled = BruteForceOverlap(slab, offset);
  const double found = EllipsoidEllipsoid(slab, offset, warm).deflection;
  EXPECT_LE(found, sampled + 1e-12);
  EXPECT_NEAR(found, sampled, 1e-6);
}

TEST(HyperEllipsoid, BoundingRadiusHoldsTheSurface) {
  for (const double degree : {2.0, 3.0, 4.0, 10.0}) {
    const EllipsoidShape shape = Shape(Vec3::Zero(), Vec3(0.3, 0.1, 0.2), Mat3::Identity(), degree);
    double widest = 0;
    for (int i = 0; i <= 60; ++i) {
      for (int j = 0; j < 120; ++j) {
        const double theta = kPi * i / 60, phi = 2 * kPi * j / 120;
        const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta));
        widest = std::max(widest, SupportPoint(shape, n, nullptr).norm());
      }
    }
    EXPECT_LE(widest, shape.radius * (1 + 1e-12)) << degree;
    EXPECT_GE(widest, 0.3 - 1e-12) << degree;
  }
}

}  // namespace
}  // namespace sled::runtime
