#include "compiler/sweep/design_csv.h"

#include <fmt/format.h>

#include "compiler/sweep/design_text.h"
#include "compiler/sweep/design_units.h"

namespace sled::compiler {
namespace {

constexpr std::string_view kCsvHelp =
    "a design file has a header of parameter names, each with an optional unit in brackets "
    "(`speed [km/h],belt_slack [mm]`), then one row of numbers per run";

// The fields of one line: byte ranges with surrounding spaces and double quotes removed.
std::vector<lang::SourceRange> Fields(std::string_view text, lang::FileId file, std::uint32_t begin,
                                      std::uint32_t end) {
  std::vector<lang::SourceRange> fields;
  std::uint32_t at = begin;
  while (true) {
    std::uint32_t field_end = at;
    bool quoted = false;
    while (field_end < end && (quoted || text[field_end] != ',')) {
      if (text[field_end] == '"') quoted = !quoted;
      ++field_end;
    }
    std::uint32_t b = at;
    std::uint32_t e = field_end;
    while (b < e && (text[b] == ' ' || text[b] == '\t')) ++b;
    while (e > b && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
    if (e - b >= 2 && text[b] == '"' && text[e - 1] == '"') {
      ++b;
      --e;
    }
    fields.push_back({file, b, e});
    if (field_end >= end) break;
    at = field_end + 1;
  }
  return fields;
}

struct Column {
  const ScenarioParameter* parameter = nullptr;
  std::optional<lang::ast::Unit> unit;  // from the header
  lang::SourceRange header;
};

}  // namespace

std::optional<CsvDesign> ReadCsvDesign(const lang::SourceManager& sources, lang::FileId file,
                                       const CheckedScenario& scene,
                                       lang::DiagnosticConsumer& diagnostics) {
  lang::ErrorTrackingConsumer tracked(diagnostics);
  const std::string_view text = sources.buffer(file).text();
  std::vector<Column> columns;
  std::vector<std::vector<WrittenQuantity>> rows;
  bool header_read = false;
  std::uint32_t line_start = 0;
  while (line_start < text.size()) {
    std::uint32_t line_end = line_start;
    while (line_end < text.size() && text[line_end] != '\n') ++line_end;
    const std::uint32_t next = line_end + 1;
    if (line_end > line_start && text[line_end - 1] == '\r') --line_end;
    std::uint32_t first = line_start;
    while (first < line_end && (text[first] == ' ' || text[first] == '\t')) ++first;
    if (first == line_end || text[first] == '#') {
      line_start = next;
      continue;
    }
    const std::vector<lang::SourceRange> fields = Fields(text, file, line_start, line_end);
    if (!header_read) {
      header_read = true;
      for (const lang::SourceRange& field : fields) {
        DesignScanner scan(sources, file, field.begin, field.end);
        Column column;
        column.header = field;
        const std::uint32_t name_start = scan.at();
        auto name = scan.Name();
        scan.SkipSpaces();
        if (name && scan.Consume("[")) {
          scan.SkipSpaces();
          column.unit = scan.Unit();
          scan.SkipSpaces();
          if (!column.unit || !scan.Consume("]")) name.reset();
          scan.SkipSpaces();
        }
        if (!name || !scan.AtEnd()) {
          ReportDesign(tracked, lang::DiagnosticKind::kMalformedDesign,
                       field.size() == 0 ? scan.Here() : field,
                       fmt::format("expected a parameter name with an optional unit in "
                                   "brackets, found `{}`",
                                   sources.Text(field)),
                       "not a column header", std::string(kCsvHelp));
          continue;
        }
        const lang::SourceRange name_range{file, name_start,
                                           name_start + static_cast<std::uint32_t>(name->size())};
        column.parameter = FindDesignParameter(scene, *name, name_range, tracked);
        if (column.parameter && !IsScalarParameter(*column.parameter, name_range, tracked)) {
          column.parameter = nullptr;
        }
        column.header = name_range;
        columns.push_back(std::move(column));
      }
      line_start = next;
      continue;
    }
    if (fields.size() != columns.size()) {
      ReportDesign(tracked, lang::DiagnosticKind::kMalformedDesign, {file, line_start, line_end},
                   fmt::format("this row has {} value{}, but the header names {} "
                               "parameter{}",
                               fields.size(), fields.size() == 1 ? "" : "s", columns.size(),
                               columns.size() == 1 ? "" : "s"),
                   "wrong number of values", "give one value per column, in order");
      line_start = next;
      continue;
    }
    std::vector<WrittenQuantity> row;
    for (const lang::SourceRange& field : fields) {
      DesignScanner scan(sources, file, field.begin, field.end);
      auto quantity = scan.Quantity();
      scan.SkipSpaces();
      if (!quantity || !scan.AtEnd()) {
        ReportDesign(
            tracked, lang::DiagnosticKind::kMalformedDesign,
            field.size() == 0 ? lang::SourceRange{file, field.begin, field.begin + 1} : field,
            field.size() == 0 ? std::string("an empty value")
                              : fmt::format("expected a number with an optional unit, found `{}`",
                                            sources.Text(field)),
            "not a value", std::string(kCsvHelp));
        continue;
      }
      row.push_back(std::move(*quantity));
    }
    if (row.size() == fields.size()) rows.push_back(std::move(row));
    line_start = next;
  }
  if (tracked.seen_error()) return std::nullopt;
  if (rows.empty()) {
    ReportDesign(
        tracked, lang::DiagnosticKind::kInvalidDesign,
        {file, 0, static_cast<std::uint32_t>(std::min<std::size_t>(text.size(), 1))},
        header_read ? "the design file has a header but no rows" : "the design file is empty",
        "no runs", std::string(kCsvHelp));
    return std::nullopt;
  }
  if (rows.size() > kMaxDesignPoints) {
    ReportDesign(tracked, lang::DiagnosticKind::kInvalidDesign, {file, 0, 1},
                 fmt::format("the design file has {} rows, more than a sweep's {}", rows.size(),
                             kMaxDesignPoints),
                 "too many runs", "split the design into several files");
    return std::nullopt;
  }

  CsvDesign design;
  design.points.assign(rows.size(), std::vector<double>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const Column& column = columns[c];
    if (column.parameter == nullptr) continue;
    std::optional<lang::ast::Unit> unit = column.unit;
    for (std::size_t r = 0; r < rows.size() && !unit; ++r) unit = rows[r][c].unit;
    auto variable = VariableInUnit(sources, *column.parameter, unit, column.header, tracked);
    if (!variable) continue;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      auto value = ValueInUnit(sources, rows[r][c], *variable, *column.parameter, tracked);
      if (value) design.points[r][c] = *value;
    }
    design.variables.push_back(std::move(*variable));
    design.headers.push_back(column.header);
  }
  if (tracked.seen_error()) return std::nullopt;
  return design;
}

}  // namespace sled::compiler
