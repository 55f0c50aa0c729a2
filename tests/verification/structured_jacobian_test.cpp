// The multibody system's structured Jacobian (runtime/dynamics/multibody_jacobian.h) against the
// dense Jacobian of its derivative by central differences, an independent reference: on scenes with
// loaded contacts, belts, joint stops, damping and an airbag, at states taken from a dopri5 run,
// the remainder J - A must be non-stiff: its spectral radius far below J's where J is stiff, and
// small against the step A was formed for (the terms A leaves out are those too soft for it).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/structured_jacobian.h"
#include "runtime/run/system.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

struct JacobianCase {
  std::string file;  // under examples/
  std::vector<std::pair<std::string, std::string>> overrides;
  double time;  // a state with the stiff elements loaded
  double step;  // the step A is formed for
};

void PrintTo(const JacobianCase& c, std::ostream* out) { *out << c.file << " at " << c.time; }

double SpectralRadius(const Eigen::MatrixXd& m) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(m, false).eigenvalues().cwiseAbs().maxCoeff();
}

class StructuredJacobianTest : public ::testing::TestWithParam<JacobianCase> {};

INSTANTIATE_TEST_SUITE_P(
    Scenes, StructuredJacobianTest,
    ::testing::Values(
        // A ball pressed into a 1e9 N/m floor (mid-contact).
        JacobianCase{"numerics/contact_stiffness.sled", {{"stiffness", "1e9 N/m"}}, 0.06390, 1e-3},
        // The belt stretched by a 20 kg mass, and the cushion under a 100 g pulse: stiff only
        // against steps of tens of milliseconds.
        JacobianCase{"numerics/belt_restraint.sled", {}, 0.02, 0.05},
        JacobianCase{"numerics/pulse_100g.sled", {}, 0.05, 0.05},
        // The lower hinge of the falling chain in its stiff stop (30,000 N*m/rad).
        JacobianCase{"numerics/joint_stops.sled", {}, 0.416, 1e-3},
        // The flagship: a belted occupant on a seat, joints with stops, 60 ms into the pulse;
        // and with its airbag, whose gas is loaded then.
        JacobianCase{"frontal_sled.sled", {}, 0.06, 1e-4},
        JacobianCase{"frontal_sled_airbag.sled", {}, 0.06, 1e-4}));

TEST_P(StructuredJacobianTest, LeavesOnlyANonStiffRemainder) {
  const JacobianCase c = GetParam();
  const Compiled compiled =
      CompileFile(std::filesystem::path(SLED_SOURCE_ROOT) / "examples" / c.file, c.overrides);
  ASSERT_TRUE(compiled.errors.empty()) << compiled.errors;
  const runtime::Model& model = compiled.model();
  runtime::Data data = runtime::MakeData(model);
  runtime::MultibodySystem system(model, data);
  const std::size_t n = system.size();
  std::vector<double> y(n);
  system.Store(y);
  runtime::DormandPrince dopri5;
  runtime::IntegratorOptions options;
  options.relative_tolerance = 1e-8;
  options.absolute_tolerance = 1e-10;
  dopri5.Reset(system, model.start_time, y, options);
  ASSERT_EQ(dopri5.Advance(c.time).status, runtime::IntegratorStatus::kOk);
  y.assign(dopri5.state().begin(), dopri5.state().end());

  // The reference: central differences of the derivative, column by column.
  const std::size_t m = system.ControlledSize();
  std::vector<double> f0(n), plus(n), minus(n), shifted(n);
  ASSERT_TRUE(system.Derivative(c.time, y, f0));
  Eigen::MatrixXd reference(m, m);
  for (std::size_t j = 0; j < m; ++j) {
    const double delta = 1e-7 * std::max(1.0, std::abs(y[j]));
    shifted = y;
    shifted[j] = y[j] + delta;
    ASSERT_TRUE(system.Derivative(c.time, shifted, plus));
    shifted[j] = y[j] - delta;
    ASSERT_TRUE(system.Derivative(c.time, shifted, minus));
    for (std::size_t i = 0; i < m; ++i) {
      reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          (plus[i] - minus[i]) / (2 * delta);
    }
  }

  runtime::StructuredJacobian jacobian;
  jacobian.Reserve(n, system.StructuredRank());
  ASSERT_TRUE(system.StructuredJacobianAt(c.time, y, f0, c.step, jacobian));
  ASSERT_TRUE(jacobian.NilpotentByPattern());
  const Eigen::MatrixXd a = jacobian.Dense().topLeftCorner(m, m);
  const double stiff = SpectralRadius(reference);
  const double kept = SpectralRadius(a);
  const double remainder = SpectralRadius(reference - a);
  std::printf("  %s at %.4f s: rank %ld; spectral radius of J %.3e, of A %.3e, of J - A %.3e\n",
              c.file.c_str(), c.time, static_cast<long>(jacobian.rank()), stiff, kept, remainder);
  // The scene is stiff at this state and step (else the test would prove nothing).
  EXPECT_GT(stiff * c.step, 2.0);
  // A holds the stiff part: what it leaves is non-stiff at the step it was formed for (its terms
  // below 0.2 / step are left out by design; together they stay below 1 / step).
  EXPECT_LT(remainder * c.step, 1.0);
  EXPECT_LT(remainder, 0.2 * stiff);
  EXPECT_NEAR(kept, stiff, 0.2 * stiff);
}

}  // namespace
}  // namespace sled::verification
