// The phi-functions of a 2 x 2 matrix, defective or not, with no eigenvectors:
//
//   Z = mu I + N,   mu = trace(Z) / 2,   N^2 = delta I,   delta = ((z00 - z11) / 2)^2 + z01 z10,
//
// so every power of Z, and so every phi_k(theta Z), is a I + b N for two scalars (a, b): the
// functions are computed in that two-dimensional commutative algebra, (a1 + b1 N)(a2 + b2 N) =
// (a1 a2 + delta b1 b2) + (a1 b2 + b1 a2) N, by the Taylor series at theta Z / 2^s and the
// modified squaring of phi_functions.h, and formed as a I + b N at the end. A critically damped
// oscillator (delta = 0: a Jordan block, whose eigenvectors are parallel) is no special case:
// b is then the derivative phi_k'(theta mu), which the eigen-decomposition cannot give (it
// refuses such a matrix, phi_spectral.h) and the matrix squaring gives at (p + 1) 2 x 2
// products per squaring. A stiff spring that is critically damped (`step_1000g`) made the
// exponential method's phi-functions take the matrix squaring at every step and output row.
#pragma once

#include <Eigen/Core>
#include <span>

namespace sled::runtime {

// phi_0(theta Z) ... phi_p(theta Z) of a finite 2 x 2 Z into the top-left 2 x 2 corners of
// phi[0..p] (each at least 2 x 2); 0 <= p <= PhiFunctions::kMaxOrder.
void TwoByTwoPhi(const Eigen::Ref<const Eigen::MatrixXd>& z, double theta, int p,
                 std::span<Eigen::MatrixXd> phi);

// The same as 2 x 2 matrices on the stack (phi_k(theta Z) = phi[k]), for a block of a larger
// decomposition (phi_spectral.h).
void TwoByTwoPhi(const Eigen::Matrix2d& z, double theta, int p, Eigen::Matrix2d* phi);

}  // namespace sled::runtime
