// Every attribute of `initial` is simulated or refused (issue 15: "nothing silently wrong"). A
// vehicle's initial position, orientation, velocity and angular velocity each move the frame a
// point at rest is seen from, as the closed form of a frame turning at a constant rate says; a
// root held at a point of a turning vehicle takes its angular velocity in the ground frame (as
// docs/language.md §16 says every initial velocity is), so given the vehicle's own rate it stays
// at rest in the vehicle; what the model cannot take is refused with E0421; and planar symmetry
// says when it drops the out-of-plane part of an initial position.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

using runtime::Vec3;

// A point at rest at (1, 0.5, 0) m in the ground, seen from a car that starts at p0 yawed by
// psi0, moves at v and turns at w about z: r(t) = Rz(-(psi0 + w t)) (x - p0 - v t).
TEST(InitialConditions, EachOfAVehiclesInitialAttributesMovesItsFrame) {
  const SceneRun run = RunText(R"(scenario "vehicle start" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 50 ms }
  integrator dopri5 { tolerance = 1e-10 }
  vehicle car { }
  body marker { segment m { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  initial marker { position = (1, 0.5, 0) m }
  initial car {
    position = (0.3, -0.2, 0.1) m
    orientation = (30, 0, 0) deg
    velocity = (2, 1, 0) m/s
    angular_velocity = (0, 0, 1.5) rad/s
  }
  output { position marker.m relative_to car }
})");
  ASSERT_EQ(run.errors, "");
  const runtime::TimeSeries& s = run.series;
  ASSERT_EQ(s.rows(), 21u);
  const Vec3 x(1, 0.5, 0), p0(0.3, -0.2, 0.1), v(2, 1, 0);
  const double psi0 = 30 * M_PI / 180, w = 1.5;
  for (std::size_t row = 0; row < s.rows(); ++row) {
    const double t = TimeAt(s, row);
    const Vec3 d = x - p0 - v * t;
    const double a = -(psi0 + w * t);
    const Vec3 r(std::cos(a) * d.x() - std::sin(a) * d.y(),
                 std::sin(a) * d.x() + std::cos(a) * d.y(), d.z());
    const std::string prefix = "marker.m.relative_to.car.position.";
    EXPECT_NEAR(ChannelAt(s, prefix + "x [m]", row), r.x(), 1e-7) << t;
    EXPECT_NEAR(ChannelAt(s, prefix + "y [m]", row), r.y(), 1e-7) << t;
    EXPECT_NEAR(ChannelAt(s, prefix + "z [m]", row), r.z(), 1e-7) << t;
  }
}

// A bar held at a point of a car turning at 2 rad/s, given the car's angular velocity (in the
// ground frame): it stays at rest in the car. Read as a rate relative to the car (as before),
// the bar spun at 4 rad/s in the ground and turned away from the car at 2 rad/s.
TEST(InitialConditions, AHeldRootsAngularVelocityIsInTheGroundFrame) {
  const SceneRun run = RunText(R"(scenario "held on a turning car" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 50 ms }
  integrator dopri5 { tolerance = 1e-10 }
  vehicle car { }
  body bar { segment rod { mass = 1 kg  inertia = (0.001, 0.02, 0.02) kg*m^2 } }
  constraint pivot : fixed_point(car -> bar.rod) {
    at car = (500, 0, 0) mm
    at bar.rod = (-250, 0, 0) mm
  }
  initial car { angular_velocity = (0, 0, 2) rad/s }
  initial bar { angular_velocity = (0, 0, 2) rad/s }
  output {
    position bar.rod relative_to car
    angular_velocity bar.rod
  }
})");
  ASSERT_EQ(run.errors, "");
  const runtime::TimeSeries& s = run.series;
  for (std::size_t row = 0; row < s.rows(); ++row) {
    const double t = TimeAt(s, row);
    EXPECT_NEAR(ChannelAt(s, "bar.rod.relative_to.car.position.x [m]", row), 0.75, 1e-7) << t;
    EXPECT_NEAR(ChannelAt(s, "bar.rod.relative_to.car.position.y [m]", row), 0.0, 1e-7) << t;
    EXPECT_NEAR(ChannelAt(s, "bar.rod.angular_velocity.z [rad/s]", row), 2.0, 1e-7) << t;
  }
}

// What the model cannot take is refused before anything runs, never ignored.
TEST(InitialConditions, WhatTheModelCannotTakeIsRefused) {
  const std::string body = R"(
  time { end = 100 ms  output_every = 1 ms }
  body b {
    segment upper { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    segment lower { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    joint knee : pin(upper -> lower) {
      at upper = (0, 0, -200) mm
      at lower = (0, 0, 200) mm
      axis = (0, 1, 0)
    }
  }
  constraint pivot : fixed_point(ground -> b.upper) {
    at ground = (0, 0, 1000) mm
    at b.upper = (0, 0, 200) mm
  }
)";
  struct Case {
    std::string initial, expected;
  };
  const Case cases[] = {
      {"initial b.lower { position = (0, 0, 1) m }", "initial position of `b.lower`"},
      {"initial b.lower { orientation = (0, 10, 0) deg }", "initial orientation of `b.lower`"},
      {"initial b.lower { velocity = (1, 0, 0) m/s }", "initial velocity of `b.lower`"},
      {"initial b { position = (0, 0, 0) m }", "from where constraint `pivot` holds it"},
      {"initial b { velocity = (1, 0, 0) m/s }", "contradicts constraint `pivot`"},
  };
  for (const Case& c : cases) {
    const Compiled compiled = CompileText("scenario \"s\" {" + body + "  " + c.initial + "\n}\n");
    EXPECT_NE(compiled.errors.find("error[E0421]"), std::string::npos) << c.initial;
    EXPECT_NE(compiled.errors.find(c.expected), std::string::npos) << c.initial << "\n"
                                                                   << compiled.errors;
  }
  // What the held point implies is accepted: the bar hangs 0.2 m below the pivot and turns at
  // 3 rad/s about y, so its centre moves at 3 * 0.2 = 0.6 m/s along -x.
  const Compiled held =
      CompileText("scenario \"s\" {" + body +
                  "  initial b { position = (0, 0, 0.8) m  velocity = (-0.6, 0, 0) m/s\n"
                  "              angular_velocity = (0, 3, 0) rad/s }\n"
                  "  initial b.lower { angular_velocity = (0, 3, 0) rad/s }\n}\n");
  EXPECT_EQ(held.errors, "");
}

TEST(InitialConditions, PlanarSymmetryNotesTheOutOfPlanePartOfAPosition) {
  const Compiled compiled = CompileText(R"(scenario "planar" {
  time { end = 100 ms  output_every = 1 ms }
  symmetry planar
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  initial b { position = (0.1, 0.3, 0.2) m }
})");
  ASSERT_EQ(compiled.errors, "");
  EXPECT_NE(compiled.notes().find("N0404"), std::string::npos) << compiled.notes();
  EXPECT_NE(compiled.notes().find("initial position of `b.s`"), std::string::npos)
      << compiled.notes();
}

}  // namespace
}  // namespace sled::verification
