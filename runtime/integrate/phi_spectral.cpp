#include "runtime/integrate/phi_spectral.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "runtime/integrate/phi_functions.h"
#include "runtime/integrate/phi_two_by_two.h"

namespace sled::runtime {
namespace {

// Beyond this |z| the recurrence phi_{k+1} = (phi_k - 1/k!) / z from e^z loses nothing: each
// step divides by more than twice the order.
constexpr double kRecurrenceNorm = 2.0 * (SpectralPhi::kMaxOrder + 2);

// The series is summed at |z| / 2^s <= this, then squared back (as phi_functions.cpp does for
// matrices): at most kSeriesTerms terms, fewer when the next is below the unit roundoff.
constexpr double kSeriesNorm = 0.5;
constexpr int kSeriesTerms = 22;

double OneNorm(const Eigen::Ref<const Eigen::MatrixXd>& z) {
  double norm = 0.0;
  for (Eigen::Index j = 0; j < z.cols(); ++j) norm = std::max(norm, z.col(j).cwiseAbs().sum());
  return norm;
}

// phi_0(z) ... phi_p(z) for T = double or std::complex<double>, |z| = norm: a real eigenvalue
// (a decay) costs a quarter of the complex arithmetic.
template <class T>
void ScalarPhi(T z, double norm, int p, T* out) {
  if (norm > kRecurrenceNorm) {
    out[0] = std::exp(z);
    for (int k = 0; k < p; ++k) out[k + 1] = (out[k] - InverseFactorial(k)) / z;
    return;
  }
  int s = 0;
  if (norm > kSeriesNorm) s = static_cast<int>(std::ceil(std::log2(norm / kSeriesNorm)));
  const T x = std::ldexp(1.0, -s) * z;
  // The degree: the first neglected term |x|^(d+1) / (d+1+p)!, relative to phi_p's leading
  // 1/p!, below the unit roundoff (d = 12 at |x| = 1/2 and p = 5, fewer for smaller |x|).
  const double x_norm = std::ldexp(norm, -s);
  const int degree = PhiTaylorDegree(x_norm, p, kSeriesTerms);
  // phi_p(x) = sum_j x^j / (j + p)! by Horner, then phi_k = x phi_{k+1} + 1/k! downwards.
  T top = InverseFactorial(degree + p);
  for (int j = degree - 1; j >= 0; --j) top = x * top + InverseFactorial(j + p);
  out[p] = top;
  for (int k = p - 1; k >= 0; --k) out[k] = x * out[k + 1] + InverseFactorial(k);
  // Modified squaring: phi_k(2x) = 2^-k [phi_0(x) phi_k(x) + sum_{j=1..k} phi_j(x) / (k-j)!].
  T next[SpectralPhi::kMaxOrder + 1];
  for (int step = 0; step < s; ++step) {
    double half_power = 1.0;  // 2^-k
    for (int k = 1; k <= p; ++k) {
      half_power *= 0.5;
      T sum = out[0] * out[k];
      for (int j = 1; j <= k; ++j) sum += InverseFactorial(k - j) * out[j];
      next[k] = half_power * sum;
    }
    next[0] = out[0] * out[0];
    for (int k = 0; k <= p; ++k) out[k] = next[k];
  }
}

}  // namespace

void SpectralPhi::Scalar(std::complex<double> z, int p, std::complex<double>* out) {
  if (z.imag() == 0.0) {
    double real[kMaxOrder + 1];
    ScalarPhi(z.real(), std::abs(z.real()), p, real);
    for (int k = 0; k <= p; ++k) out[k] = real[k];
    return;
  }
  ScalarPhi(z, std::abs(z), p, out);
}

bool SpectralPhi::Decompose(const Eigen::Ref<const Eigen::MatrixXd>& z) {
  valid_ = false;
  block_count_ = 0;
  in_block_.fill(false);
  size_ = z.rows();
  if (size_ == 0 || size_ > kMaxSize || z.cols() != size_ || !z.allFinite()) return false;
  input_ = z;
  solver_.compute(input_, true);
  if (solver_.info() != Eigen::Success) return false;
  // The complex eigenvectors from the real pseudo-eigenvectors (a conjugate pair's real and
  // imaginary parts side by side), written in place: eigenvectors() returns a temporary of full
  // capacity, zeroed.
  const Real& pseudo = solver_.pseudoEigenvectors();
  values_ = solver_.eigenvalues();
  Reserve(size_);
  for (Eigen::Index j = 0; j < size_; ++j) {
    if (values_[j].imag() != 0.0 && j + 1 < size_) {
      for (Eigen::Index i = 0; i < size_; ++i) {
        vectors_(i, j) = {pseudo(i, j), pseudo(i, j + 1)};
        vectors_(i, j + 1) = {pseudo(i, j), -pseudo(i, j + 1)};
      }
      ++j;
    } else {
      for (Eigen::Index i = 0; i < size_; ++i) vectors_(i, j) = pseudo(i, j);
    }
  }
  // The eigenvectors' reciprocal condition number, and the size of Z: see the header (the
  // eigenvalues' rounding, eps ||Z|| / rcond, must stay small).
  const double norm = OneNorm(z);
  const auto acceptable = [this, norm] {
    const double rcond = ReciprocalCondition();
    return rcond > kMinReciprocalCondition && norm < kMaxNormOverCondition * rcond;
  };
  bool inverted = InvertVectors();
  while (!(inverted && acceptable())) {
    if (!BlockClosestPair()) return false;
    inverted = true;
  }
  valid_ = inverse_.topLeftCorner(size_, size_).allFinite();
  return valid_;
}

void SpectralPhi::Reserve(Eigen::Index capacity) {
  if (vectors_.rows() >= capacity) return;
  vectors_.resize(capacity, capacity);
  inverse_.resize(capacity, capacity);
  scaled_.resize(capacity, capacity);
}

double SpectralPhi::ReciprocalCondition() const {
  const auto one_norm = [this](const Complex& matrix) {
    double result = 0.0;
    for (Eigen::Index j = 0; j < size_; ++j) {
      double column = 0.0;
      for (Eigen::Index i = 0; i < size_; ++i) column += std::abs(matrix(i, j));
      result = std::max(result, column);
    }
    return result;
  };
  return 1.0 / (one_norm(vectors_) * one_norm(inverse_));
}

bool SpectralPhi::BlockClosestPair() {
  const Eigen::Index m = size_;
  // A 2 x 2 Z has its own closed form (phi_functions.h).
  if (m < 3 || 2 * static_cast<Eigen::Index>(block_count_ + 1) > m) return false;
  Eigen::Index first = -1, second = -1;
  double closest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < m; ++i) {
    if (in_block_[static_cast<std::size_t>(i)]) continue;
    for (Eigen::Index j = i + 1; j < m; ++j) {
      if (in_block_[static_cast<std::size_t>(j)]) continue;
      const bool real_pair = values_[i].imag() == 0.0 && values_[j].imag() == 0.0;
      if (!real_pair && values_[i] != std::conj(values_[j])) continue;
      const double distance = std::abs(values_[i] - values_[j]);
      if (distance < closest) {
        closest = distance;
        first = i;
        second = j;
      }
    }
  }
  if (first < 0) return false;
  // The pair's invariant subspace: the null space of P = (Z - l1 I)(Z - l2 I), a real matrix,
  // which is the orthogonal complement of P^T's range: the last two columns of the Q of P^T's
  // QR decomposition with column pivoting.
  const double sum = (values_[first] + values_[second]).real();
  const double product = (values_[first] * values_[second]).real();
  work_.noalias() = input_ * input_;
  work_ -= sum * input_;
  work_.diagonal().array() += product;
  null_space_.compute(work_.transpose());
  work_ = null_space_.householderQ();
  for (Eigen::Index i = 0; i < m; ++i) {
    vectors_(i, first) = work_(i, m - 2);
    vectors_(i, second) = work_(i, m - 1);
  }
  if (!InvertVectors()) return false;
  // B = the rows of W^-1 for the pair times Z [q1, q2], and the residual Z q - [q1, q2] B,
  // which is rounding only when the subspace is invariant.
  Block& block = blocks_[static_cast<std::size_t>(block_count_)];
  double residual = 0.0;
  Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxSize, 2> zq(m, 2);
  zq.col(0).noalias() = input_ * work_.col(m - 2);
  zq.col(1).noalias() = input_ * work_.col(m - 1);
  for (int c = 0; c < 2; ++c) {
    for (int r = 0; r < 2; ++r) {
      std::complex<double> entry = 0.0;
      const Eigen::Index row = r == 0 ? first : second;
      for (Eigen::Index l = 0; l < m; ++l) entry += inverse_(row, l) * zq(l, c);
      block.b(r, c) = entry.real();
    }
    for (Eigen::Index l = 0; l < m; ++l) {
      const double fitted = work_(l, m - 2) * block.b(0, c) + work_(l, m - 1) * block.b(1, c);
      residual = std::max(residual, std::abs(zq(l, c) - fitted));
    }
  }
  if (!(residual <= kBlockResidual * OneNorm(input_))) return false;
  block.first = first;
  block.second = second;
  in_block_[static_cast<std::size_t>(first)] = true;
  in_block_[static_cast<std::size_t>(second)] = true;
  ++block_count_;
  return true;
}

