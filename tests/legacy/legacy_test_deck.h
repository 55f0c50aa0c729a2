// Helpers of the legacy-deck tests: convert a deck given as text and keep its compact
// diagnostics, and edit a deck line by line.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/source/source_manager.h"

namespace sled::lang::legacy::deck_testing {

inline const std::string kLegacyDir = std::string(SLED_SOURCE_ROOT) + "/examples/legacy/";

struct Converted {
  std::string text;                      // the formatted scenario, empty on errors
  std::vector<std::string> diagnostics;  // compact renderings, sorted by position
  int errors = 0;
  int warnings = 0;
  bool Has(std::string_view needle) const {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [&](const std::string& d) { return d.find(needle) != std::string::npos; });
  }
  std::string All() const {
    std::string all;
    for (const auto& d : diagnostics) all += d + "\n";
    return all;
  }
  bool Says(std::string_view needle) const { return text.find(needle) != std::string::npos; }
};

// A joint converted locked with B.5.a's levels (VISC(4) 50 lb*in, VISC(5) 10 lb*in).
inline void ExpectLockedWithB5Levels(const Converted& converted) {
  ASSERT_EQ(converted.errors, 0) << converted.All();
  for (const char* line : {"locked = true", "unlock_above = 50 lbf*in", "lock_below = 10 lbf*in"})
    EXPECT_TRUE(converted.Says(line)) << line << "\n" << converted.text;
}

inline Converted ConvertText(const std::string& text, ConvertOptions options = {},
                             const std::string& name = "deck.ain") {
  SourceManager sources;
  DiagnosticCollector collector;
  const FileId id = sources.Add(name, text);
  options.diagnostics = &collector;
  const ast::File file = ConvertDeck(sources, id, options);
  Converted out;
  if (!collector.has_errors()) out.text = Format(file);
  collector.SortByPosition();
  for (const Diagnostic& d : collector.diagnostics())
    out.diagnostics.push_back(RenderCompact(sources, d));
  out.errors = collector.error_count();
  out.warnings = collector.warning_count();
  return out;
}

inline std::string ReadDeckFile(const std::string& path) {
  auto text = ReadFile(path);
  EXPECT_TRUE(text.has_value()) << path;
  return text.value_or("");
}

inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

inline std::string Join(const std::vector<std::string>& lines,
                        std::size_t count = std::string::npos) {
  std::string text;
  for (std::size_t i = 0; i < count && i < lines.size(); ++i) text += lines[i] + "\n";
  return text;
}

// The 1-based line of the first line starting with `prefix`.
inline std::size_t LineStarting(const std::vector<std::string>& lines, std::string_view prefix) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind(prefix, 0) == 0) return i + 1;
  }
  ADD_FAILURE() << "no line starts with " << prefix;
  return 1;
}

// Cuts `deck` after every line and converts each cut with `convert`: before the H cards a cut
// deck always lacks a card it announced, so it must report an error (E0501 when
// `expect_end_of_deck`); no cut may crash.
template <typename ConvertFunction>
void ExpectEveryCutIsReported(const std::string& deck, ConvertFunction convert,
                              bool expect_end_of_deck) {
  const std::vector<std::string> lines = Lines(deck);
  const std::size_t h_cards = LineStarting(lines, "# ---- H cards");
  for (std::size_t keep = 0; keep < lines.size(); ++keep) {
    const Converted converted = convert(Join(lines, keep));
    if (keep + 1 < h_cards) {
      EXPECT_GT(converted.errors, 0) << "cut after line " << keep;
      if (expect_end_of_deck) {
        EXPECT_TRUE(converted.Has("error[E0501]")) << "cut after line " << keep;
      }
    }
  }
}

}  // namespace sled::lang::legacy::deck_testing

namespace sled::lang::legacy {

// Every legacy test lives in sled::lang::legacy: the helpers by their short names there.
using deck_testing::Converted;
using deck_testing::ConvertText;
using deck_testing::Join;
using deck_testing::kLegacyDir;
using deck_testing::Lines;
using deck_testing::LineStarting;
using deck_testing::ReadDeckFile;

}  // namespace sled::lang::legacy
