#include "compiler/driver/sweep_point_check.h"

#include <charconv>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "compiler/driver/process_pool.h"
#include "lang/diagnostics/load_file.h"
#include "lang/diagnostics/render.h"

namespace sled::driver {
namespace {

// The points of one share, i = share, share + shares, ...; what a worker sends back:
// "FAILING FIRST\n" and the first failing point's rendered diagnostics.
std::string CheckShare(const std::string& scene, const compiler::CheckOptions& base,
                       const compiler::Design& design, std::size_t share, std::size_t shares,
                       bool compact, bool color) {
  std::size_t failing = 0;
  std::size_t first = 0;
  std::string rendered;
  for (std::size_t run = share; run < design.points.size(); run += shares) {
    lang::SourceManager sources;
    lang::DiagnosticCollector collector;
    const auto file = lang::LoadFileOrReport(sources, scene, collector);
    compiler::CheckOptions options = base;
    options.diagnostics = &collector;
    options.lints = false;
    const auto values = design.Overrides(run);
    options.overrides.insert(options.overrides.end(), values.begin(), values.end());
    if (file) compiler::ParseAndCheck(sources, *file, options);
    if (!collector.has_errors()) continue;
    if (failing++ == 0) {
      first = run;
      collector.SortByPosition();
      rendered = lang::RenderAll(
          sources, collector.diagnostics(),
          compact ? lang::DiagnosticStyle::kCompact : lang::DiagnosticStyle::kRich, {color});
    }
  }
  return fmt::format("{} {}\n", failing, first) + rendered;
}

// Adds one share's answer to `result`; false when it cannot be read.
bool Merge(const std::string& answer, PointCheckResult* result) {
  const std::size_t space = answer.find(' ');
  const std::size_t newline = answer.find('\n');
  if (space == std::string::npos || newline == std::string::npos || newline < space) return false;
  std::size_t failing = 0;
  std::size_t first = 0;
  const char* text = answer.data();
  if (std::from_chars(text, text + space, failing).ec != std::errc() ||
      std::from_chars(text + space + 1, text + newline, first).ec != std::errc()) {
    return false;
  }
  if (failing > 0 && (result->failing == 0 || first < result->first)) {
    result->first = first;
    result->diagnostics = answer.substr(newline + 1);
  }
  result->failing += failing;
  return true;
}

}  // namespace

PointCheckResult CheckDesignPoints(const std::string& scene, const compiler::CheckOptions& base,
                                   const compiler::Design& design, int workers, bool compact,
                                   bool color) {
  PointCheckResult result;
  const std::size_t shares =
      std::max<std::size_t>(1, std::min<std::size_t>(design.points.size(), workers));
  auto share = [&](std::size_t k) {
    return CheckShare(scene, base, design, k, shares, compact, color);
  };
  if (shares == 1) {
    Merge(share(0), &result);
    return result;
  }
  std::vector<std::optional<std::string>> answers;
  result.interrupted = !RunInWorkers(shares, static_cast<int>(shares), share, &answers);
  for (const auto& answer : answers) {
    if (!answer || !Merge(*answer, &result)) result.incomplete = true;
  }
  return result;
}

}  // namespace sled::driver
