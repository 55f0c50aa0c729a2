#include "runtime/restraint/belt_slip.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime {
namespace {

constexpr int kMaxIterations = 60;
constexpr int kMaxHalvings = 40;
constexpr double kRelativeTolerance = 1e-12;  // of the junction's two tensions
constexpr double kAbsoluteTolerance = 1e-9;   // [N]
constexpr double kShortest = 1e-12;           // [m] of webbing a span keeps at least

std::size_t Index(std::int32_t value) { return static_cast<std::size_t>(value); }

// Every span's rest length from its start value and the junctions' transfers.
void SetRestLengths(BeltState& state) {
  std::copy(state.base_length.begin(), state.base_length.end(), state.rest_length.begin());
  for (std::size_t j = 0; j < state.transfer.size(); ++j) {
    state.rest_length[Index(state.junction_first[j])] -= state.transfer[j];
    state.rest_length[Index(state.junction_second[j])] += state.transfer[j];
  }
}

// Junction j's residual (zero when its mode's condition holds) and its tolerance; with `row` the
// derivatives with respect to the unknowns.
struct Residual {
  double value = 0.0;
  double tolerance = 0.0;
};

// Junction j's row of the Jacobian from its derivatives with respect to the rest lengths of its
// spans a and c and to its own transfer.
void FillRow(const BeltState& state, std::size_t j, std::size_t a, std::size_t c, double d_first,
             double d_second, double d_own, double* row) {
  // A transfer k takes webbing from its first span into its second.
  for (std::size_t k = 0; k < state.transfer.size(); ++k) {
    const std::int32_t unknown = state.solve_index[k];
    if (unknown < 0) continue;
    const auto from = Index(state.junction_first[k]), into = Index(state.junction_second[k]);
    double d = k == j ? d_own : 0.0;
    if (into == a) d += d_first;
    if (from == a) d -= d_first;
    if (into == c) d += d_second;
    if (from == c) d -= d_second;
    row[Index(unknown)] = d;
  }
}

Residual JunctionResidual(const Model& model, const BeltState& state, std::size_t j, double* row) {
  const std::size_t a = Index(state.junction_first[j]), c = Index(state.junction_second[j]);
  const SpanForce fa = SpanForceAt(model, state, a, state.rest_length[a]);
  const SpanForce fc = SpanForceAt(model, state, c, state.rest_length[c]);
  const double r = state.junction_ratio[j];
  // d residual / d rest length of the first and of the second span, and d residual / d its own
  // transfer beyond them.
  double value = 0.0, d_first = 0.0, d_second = 0.0, d_own = 0.0;
  if (state.mode[j] == JunctionMode::kStick) {
    // A wrap whose body carries the webbing: the unstretched webbing passed since it stuck, at
    // the mean of the stretch then and now (the two spans' mean stretch), is the length the body
    // carried. That stretch makes the tension difference's work on the body the change of a
    // linear webbing's energy; taking its mean over the way (the trapezoid rule) keeps the
    // energy to the third order of the transfer.
    const double passed = state.transfer[j] - state.held_transfer[j];
    const double la = state.length[a], lc = state.length[c];
    const double ra = std::max(state.rest_length[a], kShortest);
    const double rc = std::max(state.rest_length[c], kShortest);
    const double stretch = 0.5 * (la / ra + lc / rc);
    const double mean = 0.5 * (state.carry_stretch[j] + stretch);
    value = passed * mean - state.carried_arc[j];
    d_own = mean;
    d_first = -0.25 * passed * la / (ra * ra);
    d_second = -0.25 * passed * lc / (rc * rc);
    if (row != nullptr) FillRow(state, j, a, c, d_first, d_second, d_own, row);
    return {value, kRelativeTolerance * (ra + rc) + 1e-15};
  }
  switch (state.mode[j]) {
    case JunctionMode::kSlipIntoSecond:  // the second is the tighter: T~_second = r (T~_first)
      value = fc.extended - CapstanBound(r, fa.extended);
      d_first = -CapstanSlope(r, fa.extended) * fa.extended_slope;
      d_second = fc.extended_slope;
      break;
    case JunctionMode::kSlipIntoFirst:  // T~_first = r (T~_second)
      value = fa.extended - CapstanBound(r, fc.extended);
      d_first = fa.extended_slope;
      d_second = -CapstanSlope(r, fc.extended) * fc.extended_slope;
      break;
    case JunctionMode::kFree:
    case JunctionMode::kStick:  // (kStick: above)
      value = fa.extended - fc.extended;
      d_first = fa.extended_slope;
      d_second = -fc.extended_slope;
      break;
  }
  if (row != nullptr) FillRow(state, j, a, c, d_first, d_second, d_own, row);
  return {value, kRelativeTolerance * (std::abs(fa.extended) + std::abs(fc.extended)) +
                     kAbsoluteTolerance};
}

// max over the unknowns of |residual| / tolerance (<= 1: converged), with the residuals.
double ResidualNorm(const Model& model, BeltState& state, std::size_t unknowns, double* matrix) {
  SetRestLengths(state);
  double worst = 0.0;
  for (std::size_t j = 0; j < state.transfer.size(); ++j) {
    const std::int32_t unknown = state.solve_index[j];
    if (unknown < 0) continue;
    const auto i = Index(unknown);
    const Residual r = JunctionResidual(model, state, j, matrix ? matrix + i * unknowns : nullptr);
    state.solve_residual[i] = r.value;
    worst = std::max(worst, std::abs(r.value) / r.tolerance);
  }
  return worst;
}

// Solves m x = b in place (x into b) by Gaussian elimination with partial pivoting; a pivot that
// vanishes (a span in a flat stretch of its function) is replaced by a tiny one, so the step
// stays finite and the line search decides.
void SolveInPlace(std::vector<double>& m, std::vector<double>& b, std::size_t n) {
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t row = col + 1; row < n; ++row) {
      if (std::abs(m[row * n + col]) > std::abs(m[pivot * n + col])) pivot = row;
    }
    if (pivot != col) {
      for (std::size_t k = 0; k < n; ++k) std::swap(m[col * n + k], m[pivot * n + k]);
      std::swap(b[col], b[pivot]);
    }
    if (std::abs(m[col * n + col]) < 1e-300) m[col * n + col] = -1e-300;
    for (std::size_t row = col + 1; row < n; ++row) {
      const double factor = m[row * n + col] / m[col * n + col];
      if (factor == 0.0) continue;
      for (std::size_t k = col; k < n; ++k) m[row * n + k] -= factor * m[col * n + k];
      b[row] -= factor * b[col];
    }
  }
  for (std::size_t col = n; col-- > 0;) {
    double sum = b[col];
    for (std::size_t k = col + 1; k < n; ++k) sum -= m[col * n + k] * b[k];
    b[col] = sum / m[col * n + col];
  }
}

