// ATB's R and G factors (F.x.b NF(3), NF(4); F.8.c columns 9-16) as the unloading attributes of
// the force function. What ATB does with them was read from DEF_NEW_QUADRATIC, the routine that
// sets up a contact's unloading when its deflection turns at the largest so far, x_max:
//
//   R = R(x_max), G = G(x_max) (functions of the largest deflection; R = 1 and G = 0 without);
//   R = 1: unload along the loading function (G is not used);
//   else: the permanent deflection x_g = D0 + G (x_max - D0), the loading energy
//   E = integral of f from D0 to x_max, and the quadratic A1 u + A2 u^2 (u = x - x_g) through
//   (x_max, f(x_max)) whose area is R E, with A1 >= 0 (else A1 = 0) and A2 >= 0 (else the
//   straight line A1 = f / (x_max - x_g)).
//
// sled's `energy_loss` L and `permanent_set` p unload along f(x_max) ((x - p x_max) /
// (x_max - p x_max))^n with the exponent n that gives back (1 - L) E: for a constant R < 1 and
// G > 0 (with D0 = 0, which the E.2 reader requires) L = 1 - R and p = G give the same end
// points, the same zero of force and the same energy where ATB's quadratic is not clamped; the
// curves differ in between, by what the W0504 warning measures at the function's last
// deflection. Reloading differs too: ATB climbs a cubic from the unloading curve to the loading
// function at x_max (DEF_NEW_CUBIC), sled climbs back the unloading curve.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lang/legacy/deck_mapper.h"

