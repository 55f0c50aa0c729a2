#include "compiler/sweep/design_text.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace sled::compiler {
namespace {

bool IsNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

constexpr std::string_view kVaryHelp =
    "write `NAME=A..B UNIT step S`, `NAME=A..B UNIT count N`, `NAME=A..B UNIT` (sampled with "
    "--sample) or a list `NAME=A,B,C UNIT`";

}  // namespace

void ReportDesign(lang::DiagnosticConsumer& diagnostics, lang::DiagnosticKind kind,
                  lang::SourceRange range, std::string message, std::string label,
                  std::string help) {
  auto diagnostic = lang::MakeDiagnostic(kind, range, std::move(message), std::move(label));
  diagnostic.help = std::move(help);
  diagnostics.Consume(std::move(diagnostic));
}

DesignScanner::DesignScanner(const lang::SourceManager& sources, lang::FileId file,
                             std::uint32_t begin, std::uint32_t end)
    : text_(sources.buffer(file).text()), file_(file), at_(begin), end_(end) {}

char DesignScanner::Peek(std::uint32_t ahead) const {
  return at_ + ahead < end_ ? text_[at_ + ahead] : '\0';
}

void DesignScanner::SkipSpaces() {
  while (!AtEnd() && (text_[at_] == ' ' || text_[at_] == '\t')) ++at_;
}

bool DesignScanner::Consume(std::string_view text) {
  if (text_.substr(at_, std::min<std::size_t>(text.size(), end_ - at_)) != text) return false;
  at_ += static_cast<std::uint32_t>(text.size());
  return true;
}

bool DesignScanner::ConsumeWord(std::string_view word) {
  if (at_ + word.size() > end_ || text_.substr(at_, word.size()) != word) return false;
  if (at_ + word.size() < end_ && IsNameChar(text_[at_ + word.size()])) return false;
  at_ += static_cast<std::uint32_t>(word.size());
  return true;
}

std::optional<std::string> DesignScanner::Name() {
  if (AtEnd() || !IsNameStart(Peek())) return std::nullopt;
  const std::uint32_t from = at_;
  while (!AtEnd() && IsNameChar(Peek())) ++at_;
  return std::string(text_.substr(from, at_ - from));
}

std::optional<double> DesignScanner::Number() {
  const std::uint32_t from = at_;
  std::uint32_t at = at_;
  auto digits = [&] {
    const std::uint32_t start = at;
    while (at < end_ && IsDigit(text_[at])) ++at;
    return at > start;
  };
  if (at < end_ && (text_[at] == '-' || text_[at] == '+')) ++at;
  bool any = digits();
  // A decimal point, but not the first dot of `..`.
  if (at < end_ && text_[at] == '.' && !(at + 1 < end_ && text_[at + 1] == '.')) {
    ++at;
    any |= digits();
  }
  if (!any) return std::nullopt;
  // An exponent only when digits follow: `5 e` is no number with an exponent.
  if (at < end_ && (text_[at] == 'e' || text_[at] == 'E')) {
    std::uint32_t exponent = at + 1;
    if (exponent < end_ && (text_[exponent] == '-' || text_[exponent] == '+')) ++exponent;
    if (exponent < end_ && IsDigit(text_[exponent])) {
      at = exponent;
      digits();
    }
  }
  const char* first = text_.data() + from + (text_[from] == '+' ? 1 : 0);
  double value = 0.0;
  const auto [end, status] = std::from_chars(first, text_.data() + at, value);
  if (status != std::errc() || end != text_.data() + at || !std::isfinite(value)) {
    return std::nullopt;
  }
  at_ = at;
  return value;
}

std::optional<lang::ast::Unit> DesignScanner::Unit() {
  lang::ast::Unit unit;
  const std::uint32_t from = at_;
  int sign = 1;
  while (true) {
    const std::uint32_t factor_start = at_;
    auto symbol = Name();
    if (!symbol) {
      at_ = from;
      return std::nullopt;
    }
    lang::ast::UnitFactor factor;
    factor.symbol = *symbol;
    if (Peek() == '^') {
      std::uint32_t at = at_ + 1;
      const bool negative = at < end_ && text_[at] == '-';
      if (negative) ++at;
      const std::uint32_t digits = at;
      while (at < end_ && IsDigit(text_[at])) ++at;
      if (at > digits) {
        int exponent = 0;
        std::from_chars(text_.data() + digits, text_.data() + at, exponent);
        factor.exponent = negative ? -exponent : exponent;
        at_ = at;
      }
    }
    factor.exponent *= sign;
    factor.range = Range(factor_start);
    unit.factors.push_back(std::move(factor));
    if (Peek() == '*' && IsNameStart(Peek(1))) {
      sign = 1;
    } else if (Peek() == '/' && IsNameStart(Peek(1))) {
      sign = -1;
    } else {
      break;
    }
    ++at_;
  }
  unit.range = Range(from);
  return unit;
}