// Junction j's transfer alone, the others held, until its residual is within tolerance: its
// residual is strictly monotone in its own transfer (more webbing into the tighter side slackens
// it), so a bracket found by doubling steps and the Illinois method on it always converge.
void SolveOneJunction(const Model& model, BeltState& state, std::size_t j) {
  auto residual = [&](double u) {
    state.transfer[j] = u;
    SetRestLengths(state);
    return JunctionResidual(model, state, j, nullptr);
  };
  double low = state.transfer[j];
  Residual r_low = residual(low);
  if (std::abs(r_low.value) <= r_low.tolerance) return;
  // The residual rises with the transfer when it is the first span's tension that leads it.
  const bool rising = state.mode[j] != JunctionMode::kSlipIntoSecond;
  const double direction = (r_low.value > 0) == rising ? -1.0 : 1.0;
  const std::size_t a = Index(state.junction_first[j]), c = Index(state.junction_second[j]);
  double step = 1e-6 * (state.length[a] + state.length[c]);
  double high = low, g_high = r_low.value;
  for (int k = 0; k < 80 && (g_high > 0) == (r_low.value > 0); ++k, step *= 2) {
    low = high;
    r_low.value = g_high;
    high = low + direction * step;
    g_high = residual(high).value;
  }
  double g_low = r_low.value;
  int stale = 0;
  for (int k = 0; k < 200; ++k) {
    ++state.slip_iterations;
    const double u = (low * g_high - high * g_low) / (g_high - g_low);
    const Residual r = residual(u);
    if (std::abs(r.value) <= r.tolerance || std::abs(high - low) <= 1e-15 * step) return;
    if ((r.value > 0) == (g_low > 0)) {
      low = u;
      g_low = r.value;
      if (stale == 1) g_high *= 0.5;
      stale = 1;
    } else {
      high = u;
      g_high = r.value;
      if (stale == -1) g_low *= 0.5;
      stale = -1;
    }
  }
}

