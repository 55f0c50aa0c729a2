// lang/diagnostics and lang/source: the compact and rich renderers of a diagnostic, the registry
// of diagnostic kinds, the collector, the did-you-mean suggestions, and the line and column
// tables of source buffers. (The parse errors themselves are tested in parser_test.cpp.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"

namespace sled::lang {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// --- Diagnostics rendering --------------------------------------------------------------------

// A diagnostic of a registered kind on a known piece of a buffer.
Diagnostic UnknownUnitAt(FileId file, std::uint32_t begin, std::uint32_t end) {
  Diagnostic diagnostic = MakeDiagnostic(DiagnosticKind::kUnknownUnit, {file, begin, end},
                                         "unknown unit `kgg`", "not a unit sled knows");
  diagnostic.help = "did you mean `kg`?";
  return diagnostic;
}

TEST(RenderDiagnostic, CompactFormIsPathLineColumnSeverityCodeMessage) {
  SourceManager sources;
  const FileId file = sources.Add("scenes/a.sled", "x = 1\nmass = 11.7 kgg\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kSyntaxError, {file, 18, 21}, "expected `=`, found `kgg`");
  EXPECT_EQ(RenderCompact(sources, diagnostic),
            "scenes/a.sled:2:13: error[E0101]: expected `=`, found `kgg`");
  diagnostic.help = "remove it";
  EXPECT_EQ(RenderCompact(sources, diagnostic),
            "scenes/a.sled:2:13: error[E0101]: expected `=`, found `kgg` (help: remove it)");
}

TEST(RenderDiagnostic, CompactFormOfWarningsAndLocationFreeDiagnostics) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "function f = 1\n");
  Diagnostic warning =
      MakeDiagnostic(DiagnosticKind::kUnusedFunction, {file, 9, 10}, "function `f` is unused");
  EXPECT_EQ(RenderCompact(sources, warning), "a.sled:1:10: warning[W0001]: function `f` is unused");
  Diagnostic nowhere;
  nowhere.kind = DiagnosticKind::kFileUnreadable;
  nowhere.message = "cannot read `missing.sled`";
  EXPECT_EQ(RenderCompact(sources, nowhere), "sled: error[E0107]: cannot read `missing.sled`");
}

TEST(RenderDiagnostic, CompactFormShowsCardColumnsWhenAsked) {
  SourceManager sources;
  const FileId file = sources.Add("deck.ain", "A.1 CARD  12.5  x\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kSyntaxError, {file, 10, 14}, "not a number");
  diagnostic.show_column_range = true;
  EXPECT_EQ(RenderCompact(sources, diagnostic), "deck.ain:1:11-14: error[E0101]: not a number");
}

TEST(RenderDiagnostic, RichFormShowsTheLineCaretsLabelAndHelp) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "x = 1\nmass = 11.7 kgg\n");
  Diagnostic diagnostic = UnknownUnitAt(file, 18, 21);
  diagnostic.notes.push_back("units are case-sensitive");
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:2:13\n"
            "  |\n"
            "2 | mass = 11.7 kgg\n"
            "  |             ^^^ not a unit sled knows\n"
            "  = note: units are case-sensitive\n"
            "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormWidensTheGutterAndDrawsSecondaryLabels) {
  std::string text;
  for (int i = 1; i <= 9; ++i) text += "a = 1\n";
  text += "b = 2 mm\n";  // line 10
  SourceManager sources;
  const FileId file = sources.Add("a.sled", text);
  Diagnostic diagnostic = MakeDiagnostic(DiagnosticKind::kDuplicateName, {file, 0, 1},
                                         "`a` is declared twice", "first here");
  diagnostic.labels.push_back({{file, 54, 55}, "b is here", false});
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0202]: `a` is declared twice\n"
            "  --> a.sled:1:1\n"
            "   |\n"
            " 1 | a = 1\n"
            "   | ^ first here\n"
            "10 | b = 2 mm\n"
            "   | - b is here\n");
}

