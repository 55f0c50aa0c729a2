#include "lang/diagnostics/render.h"

#include <algorithm>

#include <fmt/format.h>

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

// Width in characters of a byte span, so carets line up with UTF-8 text; tabs count as one
// because the source line is printed with tabs replaced by a single space.
std::uint32_t CharacterWidth(std::string_view text) {
  std::uint32_t width = 0;
  for (unsigned char c : text) {
    if ((c & 0xC0u) != 0x80u) ++width;
  }
  return width;
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
      std::string line(buffer.Line(start.line));
      std::replace(line.begin(), line.end(), '\t', ' ');
      // Underline to the end of the range or of the line, whichever comes first.
      const std::uint32_t line_start = buffer.OffsetOf(start.line, 1);
      const std::uint32_t line_end =
          line_start + static_cast<std::uint32_t>(buffer.Line(start.line).size());
      const std::uint32_t span_end = std::min(std::max(label.range.end, label.range.begin + 1),
                                              std::max(line_end, label.range.begin + 1));
      const std::uint32_t width =
          label.range.begin >= line_end
              ? 1
              : std::max<std::uint32_t>(
                    1, CharacterWidth(buffer.text().substr(
                           label.range.begin, std::min(span_end, line_end) - label.range.begin)));
      out +=
          fmt::format("{:>{}} {} {}\n", start.line, gutter.size(), Paint("|", "1;34", color), line);
      const std::string marks(width, label.primary ? '^' : '-');
      std::string underline = std::string(start.column - 1, ' ') + marks;
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

}  // namespace sled::lang