// d r(T~) / d r, the capstan bound's derivative in the ratio.
double CapstanRatioSlope(double ratio, double extended) {
  return extended >= 0.0 ? extended : -extended / (ratio * ratio);
}

// The rate of junction j's residual (JunctionResidual) with its transfers held: from the rates
// of its spans' lengths, of its capstan ratio and of the arc its body carried.
double ResidualRate(const Model& model, const BeltState& state, std::size_t j,
                    std::span<const double> length_rate, double ratio_rate, double carried_rate) {
  const std::size_t a = Index(state.junction_first[j]), c = Index(state.junction_second[j]);
  const double ra = std::max(state.rest_length[a], kShortest);
  const double rc = std::max(state.rest_length[c], kShortest);
  // A span's strain is its length over its rest length, less 1.
  const double strain_rate_a = length_rate[a] / ra, strain_rate_c = length_rate[c] / rc;
  if (state.mode[j] == JunctionMode::kStick) {
    const double passed = state.transfer[j] - state.held_transfer[j];
    return passed * 0.25 * (strain_rate_a + strain_rate_c) - carried_rate;
  }
  const SpanForce fa = SpanForceAt(model, state, a, state.rest_length[a]);
  const SpanForce fc = SpanForceAt(model, state, c, state.rest_length[c]);
  const double r = state.junction_ratio[j];
  const double rate_a = fa.extended_strain_slope * strain_rate_a;
  const double rate_c = fc.extended_strain_slope * strain_rate_c;
  switch (state.mode[j]) {
    case JunctionMode::kSlipIntoSecond:
      return rate_c - CapstanSlope(r, fa.extended) * rate_a -
             CapstanRatioSlope(r, fa.extended) * ratio_rate;
    case JunctionMode::kSlipIntoFirst:
      return rate_a - CapstanSlope(r, fc.extended) * rate_c -
             CapstanRatioSlope(r, fc.extended) * ratio_rate;
    case JunctionMode::kFree:
    case JunctionMode::kStick:
      break;
  }
  return rate_a - rate_c;
}

// Which junctions the solver solves for (the others hold their webbing): their unknowns'
// indices in solve_index; returns how many. With `carried_rate`, a sticking junction whose body
// starts to carry its webbing (no arc carried yet, as just after it stuck) is one too.
std::size_t NumberUnknowns(BeltState& state, std::span<const double> carried_rate = {}) {
  std::size_t unknowns = 0;
  for (std::size_t j = 0; j < state.transfer.size(); ++j) {
    // A sticking junction holds its webbing unless the body it lies on carries it.
    const bool carried =
        state.carried_arc[j] != 0.0 || (!carried_rate.empty() && carried_rate[j] != 0.0);
    const bool solved = state.mode[j] != JunctionMode::kStick || carried;
    state.solve_index[j] = solved ? static_cast<std::int32_t>(unknowns++) : -1;
  }
  return unknowns;
}

}  // namespace

void TransferRates(const Model& model, BeltState& state, std::span<const double> length_rate,
                   std::span<const double> ratio_rate, std::span<const double> carried_rate,
                   std::span<double> transfer_rate) {
  std::fill(transfer_rate.begin(), transfer_rate.end(), 0.0);
  const std::size_t unknowns = NumberUnknowns(state, carried_rate);
  if (unknowns == 0) return;
  // The Jacobian at the solution (ResidualNorm leaves the rest lengths as they are), and the
  // residuals' rates with the transfers held: J x' = -F'.
  ResidualNorm(model, state, unknowns, state.solve_matrix.data());
  for (std::size_t j = 0; j < state.transfer.size(); ++j) {
    const std::int32_t unknown = state.solve_index[j];
    if (unknown < 0) continue;
    state.solve_step[Index(unknown)] =
        -ResidualRate(model, state, j, length_rate, ratio_rate[j], carried_rate[j]);
  }
  SolveInPlace(state.solve_matrix, state.solve_step, unknowns);
  for (std::size_t j = 0; j < state.transfer.size(); ++j) {
    const std::int32_t unknown = state.solve_index[j];
    if (unknown >= 0) transfer_rate[j] = state.solve_step[Index(unknown)];
  }
}