namespace sled::lang::legacy::mapping {
namespace {

const char* FormName(FunctionCard::Form form) {
  switch (form) {
    case FunctionCard::Form::kConstant:
      return "a constant";
    case FunctionCard::Form::kPolynomial:
      return "a polynomial";
    case FunctionCard::Form::kTable:
      return "a table";
  }
  return "";
}

double Evaluate(const FunctionCard& f, double x) {
  switch (f.form) {
    case FunctionCard::Form::kConstant:
      return f.constant;
    case FunctionCard::Form::kPolynomial: {
      double value = 0;
      for (std::size_t k = f.coefficients.size(); k-- > 0;) value = value * x + f.coefficients[k];
      return value;
    }
    case FunctionCard::Form::kTable: {
      const auto& p = f.points;
      if (p.empty()) return 0;
      if (x <= p.front().first) return p.front().second;
      for (std::size_t k = 1; k < p.size(); ++k) {
        if (x <= p[k].first) {
          const double t = (x - p[k - 1].first) / (p[k].first - p[k - 1].first);
          return p[k - 1].second + t * (p[k].second - p[k - 1].second);
        }
      }
      return p.back().second;
    }
  }
  return 0;
}

// The deflection at which the warning compares the two unloading curves: the table's last
// argument, the end of a polynomial's first part (E.2 |D1|), 1 for a constant (its curves do
// not depend on x_max).
double LargestDeflection(const FunctionCard& f) {
  if (f.form == FunctionCard::Form::kTable && !f.points.empty()) return f.points.back().first;
  if (f.form == FunctionCard::Form::kPolynomial && f.first_part_end > 0) return f.first_part_end;
  return 1.0;
}

// Unloading from x_max with R and G by ATB's quadratic and by sled's power law: the largest
// difference of the two forces as a share of f(x_max), and the share of the loading energy
// each gives back. Empty when f(x_max) or the energy is not positive.
struct CurveComparison {
  double largest_difference = 0, atb_returned = 0, sled_returned = 0;
};
std::optional<CurveComparison> CompareUnloading(const FunctionCard& f, double x_max, double r,
                                                double g) {
  constexpr int kSteps = 400;
  double energy = 0;  // the trapezoid rule, exact for a table, fine for a smooth polynomial
  for (int k = 0; k < kSteps; ++k) {
    const double a = x_max * k / kSteps, b = x_max * (k + 1) / kSteps;
    energy += 0.5 * (Evaluate(f, a) + Evaluate(f, b)) * (b - a);
  }
  const double force = Evaluate(f, x_max);
  if (!(force > 0) || !(energy > 0)) return std::nullopt;
  const double dx = (1 - g) * x_max;
  double a1 = 2 / dx * (3 * r * energy / dx - force);
  a1 = std::max(a1, 0.0);
  double a2 = (force / dx - a1) / dx;
  if (a2 < 0) {
    a1 = force / dx;
    a2 = 0;
  }
  const double exponent = std::clamp(force * dx / (r * energy) - 1, 1e-3, 1e3);
  CurveComparison c;
  for (int k = 0; k <= kSteps; ++k) {
    const double u = dx * k / kSteps;
    const double atb = u * (a1 + u * a2);
    const double sled = force * std::pow(u / dx, exponent);
    c.largest_difference = std::max(c.largest_difference, std::fabs(atb - sled) / force);
  }
  c.atb_returned = (a1 * dx * dx / 2 + a2 * dx * dx * dx / 3) / energy;
  c.sled_returned = force * dx / (exponent + 1) / energy;
  return c;
}

}  // namespace

std::optional<double> DeckMapper::Factor(const Ref& ref, std::string_view what, double none) {
  if (ref.number == 0) return none;
  const FunctionCard* function = Function(ref);
  if (function == nullptr) return std::nullopt;
  used_.insert(function->number);
  if (function->form != FunctionCard::Form::kConstant) {
    Report(DiagnosticKind::kDeckNotExpressible, ref,
           fmt::format("card {}: {} function {} is {}, a factor that changes with the largest "
                       "deflection",
                       ref.card, what, ref.number, FormName(function->form)),
           fmt::format("ATB evaluates it at the largest deflection each time the contact starts "
                       "to unload (DEF_NEW_QUADRATIC); sled's `energy_loss` and `permanent_set` "
                       "are numbers: give a constant function (E.2 D1 = 0, D2 = the {})",
                       what));
    return std::nullopt;
  }
  return function->constant;
}

std::optional<DeckMapper::FunctionUnloading> DeckMapper::Unloading(const FunctionCard& function,
                                                                   const UnloadingRefs& refs) {
  const auto r = Factor(refs.r_factor, "R-factor", 1.0);
  const auto g = Factor(refs.g_factor, "G-factor", 0.0);
  if (!r || !g) return std::nullopt;
  if (*r < 0 || *r > 1) {
    Report(DiagnosticKind::kDeckInvalidValue, refs.r_factor,
           fmt::format("card {}: the R factor (function {}) is {}", refs.r_factor.card,
                       refs.r_factor.number, *r),
           "R is the share of the loading energy the unloading curve gives back: 0 to 1");
    return std::nullopt;
  }
  if (*g < 0 || *g >= 1) {
    Report(DiagnosticKind::kDeckInvalidValue, refs.g_factor,
           fmt::format("card {}: the G factor (function {}) is {}", refs.g_factor.card,
                       refs.g_factor.number, *g),
           "G is the permanent deflection as a share of the largest: from 0 up to, not "
           "including, 1 (ATB divides by 1 - G)");
    return std::nullopt;
  }
  if (*r == 1) {
    if (*g != 0) {
      Report(DiagnosticKind::kDeckIgnoredField, refs.g_factor,
             fmt::format("card {}: the G factor {} (function {}) is not used, as ATB does not use "
                         "it when R is 1: the contact unloads along its loading function",
                         refs.g_factor.card, *g, refs.g_factor.number),
             "give an R factor below 1 for a contact that loses energy");
    }
    return FunctionUnloading{};
  }
  if (*g == 0) {
    Report(DiagnosticKind::kDeckNotExpressible, refs.r_factor,
           fmt::format("card {}: an R factor of {} with no G factor", refs.r_factor.card, *r),
           "with G = 0 ATB unloads along a quadratic to zero force at zero deflection that gives "
           "back R of the loading energy; sled's `energy_loss` without a `permanent_set` unloads "
           "along a straight line that ends at a permanent deflection: give a G factor above 0, "
           "or convert the contact by hand");
    return std::nullopt;
  }
  // 1 - R rounded to 12 decimals, so that R = 0.8 gives 0.2 and not 0.19999999999999996.
  const FunctionUnloading unloading{std::round((1 - *r) * 1e12) / 1e12, *g};
  const double x_max = LargestDeflection(function);
  if (const auto c = CompareUnloading(function, x_max, *r, *g)) {
    const char* where = function.form == FunctionCard::Form::kTable ? "last argument"
                        : function.form == FunctionCard::Form::kPolynomial
                            ? "E.2 |D1|"
                            : "a constant's curves do not depend on it";
    Report(DiagnosticKind::kDeckApproximated, refs.r_factor,
           fmt::format("card {}: R = {} and G = {} become `energy_loss = {}` and `permanent_set "
                       "= {}`; both curves unload from f(x_max) to zero force at G x_max, but "
                       "ATB's is a quadratic and sled's a power law: unloading from x_max = {} "
                       "(function {}: {}) they differ by up to {:.1f} % of f(x_max), ATB's "
                       "gives back {:.1f} % of the loading energy and sled's {:.1f} %; reloading "
                       "climbs ATB's cubic to the loading function at x_max, sled's unloading "
                       "curve",
                       refs.r_factor.card, *r, *g, unloading.energy_loss, unloading.permanent_set,
                       x_max, function.number, where, 100 * c->largest_difference,
                       100 * c->atb_returned, 100 * c->sled_returned),
           "sled's model differs here from ATB's: compare the converted scenario's results with "
           "the deck's before trusting them");
  }
  return unloading;
}

}  // namespace sled::lang::legacy::mapping
