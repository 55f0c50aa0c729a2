// The shapes the animation draws: every segment's declared ellipsoids that are no contact
// ellipsoid (those are drawn from the contact table), and for a segment without any ellipsoid the
// ellipsoid of uniform density that has its mass and principal moments, so that an arm without
// contacts is still drawn.
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "compiler/lower/lowering.h"

namespace sled::compiler::lowering {

void LowerShapes(Lowering& lowering) {
  runtime::Model& model = lowering.model();
  const CheckedScenario& scenario = lowering.scenario();
  const auto& drawn = model.contacts.ellipsoid_name;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const Segment& segment = lowering.segment(lowering.old_index[s]);
    for (const int e : segment.ellipsoids) {
      const Ellipsoid& ellipsoid = scenario.ellipsoids[static_cast<std::size_t>(e)];
      if (std::find(drawn.begin(), drawn.end(), ellipsoid.name) != drawn.end()) continue;
      model.shape_name.push_back(ellipsoid.name);
      model.shape_segment.push_back(static_cast<std::int32_t>(s));
      model.shape_center.push_back(ToEigen(ellipsoid.center));
      model.shape_axes.push_back(RotationMatrix(ellipsoid.orientation));
      model.shape_semi_axes.push_back(ToEigen(ellipsoid.semi_axes));
      model.shape_degree.push_back(ellipsoid.degree);
    }
    if (!segment.ellipsoids.empty() || !(model.segment_mass[s] > 0)) continue;
    // A solid ellipsoid of mass m and semi-axes a, b, c has I_x = m (b^2 + c^2) / 5, ...:
    // a^2 = 5 (I_y + I_z - I_x) / (2 m) about the principal axes.
    const Eigen::SelfAdjointEigenSolver<runtime::Mat3> principal(model.segment_inertia[s]);
    const runtime::Vec3 moments = principal.eigenvalues();
    runtime::Vec3 semi;
    for (int i = 0; i < 3; ++i) {
      const double twice = moments.sum() - 2 * moments[i];
      semi[i] = std::sqrt(std::max(5 * twice / (2 * model.segment_mass[s]), 0.0));
    }
    if (!(semi.maxCoeff() > 0)) continue;
    semi = semi.cwiseMax(1e-3 * semi.maxCoeff());  // a flat body stays visible
    model.shape_name.push_back(segment.name + ".inertia");
    model.shape_segment.push_back(static_cast<std::int32_t>(s));
    model.shape_center.push_back(runtime::Vec3::Zero());
    model.shape_axes.push_back(principal.eigenvectors());
    model.shape_semi_axes.push_back(semi);
    model.shape_degree.push_back(2.0);
  }
}

}  // namespace sled::compiler::lowering