bool SpectralPhi::InvertVectors() {
  const Eigen::Index m = size_;
  Complex& elimination = scaled_;  // free until Evaluate
  for (Eigen::Index j = 0; j < m; ++j) {
    for (Eigen::Index i = 0; i < m; ++i) {
      elimination(i, j) = vectors_(i, j);
      inverse_(i, j) = i == j ? 1.0 : 0.0;
    }
  }
  for (Eigen::Index k = 0; k < m; ++k) {
    Eigen::Index pivot = k;
    for (Eigen::Index i = k + 1; i < m; ++i) {
      if (std::abs(elimination(i, k)) > std::abs(elimination(pivot, k))) pivot = i;
    }
    if (!(std::abs(elimination(pivot, k)) > 0.0)) return false;
    if (pivot != k) {
      for (Eigen::Index j = 0; j < m; ++j) {
        std::swap(elimination(k, j), elimination(pivot, j));
        std::swap(inverse_(k, j), inverse_(pivot, j));
      }
    }
    const std::complex<double> scale = 1.0 / elimination(k, k);
    for (Eigen::Index j = 0; j < m; ++j) {
      elimination(k, j) *= scale;
      inverse_(k, j) *= scale;
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      const std::complex<double> factor = elimination(i, k);
      if (i == k || factor == 0.0) continue;
      for (Eigen::Index j = 0; j < m; ++j) {
        elimination(i, j) -= factor * elimination(k, j);
        inverse_(i, j) -= factor * inverse_(k, j);
      }
    }
  }
  return true;
}