TEST(RenderDiagnostic, RichFormAlignsCaretsUnderUtf8AndTabs) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "\tname = \"Müller\" kgg\n");
  const std::uint32_t begin =
      static_cast<std::uint32_t>(std::string("\tname = \"Müller\" ").size());
  Diagnostic diagnostic = UnknownUnitAt(file, begin, begin + 3);
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:1:18\n"
            "  |\n"
            "1 |  name = \"Müller\" kgg\n"
            "  |                  ^^^ not a unit sled knows\n"
            "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormOfALongUtf8LineShowsAWindowWithAlignedCarets) {
  // 5,000 two-byte characters (past the source's 4 KB column blocks), a tab, the label, more.
  std::string before;
  for (int i = 0; i < 5000; ++i) before += "ü";
  const std::string text = before + "\tkgg" + std::string(300, 'x') + "\n";
  SourceManager sources;
  const FileId file = sources.Add("a.sled", text);
  const auto begin = static_cast<std::uint32_t>(before.size() + 1);
  Diagnostic diagnostic = UnknownUnitAt(file, begin, begin + 3);
  std::string window = "...";
  for (int i = 0; i < 39; ++i) window += "ü";
  window += " kgg" + std::string(77, 'x') + "...";  // 120 characters in all
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:1:5002\n"
            "  |\n"
            "1 | " +
                window +
                "\n"
                "  | " +
                std::string(43, ' ') +
                "^^^ not a unit sled knows\n"
                "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormOfAnEmptyRangeAtTheEndOfALineShowsOneCaret) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "title = \"abc\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kUnclosedDelimiter, {file, 12, 12}, "string is not closed");
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0102]: string is not closed\n"
            " --> a.sled:1:13\n"
            "  |\n"
            "1 | title = \"abc\n"
            "  |             ^\n");
}

TEST(RenderDiagnostic, RichFormInColorWrapsTheHeadingInEscapes) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "mass = 1 kgg\n");
  const std::string colored =
      RenderRich(sources, UnknownUnitAt(file, 9, 12), RenderOptions{.color = true});
  EXPECT_THAT(colored, HasSubstr("\x1b[1;31merror[E0301]\x1b[0m"));
  EXPECT_EQ(RenderRich(sources, UnknownUnitAt(file, 9, 12)).find('\x1b'), std::string::npos);
}

// --- Diagnostic registry and suggestions ------------------------------------------------------

TEST(DiagnosticRegistry, CodesAreUniqueAndFindable) {
  std::vector<std::string_view> codes;
  for (const DiagnosticInfo& info : AllDiagnostics()) {
    EXPECT_EQ(std::count(codes.begin(), codes.end(), info.code), 0) << info.code;
    codes.push_back(info.code);
    EXPECT_EQ(FindDiagnosticByCode(info.code), info.kind);
    EXPECT_EQ(InfoOf(info.kind).code, info.code);
    EXPECT_EQ(info.code[0] == 'W', info.severity == Severity::kWarning) << info.code;
  }
  EXPECT_FALSE(FindDiagnosticByCode("E9999").has_value());
}

TEST(DiagnosticCollector, CountsBySeverityAndSortsByPosition) {
  DiagnosticCollector collector;
  const FileId file{1};
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnknownName, {file, 30, 31}, "late"));
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnusedFunction, {file, 5, 6}, "early"));
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnknownUnit, {file, 30, 32}, "late too"));
  EXPECT_EQ(collector.error_count(), 2);
  EXPECT_EQ(collector.warning_count(), 1);
  collector.SortByPosition();
  std::vector<std::string> order;
  for (const Diagnostic& d : collector.diagnostics()) order.push_back(d.message);
  EXPECT_THAT(order, ElementsAre("early", "late", "late too"));
  collector.Clear();
  EXPECT_FALSE(collector.has_errors());
  EXPECT_THAT(collector.diagnostics(), IsEmpty());
}

TEST(DidYouMean, SuggestsTheClosestCandidateWithinAThirdOfTheLength) {
  const std::vector<std::string> attributes = {"friction", "force", "damping", "mass"};
  EXPECT_EQ(ClosestMatch("frictoin", attributes), "friction");
  EXPECT_EQ(ClosestMatch("forse", attributes), "force");
  EXPECT_EQ(ClosestMatch("mas", attributes), "mass");
  EXPECT_EQ(ClosestMatch("stiffness", attributes), std::nullopt);
  EXPECT_EQ(ClosestMatch("mass", attributes), std::nullopt);  // an exact match needs no hint
  EXPECT_EQ(ClosestMatch("x", {}), std::nullopt);
  EXPECT_EQ(DidYouMean("kgg", {"kg", "g", "m"}), "did you mean `kg`?");
  EXPECT_EQ(DidYouMean("qq", {"kg", "g", "m"}), "one of: `kg`, `g`, `m`");
  EXPECT_EQ(DidYouMean("qq", {"kg"}), "the only choice here is `kg`");
  EXPECT_EQ(DidYouMean("qq", {"a", "b", "c", "d", "e", "f", "g", "h", "i"}), "");
  EXPECT_EQ(DidYouMean("qq", {}), "");
}

TEST(DidYouMean, SuggestedNamesReadBackEveryFormItWrites) {
  using V = std::vector<std::string>;
  EXPECT_EQ(SuggestedNames(DidYouMean("kgg", {"kg", "g", "m"})), V{"kg"});
  EXPECT_EQ(SuggestedNames(DidYouMean("qq", {"kg", "g", "m"})), (V{"kg", "g", "m"}));
  EXPECT_EQ(SuggestedNames(DidYouMean("qq", {"kg"})), V{"kg"});
  // A longer hint that starts the same way suggests its first name only.
  EXPECT_EQ(SuggestedNames("did you mean `knee_r`, the joint from `a` to `b`?"), V{"knee_r"});
  EXPECT_EQ(SuggestedNames("write the unit after the number, such as `5 mm`"), V{});
  EXPECT_EQ(SuggestedNames(""), V{});
}