SpanForce SpanForceAt(const Model& model, const BeltState& state, std::size_t span,
                      double rest_length) {
  const double rest = std::max(rest_length, kShortest);
  const double strain = state.length[span] / rest - 1.0;
  const double d_strain = -state.length[span] / (rest * rest);  // d strain / d rest length
  const auto belt = Index(state.span_belt[span]);
  const std::int32_t function = model.belts.function[belt];
  const LoadingHistory& history = state.history[span];
  // Where the tension reaches zero: at zero strain while loading, at the permanent strain on
  // the unloading curve.
  const double zero =
      state.hysteresis[span] && strain < history.max_deflection ? history.permanent : 0.0;
  SpanForce out;
  if (strain > zero) {
    const double tension = LoadingUnloadingForce(model.functions, function, strain, history);
    if (tension > 0) {
      out.tension = tension;
      out.extended_strain_slope = LoadingUnloadingSlope(model.functions, function, strain, history);
      out.tension_slope = out.extended_strain_slope * d_strain;
    }
    out.extended = out.tension;
    out.extended_slope = out.tension_slope;
  } else {
    const double stiffness = state.slack_stiffness[belt];
    out.extended = stiffness * (strain - zero);
    out.extended_strain_slope = stiffness;
    out.extended_slope = stiffness * d_strain;
  }
  return out;
}

double CapstanBound(double ratio, double extended) {
  return extended >= 0.0 ? ratio * extended : extended / ratio;
}

double CapstanSlope(double ratio, double extended) { return extended >= 0.0 ? ratio : 1.0 / ratio; }

double SpanTension(const Model& model, const BeltState& state, std::size_t span,
                   double rest_length) {
  return SpanForceAt(model, state, span, rest_length).tension;
}

void SizeSlipSolver(BeltState& state) {
  const std::size_t n = state.junction_first.size();
  state.solve_index.assign(n, -1);
  state.solve_residual.assign(n, 0.0);
  state.solve_step.assign(n, 0.0);
  state.solve_trial.assign(n, 0.0);
  state.solve_matrix.assign(n * n, 0.0);
}

void ResolveSlip(const Model& model, BeltState& state) {
  const std::size_t unknowns = NumberUnknowns(state);
  std::copy(state.held_transfer.begin(), state.held_transfer.end(), state.transfer.begin());
  if (unknowns > 0) {
    // Newton's method with a backtracking line search on the largest scaled residual.
    double norm = ResidualNorm(model, state, unknowns, state.solve_matrix.data());
    for (int iteration = 0; iteration < kMaxIterations && norm > 1.0; ++iteration) {
      ++state.slip_iterations;
      for (std::size_t i = 0; i < unknowns; ++i) state.solve_step[i] = -state.solve_residual[i];
      SolveInPlace(state.solve_matrix, state.solve_step, unknowns);
      for (std::size_t j = 0; j < state.transfer.size(); ++j) {
        if (state.solve_index[j] >= 0)
          state.solve_trial[Index(state.solve_index[j])] = state.transfer[j];
      }
      // Each trial fills the Jacobian too (the solve left the matrix factored, so nothing is
      // lost): the last one, where the line search stops, is the next step's.
      double scale = 1.0;
      double trial_norm = norm;
      for (int halving = 0; halving < kMaxHalvings; ++halving, scale *= 0.5) {
        for (std::size_t j = 0; j < state.transfer.size(); ++j) {
          const std::int32_t unknown = state.solve_index[j];
          if (unknown >= 0) {
            state.transfer[j] =
                state.solve_trial[Index(unknown)] + scale * state.solve_step[Index(unknown)];
          }
        }
        trial_norm = ResidualNorm(model, state, unknowns, state.solve_matrix.data());
        if (trial_norm < norm || trial_norm <= 1.0) break;
      }
      norm = trial_norm;
      if (scale < 1e-10) break;  // no further progress: rounding
    }
    // Where the equations' kinks (a span going slack) stall Newton's method: nonlinear
    // Gauss-Seidel on the junctions one by one, each solved exactly.
    for (int sweep = 0; sweep < 500 && norm > 1.0; ++sweep) {
      for (std::size_t j = 0; j < state.transfer.size(); ++j) {
        if (state.solve_index[j] >= 0) SolveOneJunction(model, state, j);
      }
      norm = ResidualNorm(model, state, unknowns, nullptr);
    }
  }
  SetRestLengths(state);
  for (std::size_t span = 0; span < state.tension.size(); ++span) {
    state.tension[span] = SpanTension(model, state, span, state.rest_length[span]);
  }
}

}  // namespace sled::runtime