void SpectralPhi::ToEigenbasis(const Eigen::Ref<const Eigen::VectorXd>& x,
                               ComplexVector& coordinates) const {
  const Eigen::Index m = size_;
  coordinates.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    std::complex<double> sum = 0.0;
    for (Eigen::Index l = 0; l < x.size() && l < m; ++l) sum += inverse_(i, l) * x[l];
    coordinates[i] = sum;
  }
}

void SpectralPhi::FromEigenbasis(const ComplexVector& coordinates,
                                 Eigen::Ref<Eigen::VectorXd> x) const {
  const Eigen::Index m = size_;
  for (Eigen::Index i = 0; i < m; ++i) {
    double sum = 0.0;
    for (Eigen::Index l = 0; l < m; ++l) {
      sum += vectors_(i, l).real() * coordinates[l].real() -
             vectors_(i, l).imag() * coordinates[l].imag();
    }
    x[i] = sum;
  }
}

void SpectralPhi::PrepareFunctions(double theta, int p) const {
  for (Eigen::Index i = 0; i < size_; ++i) {
    if (in_block_[static_cast<std::size_t>(i)]) continue;
    std::complex<double> values[kMaxOrder + 1];
    Scalar(theta * values_[i], p, values);
    for (int k = 0; k <= p; ++k) functions_(k, i) = values[k];
  }
  for (int j = 0; j < block_count_; ++j) {
    Block& block = blocks_[static_cast<std::size_t>(j)];
    TwoByTwoPhi(block.b, theta, p, block.functions);
  }
}

void SpectralPhi::ApplyFunction(int k, double weight, const ComplexVector& coordinates,
                                ComplexVector& out) const {
  for (Eigen::Index i = 0; i < size_; ++i) {
    if (in_block_[static_cast<std::size_t>(i)]) continue;
    out[i] += weight * functions_(k, i) * coordinates[i];
  }
  for (int j = 0; j < block_count_; ++j) {
    const Block& block = blocks_[static_cast<std::size_t>(j)];
    const Eigen::Matrix2d& f = block.functions[k];
    const std::complex<double> a = coordinates[block.first], b = coordinates[block.second];
    out[block.first] += weight * (f(0, 0) * a + f(0, 1) * b);
    out[block.second] += weight * (f(1, 0) * a + f(1, 1) * b);
  }
}

void SpectralPhi::Evaluate(double theta, int p, std::span<Eigen::MatrixXd> phi) const {
  if (!valid_ || p < 0 || p > kMaxOrder || phi.size() <= static_cast<std::size_t>(p)) {
    throw std::logic_error("SpectralPhi::Evaluate: Decompose first; 0 <= p <= kMaxOrder");
  }
  const Eigen::Index m = size_;
  PrepareFunctions(theta, p);
  // Re(W diag(f) W^-1) by plain loops: Eigen's expressions on these fixed-capacity complex
  // matrices made temporaries of full capacity, each zeroed (std::complex's constructor).
  for (int k = 0; k <= p; ++k) {
    for (Eigen::Index l = 0; l < m; ++l) {
      if (in_block_[static_cast<std::size_t>(l)]) continue;
      scaled_.col(l).head(m) = vectors_.col(l).head(m) * functions_(k, l);
    }
    for (int j = 0; j < block_count_; ++j) {
      // W's pair of columns times phi_k(theta B).
      const Block& block = blocks_[static_cast<std::size_t>(j)];
      const Eigen::Matrix2d& f = block.functions[k];
      for (Eigen::Index i = 0; i < m; ++i) {
        const std::complex<double> a = vectors_(i, block.first), b = vectors_(i, block.second);
        scaled_(i, block.first) = a * f(0, 0) + b * f(1, 0);
        scaled_(i, block.second) = a * f(0, 1) + b * f(1, 1);
      }
    }
    auto out = phi[static_cast<std::size_t>(k)].topLeftCorner(m, m);
    for (Eigen::Index j = 0; j < m; ++j) {
      for (Eigen::Index i = 0; i < m; ++i) {
        double sum = 0.0;
        for (Eigen::Index l = 0; l < m; ++l) {
          sum += scaled_(i, l).real() * inverse_(l, j).real() -
                 scaled_(i, l).imag() * inverse_(l, j).imag();
        }
        out(i, j) = sum;
      }
    }
  }
}

}  // namespace sled::runtime