std::optional<WrittenQuantity> DesignScanner::Quantity() {
  const std::uint32_t from = at_;
  auto number = Number();
  if (!number) return std::nullopt;
  WrittenQuantity quantity;
  quantity.number = *number;
  const std::uint32_t after_number = at_;
  SkipSpaces();
  // `step` and `count` are keywords, never units.
  const std::uint32_t before_unit = at_;
  if (!ConsumeWord("step") && !ConsumeWord("count")) {
    quantity.unit = Unit();
  } else {
    at_ = before_unit;
  }
  if (!quantity.unit) at_ = after_number;
  quantity.range = Range(from);
  return quantity;
}

lang::SourceRange DesignScanner::Here() const { return {file_, at_, AtEnd() ? at_ : at_ + 1}; }

std::string DesignScanner::Found() const {
  if (AtEnd()) return "the end";
  std::uint32_t to = at_ + 1;
  while (to < end_ && IsNameChar(text_[to]) && IsNameChar(text_[at_])) ++to;
  return fmt::format("`{}`", text_.substr(at_, to - at_));
}

std::optional<VarySpec> ParseVary(const lang::SourceManager& sources, lang::FileId file,
                                  lang::DiagnosticConsumer& diagnostics) {
  const std::string_view text = sources.buffer(file).text();
  DesignScanner scan(sources, file, 0, static_cast<std::uint32_t>(text.size()));
  VarySpec spec;
  auto fail = [&](std::string message, std::string label) {
    ReportDesign(diagnostics, lang::DiagnosticKind::kMalformedDesign, scan.Here(),
                 std::move(message), std::move(label), std::string(kVaryHelp));
    return std::nullopt;
  };
  scan.SkipSpaces();
  const std::uint32_t name_start = scan.at();
  auto name = scan.Name();
  if (!name) return fail(fmt::format("expected a parameter name, found {}", scan.Found()), "");
  spec.name = *name;
  spec.name_range = scan.Range(name_start);
  scan.SkipSpaces();
  if (!scan.Consume("=")) {
    return fail(fmt::format("expected `=` after `{}`, found {}", spec.name, scan.Found()),
                "expected `=`");
  }
  scan.SkipSpaces();
  const std::uint32_t values_start = scan.at();
  auto first = scan.Quantity();
  if (!first) return fail(fmt::format("expected a number, found {}", scan.Found()), "");
  spec.values.push_back(std::move(*first));
  scan.SkipSpaces();
  if (scan.Consume("..")) {
    scan.SkipSpaces();
    auto last = scan.Quantity();
    if (!last) {
      return fail(fmt::format("expected the number that ends the range, found {}", scan.Found()),
                  "");
    }
    spec.values.push_back(std::move(*last));
    spec.kind = VarySpec::Kind::kInterval;
    scan.SkipSpaces();
    if (scan.ConsumeWord("step")) {
      scan.SkipSpaces();
      spec.step = scan.Quantity();
      if (!spec.step) return fail(fmt::format("expected a step, found {}", scan.Found()), "");
      spec.kind = VarySpec::Kind::kStep;
    } else if (scan.ConsumeWord("count")) {
      scan.SkipSpaces();
      const std::uint32_t count_start = scan.at();
      auto count = scan.Number();
      if (!count || *count != std::floor(*count) || std::abs(*count) > 1e15) {
        const lang::SourceRange where = count ? scan.Range(count_start) : scan.Here();
        ReportDesign(diagnostics, lang::DiagnosticKind::kMalformedDesign, where,
                     fmt::format("expected a whole number of values after `count`, "
                                 "found {}",
                                 count ? fmt::format("`{}`", sources.Text(where)) : scan.Found()),
                     "", std::string(kVaryHelp));
        return std::nullopt;
      }
      spec.count = static_cast<long long>(*count);
      spec.count_range = scan.Range(count_start);
      spec.kind = VarySpec::Kind::kCount;
    }
  } else {
    while (scan.Consume(",")) {
      scan.SkipSpaces();
      auto next = scan.Quantity();
      if (!next)
        return fail(fmt::format("expected a number after `,`, found {}", scan.Found()), "");
      spec.values.push_back(std::move(*next));
      scan.SkipSpaces();
    }
  }
  spec.values_range = {file, values_start, scan.at()};
  scan.SkipSpaces();
  if (!scan.AtEnd()) {
    return fail(fmt::format("expected {}, found {}",
                            spec.kind == VarySpec::Kind::kInterval ? "`step`, `count` or the end"
                            : spec.kind == VarySpec::Kind::kList   ? "`,`, `..` or the end"
                                                                   : "the end",
                            scan.Found()),
                "");
  }
  return spec;
}

}  // namespace sled::compiler
