// The geometry of wind and water (runtime/forces/fluid_forces.h) against closed forms: a sphere
// presents pi r^2 from every side and an ellipsoid pi a b along c; a sphere cut through its centre
// has half its volume below with the centroid 3 r / 8 down (a hemisphere's); a cap of height r/2
// holds 5/32 of the volume (pi h^2 (3 r - h) / 3 over 4 pi r^3 / 3); an ellipsoid stretched by c
// along `up` scales the cut heights and centroid by c, at any attitude of its other axes.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "runtime/forces/fluid_forces.h"

namespace sled::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(FluidGeometry, ProjectedAreasOfASphereAndAnEllipsoid) {
  const Vec3 sphere(0.3, 0.3, 0.3);
  EXPECT_NEAR(ProjectedArea(sphere, Vec3(1, 2, -2).normalized()), kPi * 0.09, 1e-15);
  const Vec3 ellipsoid(0.2, 0.15, 0.1);
  EXPECT_NEAR(ProjectedArea(ellipsoid, Vec3::UnitZ()), kPi * 0.2 * 0.15, 1e-15);
  EXPECT_NEAR(ProjectedArea(ellipsoid, Vec3::UnitX()), kPi * 0.15 * 0.1, 1e-15);
}

TEST(FluidGeometry, ASphereCutThroughItsCentreOrAtACap) {
  const double r = 0.5;
  const Mat3 shape = r * r * Mat3::Identity();
  const Vec3 up = Vec3::UnitZ(), center(1, 2, 3);
  const SubmergedPart half = SubmergedPartOf(center, shape, up, 3.0);
  EXPECT_NEAR(half.fraction, 0.5, 1e-15);
  EXPECT_NEAR((half.centroid - (center - 3 * r / 8 * up)).norm(), 0.0, 1e-15);
  // The surface r/2 below the centre: a cap of height h = r/2 under water.
  const double h = r / 2;
  const SubmergedPart cap = SubmergedPartOf(center, shape, up, 3.0 - r / 2);
  EXPECT_NEAR(cap.fraction, (kPi * h * h * (3 * r - h) / 3) / (4 * kPi * r * r * r / 3), 1e-15);
  // A cap's centroid lies 3 (2 r - h)^2 / (4 (3 r - h)) below the sphere's centre.
  const double depth = 3 * (2 * r - h) * (2 * r - h) / (4 * (3 * r - h));
  EXPECT_NEAR((cap.centroid - (center - depth * up)).norm(), 0.0, 1e-15);
  EXPECT_EQ(SubmergedPartOf(center, shape, up, 3.0 - r).fraction, 0.0);
  EXPECT_EQ(SubmergedPartOf(center, shape, up, 3.0 + r).fraction, 1.0);
}

TEST(FluidGeometry, AnEllipsoidTurnedAboutTheVerticalCutsAsItsVerticalAxisSays) {
  const Vec3 a(0.2, 0.15, 0.1);
  const Mat3 axes = Eigen::AngleAxisd(0.7, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 shape = axes * a.cwiseProduct(a).asDiagonal() * axes.transpose();
  const SubmergedPart half = SubmergedPartOf(Vec3::Zero(), shape, Vec3::UnitZ(), 0.0);
  EXPECT_NEAR(half.fraction, 0.5, 1e-15);
  EXPECT_NEAR((half.centroid - Vec3(0, 0, -3 * 0.1 / 8)).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace sled::runtime
