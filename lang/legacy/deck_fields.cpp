#include "lang/legacy/deck_fields.h"

#include <algorithm>

#include <fmt/format.h>

namespace sled::lang::legacy {

Vec3 DeckFields::Triple(const Card& card, int first, int width, std::string_view what) {
  Vec3 v{};
  for (int i = 0; i < 3; ++i) {
    v[static_cast<std::size_t>(i)] =
        r_.Real(card, first + i * width, first + (i + 1) * width - 1, what);
  }
  return v;
}

int DeckFields::Count(const Card& card, int first, int last, std::string_view what, int limit) {
  const int value = r_.Integer(card, first, last, what);
  if (value < 0 || value > limit) {
    r_.Report(DiagnosticKind::kDeckCountOutOfRange, card, first, last,
              fmt::format("card {}, {} ({}): {} is outside 0 to {}", card.label,
                          r_.Where(card, first, last), what, value, limit),
              "the ATB V.3 limits (MODULE_STANDARD) bound every count");
    return 0;
  }
  return value;
}

Ref DeckFields::Reference(const Card& card, int first, int last, std::string_view what) {
  return Ref{r_.Integer(card, first, last, what), r_.Range(card, first, last), card.label};
}

std::vector<int> DeckFields::CountsPerItem(const std::string& label, int items,
                                           std::string_view format, int per_card, bool one_read,
                                           std::string_view what, int limit) {
  std::vector<int> counts;
  for (int line = 0; line < (items + per_card - 1) / per_card; ++line) {
    const CardSpec spec{format, std::min(per_card, items - per_card * line), one_read && line > 0};
    const Card card = r_.Next(fmt::format("{} (line {})", label, line + 1), spec);
    for (int i = 0; i < per_card && line * per_card + i < items; ++i) {
      counts.push_back(Count(card, 4 * i + 1, 4 * i + 4, what, limit));
    }
  }
  counts.resize(static_cast<std::size_t>(std::max(items, 0)), 0);
  return counts;
}

// Negative NF(2), NF(3), NF(4) (spike, R and G all zero or negative): F2 = |NF(2)| of the
// deflection, F3 = |NF(3)| and F4 = |NF(4)| of its rate.
void DeckFields::ReadRateTerms(const Card& card, int first, int spike, UnloadingRefs* unloading) {
  unloading->rate_scaled_force = Ref{-spike, r_.Range(card, first + 4, first + 7), card.label};
  unloading->rate_scale = unloading->r_factor;
  unloading->rate_scale.number = -unloading->rate_scale.number;
  unloading->rate_force = unloading->g_factor;
  unloading->rate_force.number = -unloading->rate_force.number;
  unloading->r_factor.number = unloading->g_factor.number = 0;
  if ((unloading->rate_scaled_force.number == 0) != (unloading->rate_scale.number == 0)) {
    const bool scaled = unloading->rate_scaled_force.number != 0;
    const int at = scaled ? first + 4 : first + 8;
    Ignored(card, at, at + 3,
            fmt::format("{} without {}",
                        scaled ? "NF(2), F2 of the rate-dependent force"
                               : "NF(3), F3 of the rate-dependent force",
                        scaled ? "NF(3)" : "NF(2)"),
            "ATB multiplies F2(D) by F3(D'), 0 without either: the term is left out");
    unloading->rate_scaled_force.number = unloading->rate_scale.number = 0;
  }
}

void DeckFields::ReadFunctionNumbers(const Card& card, int first, Ref* force, Ref* friction,
                                     UnloadingRefs* unloading) {
  *force = Reference(card, first, first + 3, "the force-deflection function");
  const int spike = r_.Integer(card, first + 4, first + 7, "the inertial-spike function");
  // ATB's inertial spike: added to the loading force until its E.2 D3 (map_unloading.cpp).
  if (spike > 0) unloading->spike = Ref{spike, r_.Range(card, first + 4, first + 7), card.label};
  Ref* factors[] = {&unloading->r_factor, &unloading->g_factor};
  const char* names[] = {"the R-factor function", "the G-factor function"};
  for (int i = 0; i < 2; ++i) {
    const int at = first + 8 + 4 * i;
    *factors[i] = Reference(card, at, at + 3, names[i]);
  }
  const bool positive =
      spike > 0 || unloading->r_factor.number > 0 || unloading->g_factor.number > 0;
  if (spike < 0 || unloading->r_factor.number < 0 || unloading->g_factor.number < 0) {
    if (positive) {
      Invalid(card, first + 4, first + 15,
              "negative function numbers (ATB's rate-dependent force) beside a spike, R or G "
              "function",
              "ATB's rate-dependent force (FUNC_RATE_DEP) takes NF(2) to NF(4) all negative or "
              "zero; it cannot be used with an inertial spike or R and G factors");
      unloading->r_factor.number = unloading->g_factor.number = unloading->spike.number = 0;
    } else {
      ReadRateTerms(card, first, spike, unloading);
    }
  }
  *friction = Reference(card, first + 16, first + 19, "the friction function");
}

std::optional<DeckFrame> DeckFields::FrameOf(const Card& card, int first, int last, int number,
                                             int bags, std::string_view what) {
  const int segments = static_cast<int>(deck_.segments.size());
  const int vehicles = static_cast<int>(deck_.vehicles.size());
  if (number >= 1 && number <= segments) return DeckFrame{DeckFrame::Kind::kSegment, number};
  if (number > segments && number <= segments + vehicles) {
    return DeckFrame{DeckFrame::Kind::kVehicle, number - segments - 1};
  }
  if (number == segments + vehicles + bags + 1) return DeckFrame{DeckFrame::Kind::kGround, 0};
  if (number > segments + vehicles && number <= segments + vehicles + bags) {
    Refuse(card, first, last, fmt::format("{} is {}: an airbag", what, number),
           "sled's airbags are not frames; name a body segment, a vehicle or the ground");
    return std::nullopt;
  }
  r_.Report(DiagnosticKind::kDeckCountOutOfRange, card, first, last,
            fmt::format("card {}, {} ({}): segment {} does not exist", card.label,
                        r_.Where(card, first, last), what, number),
            fmt::format("body segments are 1 to {}, vehicles {} to {}, the ground {}", segments,
                        segments + 1, segments + vehicles, segments + vehicles + bags + 1));
  return std::nullopt;
}

void DeckFields::CheckSemiAxes(const Card& card, int first, const Vec3& semi_axes,
                               bool may_be_absent) {
  if (may_be_absent && semi_axes == Vec3{}) return;
  if (semi_axes[0] > 0 && semi_axes[1] > 0 && semi_axes[2] > 0) return;
  Invalid(card, first, first + 17,
          fmt::format("the semi-axes ({}, {}, {}) are not all positive", semi_axes[0], semi_axes[1],
                      semi_axes[2]),
          may_be_absent ? "an ellipsoid's three semi-axes are positive; all three blank give "
                          "the segment no contact ellipsoid"
                        : "an ellipsoid's three semi-axes are positive");
}

void DeckFields::ReportField(DiagnosticKind kind, const Card& card, int first, int last,
                             std::string_view what, std::string help) {
  r_.Report(kind, card, first, last,
            fmt::format("card {}, {}: {}", card.label, r_.Where(card, first, last), what),
            std::move(help));
}

void DeckFields::Refuse(const Card& card, int first, int last, std::string_view what,
                        std::string help) {
  ReportField(DiagnosticKind::kDeckNotExpressible, card, first, last, what, std::move(help));
}

void DeckFields::RefuseNonZero(const Card& card, int first, int last, double value,
                               std::string_view what, std::string help) {
  if (value != 0) {
    Refuse(card, first, last, fmt::format("{} is {}; sled has no such attribute", what, value),
           std::move(help));
  }
}

void DeckFields::Unverified(const Card& card, int first, int last, std::string_view what) {
  ReportField(DiagnosticKind::kDeckUnverifiedField, card, first, last, what,
              "the format reference marks this unverified: compare the converted scenario with "
              "the deck's documentation before trusting it");
}

void DeckFields::Ignored(const Card& card, int first, int last, std::string_view what,
                         std::string help) {
  ReportField(DiagnosticKind::kDeckIgnoredField, card, first, last, what, std::move(help));
}

void DeckFields::Invalid(const Card& card, int first, int last, std::string_view what,
                         std::string help) {
  ReportField(DiagnosticKind::kDeckInvalidValue, card, first, last, what, std::move(help));
}

void DeckFields::Approximated(const Card& card, int first, int last, std::string_view what) {
  ReportField(DiagnosticKind::kDeckApproximated, card, first, last, what,
              "sled's model differs here from ATB's: compare the converted scenario's results "
              "with the deck's before trusting them");
}

}  // namespace sled::lang::legacy