TEST(DidYouMean, CountsTwoSwappedLettersAsOneEdit) {
  // "widht" is two substitutions from "width" but one swap; a third of five letters allows one.
  EXPECT_EQ(ClosestMatch("widht", {"width", "depth"}), "width");
  EXPECT_EQ(ClosestMatch("plevis", {"pelvis", "thorax"}), "pelvis");
  EXPECT_EQ(ClosestMatch("tdiwh", {"width"}), std::nullopt);  // a swap is of neighbours only
}

// --- Sources ----------------------------------------------------------------------------------

TEST(SourceBuffer, LocateCountsLinesAndColumnsFromOne) {
  const SourceBuffer buffer("a.sled", "ab\ncd\n\nef");
  EXPECT_EQ(buffer.line_count(), 4u);
  const auto at = [&](std::uint32_t offset) {
    const LineColumn place = buffer.Locate(offset);
    return fmt::format("{}:{}", place.line, place.column);
  };
  EXPECT_EQ(at(0), "1:1");
  EXPECT_EQ(at(2), "1:3");  // the newline itself belongs to its line
  EXPECT_EQ(at(3), "2:1");
  EXPECT_EQ(at(6), "3:1");
  EXPECT_EQ(at(8), "4:2");
  EXPECT_EQ(at(9), "4:3");     // end of buffer
  EXPECT_EQ(at(1000), "4:3");  // clamped
}

TEST(SourceBuffer, LocateCountsUtf8CharactersNotBytes) {
  const SourceBuffer buffer("a.sled", "é = \"µ€𝄞\" x\n");
  EXPECT_EQ(buffer.Locate(2).column, 2u);  // the space after é
  // Bytes: é 0-1, ` = "` 2-5, µ 6-7, € 8-10, 𝄞 11-14, `"` 15, space 16, x 17.
  EXPECT_EQ(buffer.Locate(15).column, 9u);   // the closing quote
  EXPECT_EQ(buffer.Locate(17).column, 11u);  // x
  EXPECT_EQ(buffer.OffsetOf(1, 11), 17u);
  EXPECT_EQ(buffer.OffsetOf(1, 8), 11u);
}

TEST(SourceBuffer, CrlfLinesEndBeforeTheCarriageReturn) {
  const SourceBuffer buffer("a.sled", "x = 1\r\nmass 11.7 kg\r\n");
  EXPECT_EQ(buffer.Line(1), "x = 1");
  EXPECT_EQ(buffer.Line(2), "mass 11.7 kg");
  EXPECT_EQ(buffer.Locate(7).line, 2u);
  EXPECT_EQ(buffer.Locate(7).column, 1u);
  EXPECT_EQ(buffer.Locate(12).column, 6u);
  EXPECT_EQ(buffer.OffsetOf(2, 6), 12u);
  EXPECT_EQ(buffer.Line(99), "");
}

TEST(SourceManager, AddsFindsAndSlicesBuffers) {
  SourceManager sources;
  const FileId a = sources.Add("a.sled", "alpha");
  const FileId b = sources.Add("b.sled", "beta");
  EXPECT_NE(a.value, b.value);
  EXPECT_EQ(sources.Find("b.sled"), b);
  EXPECT_FALSE(sources.Find("c.sled").has_value());
  EXPECT_EQ(sources.Text({b, 1, 3}), "et");
  EXPECT_EQ(sources.Text({}), "");
  EXPECT_EQ(sources.buffer(a).path(), "a.sled");
  EXPECT_THROW(sources.buffer(FileId{}), std::logic_error);
  EXPECT_FALSE(sources.Load("/nonexistent/sled/file.sled").has_value());
}

TEST(SourceRange, JoinCoversBothAndPrecedesOrdersByFileThenOffset) {
  const SourceRange a{FileId{1}, 4, 8};
  const SourceRange b{FileId{1}, 2, 5};
  EXPECT_EQ(Join(a, b), (SourceRange{FileId{1}, 2, 8}));
  EXPECT_EQ(Join(SourceRange{}, a), a);
  EXPECT_TRUE(Precedes(b, a));
  EXPECT_FALSE(Precedes(a, b));
  EXPECT_TRUE(Precedes(SourceRange{FileId{1}, 9, 9}, SourceRange{FileId{2}, 0, 1}));
}

}  // namespace
}  // namespace sled::lang

namespace sled::lang {
namespace {}  // namespace
}  // namespace sled::lang
