// A mass on a linear spring–damper (a slip joint to the ground with a joint characteristic, and
// separately a spring element between the ground and a free segment) against the closed-form
// underdamped response x(t) = e^{-zeta w t} (x0 cos(wd t) + (zeta w x0 / wd) sin(wd t)).
#include <cmath>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

double Response(double k, double c, double m, double x0, double t) {
  const double w = std::sqrt(k / m);
  const double zeta = c / (2 * std::sqrt(k * m));
  const double wd = w * std::sqrt(1 - zeta * zeta);
  return std::exp(-zeta * w * t) * (x0 * std::cos(wd * t) + zeta * w * x0 / wd * std::sin(wd * t));
}

class SpringDamper : public ::testing::TestWithParam<std::string> {};

TEST_P(SpringDamper, SpringElementMatchesTheClosedForm) {
  runtime::Model model;
  model.gravity.setZero();
  const double m = 2.0, k = 800.0, c = 6.0, x0 = 0.05, free_length = 0.5;
  runtime::testing::AddSegment(model, "mass", -1, runtime::JointKind::kFree, m,
                               runtime::Vec3(0.01, 0.01, 0.01));
  model.q0[0] = free_length + x0;
  // A linear spring: the polynomial 0 + k x.
  model.functions.kind = {runtime::FunctionTable::Kind::kPolynomial};
  model.functions.constant = {0};
  model.functions.first = {0};
  model.functions.count = {2};
  model.functions.energy_loss = {0};
  model.functions.permanent_set = {0};
  model.functions.coefficients = {0.0, k};
  model.spring_name = {"spring"};
  model.spring_first = {{runtime::FrameRef::Kind::kSegment, 0}};
  model.spring_second = {{runtime::FrameRef::Kind::kGround, -1}};
  model.spring_point_first = {runtime::Vec3::Zero()};
  model.spring_point_second = {runtime::Vec3::Zero()};
  model.spring_function = {0};
  model.spring_damping = {c};
  model.spring_free_length = {free_length};
  model.spring_tension_only = {0};
  runtime::Data data = runtime::MakeData(model);
  double worst = 0;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-10, Linspace(0, 1.0, 200), [&](const runtime::Data& d) {
        const double x = d.position[0].x() - free_length;
        worst = std::max(worst, std::abs(x - Response(k, c, m, x0, d.time)));
      }));
  EXPECT_LT(worst, 1e-7 * x0 * 100);  // 1e-5 relative to the amplitude
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, SpringDamper, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
