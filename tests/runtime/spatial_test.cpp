// The blockwise spatial transforms (runtime/dynamics/spatial.h) against the plain 6x6 products with
// the transform's matrix X: X m, X^T f and X^T I X, for random rotations, offsets and symmetric
// inertias.
#include <random>

#include <gtest/gtest.h>

#include "runtime/dynamics/spatial.h"

namespace sled::runtime {
namespace {

using Mat3 = Eigen::Matrix3d;

struct RandomSpatial {
  std::mt19937_64 engine{7};
  std::uniform_real_distribution<double> uniform{-1.0, 1.0};
  double Next() { return uniform(engine); }
  Transform NextTransform() {
    Transform x;
    Eigen::Quaterniond q(Next(), Next(), Next(), Next());
    x.E = q.normalized().toRotationMatrix();
    x.r = Eigen::Vector3d(Next(), Next(), Next());
    return x;
  }
  Mat6 NextSymmetric() {
    Mat6 m;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) m(i, j) = Next();
    }
    return m + m.transpose() + 12.0 * Mat6::Identity();
  }
};

TEST(Spatial, BlockwiseTransformsMatchTheSixBySixProducts) {
  RandomSpatial random;
  for (int trial = 0; trial < 20; ++trial) {
    const Transform x = random.NextTransform();
    const Mat6 X = x.Matrix();
    Vec6 m;
    for (int k = 0; k < 6; ++k) m[k] = random.Next();
    EXPECT_LT((x.ApplyMotion(m) - X * m).norm(), 1e-14);
    EXPECT_LT((x.TransposeApplyForce(m) - X.transpose() * m).norm(), 1e-14);
    const Mat6 inertia = random.NextSymmetric();
    const Mat6 expected = X.transpose() * inertia * X;
    EXPECT_LT((x.TransposeApplyInertia(inertia) - expected).norm(), 1e-12 * expected.norm());
    // The accumulating form adds to what is there.
    const Mat6 start = random.NextSymmetric();
    Mat6 sum = start;
    x.AddTransposeApplyInertia(inertia, sum);
    EXPECT_LT((sum - start - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(Spatial, PointInertiaTransformMatchesTheSixBySixProducts) {
  RandomSpatial random;
  for (int trial = 0; trial < 20; ++trial) {
    const Transform x = random.NextTransform();
    const Mat6 X = x.Matrix();
    const Mat6 any = random.NextSymmetric();
    const Mat3 K = any.topLeftCorner<3, 3>();
    const Eigen::Vector3d p(random.Next(), random.Next(), random.Next());
    // The inertia of K at p: [-p~ K p~, p~ K; -K p~, K], written with the 6x6 shift.
    Mat6 shift = Mat6::Identity();
    shift.bottomLeftCorner<3, 3>() = -Skew(p);
    Mat6 at_point = Mat6::Zero();
    at_point.bottomRightCorner<3, 3>() = K;
    const Mat6 inertia = shift.transpose() * at_point * shift;
    const Mat6 expected = X.transpose() * inertia * X;
    Mat6 sum = Mat6::Zero();
    x.AddTransposeApplyPointInertia(K, p, sum);
    EXPECT_LT((sum - expected).norm(), 1e-12 * expected.norm());
  }
}

}  // namespace
}  // namespace sled::runtime
