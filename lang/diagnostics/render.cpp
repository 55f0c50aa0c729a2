#include "lang/diagnostics/render.h"

#include <algorithm>

#include <fmt/format.h>

#include "lang/source/utf8.h"

namespace sled::lang {
namespace {

struct Place {
  std::string path;
  LineColumn start;
  LineColumn end;
};

std::optional<Place> PlaceOf(const SourceManager& sources, const Diagnostic& diagnostic) {
  const SourceRange* range = diagnostic.primary_range();
  if (!range || !range->valid()) return std::nullopt;
  const SourceBuffer& buffer = sources.buffer(range->file);
  return Place{buffer.path(), buffer.Locate(range->begin),
               buffer.Locate(std::max(range->begin, range->end))};
}

std::string Location(const Place& place, bool show_column_range) {
  if (show_column_range && place.end.line == place.start.line &&
      place.end.column > place.start.column + 1) {
    return fmt::format("{}:{}:{}-{}", place.path, place.start.line, place.start.column,
                       place.end.column - 1);
  }
  return fmt::format("{}:{}:{}", place.path, place.start.line, place.start.column);
}

// A source line wider than this is shown as a window of it around the label, so that a
// diagnostic in a generated or mangled file with very long lines stays readable.
constexpr std::uint32_t kWidestShownLine = 120;
constexpr std::uint32_t kShownBeforeLabel = 40;

// What is shown of a source line, and how far right of its column the label's marks start.
struct ShownLine {
  std::string text;
  std::uint32_t marks_at = 0;  // characters before the first mark
  std::uint32_t room = 0;      // characters shown from the first mark on
};

// The line, tabs shown as spaces, with a label starting `at` bytes into it. A line wider than
// kWidestShownLine is cut to a window around the label, found by walking from the label, so
// that a line of megabytes costs no more than a short one.
ShownLine ShowLine(std::string_view line, std::size_t at) {
  at = std::min(at, line.size());
  std::size_t from = 0;
  std::size_t to = line.size();
  // A character is at most four bytes, so only a line of few bytes needs counting.
  const bool wide =
      line.size() > kWidestShownLine &&
      (line.size() > std::size_t{4} * kWidestShownLine || CountCharacters(line) > kWidestShownLine);
  if (wide) {
    from = at;
    for (std::uint32_t back = 0; from > 0 && back < kShownBeforeLabel;) {
      if (StartsCharacter(line[--from])) ++back;
    }
    to = from;
    for (std::uint32_t shown = 0; to < line.size() && shown < kWidestShownLine; ++shown) {
      to = NextCharacterStart(line, to);
    }
    to = std::max(to, at);
  }
  ShownLine shown;
  shown.text = std::string(from > 0 ? "..." : "") + std::string(line.substr(from, to - from)) +
               (to < line.size() ? "..." : "");
  // Tabs print as one space, so that characters counted from the line's bytes are columns.
  std::replace(shown.text.begin(), shown.text.end(), '\t', ' ');
  shown.marks_at = CountCharacters(line.substr(from, at - from)) + (from > 0 ? 3 : 0);
  shown.room = std::max<std::uint32_t>(1, CountCharacters(line.substr(at, to - at)));
  return shown;
}

std::string Paint(const std::string& text, const char* code, bool color) {
  return color ? fmt::format("\x1b[{}m{}\x1b[0m", code, text) : text;
}

}  // namespace

std::string RenderCompact(const SourceManager& sources, const Diagnostic& diagnostic) {
  std::string out;
  if (auto place = PlaceOf(sources, diagnostic)) {
    out = Location(*place, diagnostic.show_column_range) + ": ";
  } else {
    out = "sled: ";
  }
  out += fmt::format("{}[{}]: {}", SeverityName(diagnostic.severity), diagnostic.code(),
                     diagnostic.message);
  if (!diagnostic.help.empty()) out += fmt::format(" (help: {})", diagnostic.help);
  return out;
}

std::string RenderRich(const SourceManager& sources, const Diagnostic& diagnostic,
                       const RenderOptions& options) {
  const bool color = options.color;
  const char* severity_color = diagnostic.severity == Severity::kError ? "1;31" : "1;33";
  std::string out =
      Paint(fmt::format("{}[{}]", SeverityName(diagnostic.severity), diagnostic.code()),
            severity_color, color);
  out += Paint(fmt::format(": {}", diagnostic.message), "1", color);
  out += '\n';

  auto place = PlaceOf(sources, diagnostic);
  if (place) {
    const SourceBuffer& buffer = sources.buffer(diagnostic.labels[0].range.file);
    // The gutter is as wide as the largest line number shown.
    std::uint32_t widest = place->start.line;
    for (const Label& label : diagnostic.labels) {
      if (label.range.file == diagnostic.labels[0].range.file) {
        widest = std::max(widest, buffer.Locate(label.range.begin).line);
      }
    }
    const std::string gutter(fmt::format("{}", widest).size(), ' ');
    out += fmt::format("{}{} {}\n", gutter, Paint("-->", "1;34", color),
                       Location(*place, diagnostic.show_column_range));
    out += fmt::format("{} {}\n", gutter, Paint("|", "1;34", color));
    for (const Label& label : diagnostic.labels) {
      if (!(label.range.file == diagnostic.labels[0].range.file)) continue;
      const LineColumn start = buffer.Locate(label.range.begin);
      const std::string_view line = buffer.Line(start.line);
      const std::uint32_t line_start = buffer.OffsetOf(start.line, 1);
      const ShownLine shown = ShowLine(line, label.range.begin - line_start);
      // Underline to the end of the range, of the line or of what is shown, whichever comes
      // first.
      const std::uint32_t line_end = line_start + static_cast<std::uint32_t>(line.size());
      const std::uint32_t span_end = std::min(label.range.end, line_end);
      const std::uint32_t width =
          span_end <= label.range.begin
              ? 1
              : CountCharacters(buffer.text().substr(
                    label.range.begin,
                    std::min<std::uint32_t>(span_end - label.range.begin, 4 * shown.room)));
      out += fmt::format("{:>{}} {} {}\n", start.line, gutter.size(), Paint("|", "1;34", color),
                         shown.text);
      const std::string marks(std::max<std::uint32_t>(1, std::min(width, shown.room)),
                              label.primary ? '^' : '-');
      std::string underline = std::string(shown.marks_at, ' ') + marks;
      if (!label.message.empty()) underline += " " + label.message;
      out += fmt::format("{} {} {}\n", gutter, Paint("|", "1;34", color),
                         Paint(underline, label.primary ? severity_color : "1;34", color));
    }
    for (const std::string& note : diagnostic.notes) {
      out += fmt::format("{} = note: {}\n", gutter, note);
    }
    if (!diagnostic.help.empty()) {
      out += fmt::format("{} = {}: {}\n", gutter, Paint("help", "1", color), diagnostic.help);
    }
  } else {
    for (const std::string& note : diagnostic.notes) out += fmt::format("  = note: {}\n", note);
    if (!diagnostic.help.empty()) out += fmt::format("  = help: {}\n", diagnostic.help);
  }
  return out;
}

std::string RenderAll(const SourceManager& sources, const std::vector<Diagnostic>& diagnostics,
                      DiagnosticStyle style, const RenderOptions& options) {
  std::string out;
  int errors = 0;
  int warnings = 0;
  for (const Diagnostic& diagnostic : diagnostics) {
    out += style == DiagnosticStyle::kCompact ? RenderCompact(sources, diagnostic)
                                              : RenderRich(sources, diagnostic, options);
    out += '\n';
    errors += diagnostic.severity == Severity::kError ? 1 : 0;
    warnings += diagnostic.severity == Severity::kWarning ? 1 : 0;
  }
  if (style == DiagnosticStyle::kRich && (errors > 0 || warnings > 0)) {
    out += fmt::format("{} error{}, {} warning{}\n", errors, errors == 1 ? "" : "s", warnings,
                       warnings == 1 ? "" : "s");
  }
  return out;
}

}  // namespace sled::lang
