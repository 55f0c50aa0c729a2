#include "lang/syntax/parser.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "lang/source/utf8.h"
#include "lang/syntax/grammar.h"
#include "lang/syntax/lexical.h"
#include "lang/syntax/syntax_to_ast.h"
#include "lang/syntax/syntax_tree.h"

namespace sled::lang {
namespace {

namespace pegtl = tao::pegtl;
namespace g = grammar;
using syntax::Node;
using syntax::NodeType;

// Which grammar rules become syntax-tree nodes.
template <typename Rule>
inline constexpr NodeType kNodeOf = NodeType::kNone;
// clang-format off
template <> inline constexpr NodeType kNodeOf<g::header> = NodeType::kHeader;
template <> inline constexpr NodeType kNodeOf<g::row> = NodeType::kRow;
template <> inline constexpr NodeType kNodeOf<g::keyword_name> = NodeType::kKeyword;
template <> inline constexpr NodeType kNodeOf<g::target> = NodeType::kTarget;
template <> inline constexpr NodeType kNodeOf<g::word_clause> = NodeType::kWordClause;
template <> inline constexpr NodeType kNodeOf<g::colon_clause> = NodeType::kColonClause;
template <> inline constexpr NodeType kNodeOf<g::clause_word> = NodeType::kClauseWord;
template <> inline constexpr NodeType kNodeOf<g::statement_value> = NodeType::kStatementValue;
template <> inline constexpr NodeType kNodeOf<g::block> = NodeType::kBlock;
template <> inline constexpr NodeType kNodeOf<g::arrow> = NodeType::kArrow;
template <> inline constexpr NodeType kNodeOf<g::sum> = NodeType::kSum;
template <> inline constexpr NodeType kNodeOf<g::product> = NodeType::kProduct;
template <> inline constexpr NodeType kNodeOf<g::power> = NodeType::kPower;
template <> inline constexpr NodeType kNodeOf<g::negate> = NodeType::kNegate;
template <> inline constexpr NodeType kNodeOf<g::op_power> = NodeType::kOperator;
template <> inline constexpr NodeType kNodeOf<g::op_times> = NodeType::kOperator;
template <> inline constexpr NodeType kNodeOf<g::op_divide> = NodeType::kOperator;
template <> inline constexpr NodeType kNodeOf<g::op_plus> = NodeType::kOperator;
template <> inline constexpr NodeType kNodeOf<g::op_minus> = NodeType::kOperator;
template <> inline constexpr NodeType kNodeOf<g::quantity> = NodeType::kQuantity;
template <> inline constexpr NodeType kNodeOf<g::number> = NodeType::kNumber;
template <> inline constexpr NodeType kNodeOf<g::unit> = NodeType::kUnit;
template <> inline constexpr NodeType kNodeOf<g::unit_symbol> = NodeType::kUnitSymbol;
template <> inline constexpr NodeType kNodeOf<g::unit_power> = NodeType::kUnitPower;
template <> inline constexpr NodeType kNodeOf<g::unit_div> = NodeType::kUnitDivide;
template <> inline constexpr NodeType kNodeOf<g::tuple> = NodeType::kVector;
template <> inline constexpr NodeType kNodeOf<g::tuple_comma> = NodeType::kTupleComma;
template <> inline constexpr NodeType kNodeOf<g::call> = NodeType::kCall;
template <> inline constexpr NodeType kNodeOf<g::named_argument> = NodeType::kNamedArgument;
template <> inline constexpr NodeType kNodeOf<g::argument_name> = NodeType::kArgumentName;
template <> inline constexpr NodeType kNodeOf<g::positional_argument> = NodeType::kPositionalArgument;
template <> inline constexpr NodeType kNodeOf<g::path> = NodeType::kPath;
template <> inline constexpr NodeType kNodeOf<g::string_literal> = NodeType::kString;
template <> inline constexpr NodeType kNodeOf<g::boolean> = NodeType::kBoolean;
// clang-format on

// What an error message calls a rule when the parser expected it and did not find it. Only
// rules that fail where they start are named, so the farthest failure is a real position.
template <typename Rule>
inline constexpr const char* kExpectedName = nullptr;
// clang-format off
template <> inline constexpr const char* kExpectedName<g::equals> = "`=`";
template <> inline constexpr const char* kExpectedName<g::colon> = "`:`";
template <> inline constexpr const char* kExpectedName<g::comma> = "`,`";
template <> inline constexpr const char* kExpectedName<g::arrow_op> = "`->`";
template <> inline constexpr const char* kExpectedName<g::open_brace> = "`{`";
template <> inline constexpr const char* kExpectedName<g::close_brace> = "`}`";
template <> inline constexpr const char* kExpectedName<g::open_paren> = "`(`";
template <> inline constexpr const char* kExpectedName<g::close_paren> = "`)`";
template <> inline constexpr const char* kExpectedName<g::close_quote> = "`\"`";
template <> inline constexpr const char* kExpectedName<g::primary> = "a value";
template <> inline constexpr const char* kExpectedName<g::keyword_name> = "a statement";
template <> inline constexpr const char* kExpectedName<g::line_end> = "end of line";
// clang-format on

// Rules whose nesting is limited, so hostile input cannot exhaust the stack.
template <typename Rule>
inline constexpr bool kCountsDepth = false;
template <>
inline constexpr bool kCountsDepth<g::value> = true;
template <>
inline constexpr bool kCountsDepth<g::unary> = true;
template <>
inline constexpr bool kCountsDepth<g::block> = true;

struct DepthExceeded {
  std::uint32_t offset;
};

struct ParseState {
  const char* base = nullptr;
  std::vector<std::unique_ptr<Node>> stack;
  std::vector<SourceRange> comments;
  std::vector<std::uint32_t> child_marks;  // children of the top node when a rule started
  FileId file;
  int depth = 0;
  int max_depth = 64;

  // The farthest point the current statement reached, and what was expected there.
  std::uint32_t farthest = 0;
  std::vector<const char*> expected;

  struct Problem {
    DiagnosticKind kind;
    std::uint32_t begin;
    std::uint32_t end;
    std::string message;
    std::string label;
    std::string help;
  };
  std::vector<Problem> problems;

  std::uint32_t Offset(const char* p) const { return static_cast<std::uint32_t>(p - base); }
};

// The PEGTL control: builds the syntax tree, tracks the farthest failure and limits depth.
template <typename Rule>
struct Control : pegtl::normal<Rule> {
  // Every rule, PEGTL's internal ones included, reports to the control: a sequence that fails
  // after some of its parts succeeded must take back the nodes those parts added
  // (`opt<op_power, unary>` where `^` matched but no operand followed).
  static constexpr bool enable = true;
  static constexpr bool kComposite = Rule::subs_t::size > 0;

  template <typename Input>
  static void start(const Input& in, ParseState& state) {
    if constexpr (kCountsDepth<Rule>) {
      if (++state.depth > state.max_depth) throw DepthExceeded{state.Offset(in.current())};
    }
    if constexpr (kNodeOf<Rule> != NodeType::kNone) {
      auto node = std::make_unique<Node>();
      node->type = kNodeOf<Rule>;
      node->begin = state.Offset(in.current());
      state.stack.push_back(std::move(node));
    } else if constexpr (kComposite) {
      state.child_marks.push_back(static_cast<std::uint32_t>(state.stack.back()->children.size()));
    }
  }

  template <typename Input>
  static void success(const Input& in, ParseState& state) {
    if constexpr (kCountsDepth<Rule>) --state.depth;
    if constexpr (kNodeOf<Rule> != NodeType::kNone) {
      auto node = std::move(state.stack.back());
      state.stack.pop_back();
      node->end = state.Offset(in.current());
      state.stack.back()->children.push_back(std::move(node));
    } else if constexpr (kComposite) {
      state.child_marks.pop_back();
    }
  }

  template <typename Input>
  static void failure(const Input& in, ParseState& state) {
    if constexpr (kCountsDepth<Rule>) --state.depth;
    if constexpr (kNodeOf<Rule> != NodeType::kNone) {
      state.stack.pop_back();
    } else if constexpr (kComposite) {
      state.stack.back()->children.resize(state.child_marks.back());
      state.child_marks.pop_back();
    }
    if constexpr (kExpectedName<Rule> != nullptr) {
      const std::uint32_t at = state.Offset(in.current());
      if (at > state.farthest) {
        state.farthest = at;
        state.expected.clear();
      }
      if (at == state.farthest && std::find(state.expected.begin(), state.expected.end(),
                                            kExpectedName<Rule>) == state.expected.end()) {
        state.expected.push_back(kExpectedName<Rule>);
      }
    }
  }
};

// Actions record trivia and recovery; they run only on the path the parse finally takes
// through a rule, but a backtracked alternative may have run them too, so reports are deduped.
template <typename Rule>
struct Action : pegtl::nothing<Rule> {};

template <>
struct Action<g::comment> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, ParseState& state) {
    const std::uint32_t begin = state.Offset(in.begin());
    if (!state.comments.empty() && state.comments.back().begin >= begin) return;
    state.comments.push_back({state.file, begin, state.Offset(in.end())});
  }
};

template <>
struct Action<g::item_start> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, ParseState& state) {
    state.farthest = state.Offset(in.begin());
    state.expected.clear();
  }
};

std::string DescribeFound(std::string_view text, std::uint32_t at) {
  if (at >= text.size()) return "end of file";
  const char c = text[at];
  if (c == '\n' || c == '\r') return "end of line";
  auto is_word = [](char x) {
    return std::isalnum(static_cast<unsigned char>(x)) || x == '_' || x == '.';
  };
  if (is_word(c)) {
    std::size_t end = at;
    while (end < text.size() && end - at < 40 && is_word(text[end])) ++end;
    return fmt::format("`{}`", text.substr(at, end - at));
  }
  if (static_cast<unsigned char>(c) >= 0x80) {
    // Decode one UTF-8 sequence so the message shows the character and its code point.
    const auto lead = static_cast<unsigned char>(c);
    const std::size_t length = Utf8SequenceLength(text, at);
    if (length < 2) return fmt::format("byte 0x{:02X}", lead);
    std::uint32_t code = lead & (0x7Fu >> length);
    for (std::size_t i = 1; i < length; ++i) {
      code = (code << 6) | (static_cast<unsigned char>(text[at + i]) & 0x3Fu);
    }
    return fmt::format("character `{}` (U+{:04X})", text.substr(at, length), code);
  }
  if (static_cast<unsigned char>(c) < 0x20) {
    return fmt::format("control character 0x{:02X}", static_cast<unsigned char>(c));
  }
  return fmt::format("`{}`", c);
}

// True when the word starting at `begin` is a complete number: 12, 0.5, 1e-5, 2.5E+3.
bool IsWholeNumber(std::string_view text, std::size_t begin) {
  const std::size_t end = begin + NumberSpellingLength(text, begin);
  return end > begin &&
         (end >= text.size() || !(std::isalnum(static_cast<unsigned char>(text[end])) ||
                                  text[end] == '_' || text[end] == '.'));
}

std::string JoinExpected(const std::vector<const char*>& expected) {
  std::string out;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (i > 0) out += (i + 1 == expected.size()) ? " or " : ", ";
    out += expected[i];
  }
  return out;
}

template <>
struct Action<g::skip> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, ParseState& state) {
    const std::string_view text(state.base, state.Offset(in.input().end()));
    std::uint32_t at = std::max(state.farthest, state.Offset(in.begin()));
    ParseState::Problem problem;
    problem.begin = at;
    const char c = at < text.size() ? text[at] : '\0';
    const bool control = at < text.size() && static_cast<unsigned char>(c) < 0x20 && c != '\n' &&
                         c != '\r' && c != '\t';
    const bool non_ascii = at < text.size() && static_cast<unsigned char>(c) >= 0x80;
    const bool meaningless =
        at < text.size() && std::string_view("@#$%&|~?!`'[]\\").find(c) != std::string_view::npos;
    const auto is_word = [](char x) {
      return std::isalnum(static_cast<unsigned char>(x)) || x == '_' || x == '.';
    };
    // A number run into letters or a second decimal point: `12abc`, `1.2.3`.
    std::uint32_t number_start = at;
    while (number_start > 0 && is_word(text[number_start - 1])) --number_start;
    const bool malformed_number = at < text.size() && is_word(text[at]) &&
                                  std::isdigit(static_cast<unsigned char>(text[number_start])) &&
                                  !IsWholeNumber(text, number_start);
    const bool expects_close_paren =
        std::find(state.expected.begin(), state.expected.end(), kExpectedName<g::close_paren>) !=
        state.expected.end();
    const bool at_line_end = at >= text.size() || c == '\n' || c == '\r';
    if (control || non_ascii || meaningless) {
      problem.kind = DiagnosticKind::kInvalidCharacter;
      problem.end = static_cast<std::uint32_t>(NextCharacterStart(text, at));
      problem.message =
          fmt::format("unexpected {} outside a string or comment", DescribeFound(text, at));
      problem.label = "not part of the language";
      problem.help = "names, units and keywords use ASCII letters, digits and `_`";
    } else if (malformed_number) {
      std::uint32_t end = at;
      while (end < text.size() && is_word(text[end])) ++end;
      problem.kind = DiagnosticKind::kInvalidNumber;
      problem.begin = number_start;
      problem.end = end;
      problem.message =
          fmt::format("malformed number `{}`", text.substr(number_start, end - number_start));
      problem.label = "not a number";
      problem.help = "numbers are written like 12, 0.5 or 1e-5, with a space before the unit";
    } else if (c == ')' && !expects_close_paren) {
      problem.kind = DiagnosticKind::kUnmatchedClosing;
      problem.end = at + 1;
      problem.message = "`)` closes nothing";
      problem.label = "no `(` is open here";
      problem.help = "remove it, or check the `(` before it";
    } else if (expects_close_paren && at_line_end) {
      problem.kind = DiagnosticKind::kUnclosedDelimiter;
      problem.end = at;
      problem.message = "`(` is not closed before the end of the line";
      problem.label = "expected `)` here";
      problem.help = "close the parenthesis; a value may continue on the next line only after `,`";
    } else if (std::find(state.expected.begin(), state.expected.end(),
                         kExpectedName<g::close_quote>) != state.expected.end()) {
      problem.kind = DiagnosticKind::kUnclosedDelimiter;
      problem.end = at;
      problem.message = "string is not closed before the end of the line";
      problem.label = "expected `\"` here";
      problem.help = "strings cannot span lines; close the string with `\"`";
    } else {
      problem.kind = DiagnosticKind::kSyntaxError;
      // When the parser had to cross a line break to find the offending token, the mistake is
      // almost always at the end of the line before (a missing `)` or `,`): report it there.
      std::uint32_t before = at;
      while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t' ||
                            text[before - 1] == '\r' || text[before - 1] == '\n')) {
        --before;
      }
      if (text.substr(before, at - before).find('\n') != std::string_view::npos &&
          before > state.Offset(in.begin())) {
        at = before;
        problem.begin = at;
      }
      problem.end = at;
      const std::string found = DescribeFound(text, at);
      problem.message = state.expected.empty() ? fmt::format("unexpected {}", found)
                                               : fmt::format("expected {}, found {}",
                                                             JoinExpected(state.expected), found);
      problem.label = state.expected.empty() ? "not understood" : "unexpected here";
      problem.help = "the rest of this statement was skipped";
    }
    // A word or a symbol is underlined whole.
    if (problem.kind == DiagnosticKind::kSyntaxError && at < text.size() && text[at] != '\n') {
      std::uint32_t end = at;
      while (end < text.size() && is_word(text[end])) ++end;
      problem.end = end > at ? end : at + 1;
    }
    state.problems.push_back(std::move(problem));
  }
};

template <>
struct Action<g::stray_close> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, ParseState& state) {
    state.problems.push_back({DiagnosticKind::kUnmatchedClosing, state.Offset(in.begin()),
                              state.Offset(in.end()), "`}` closes no block",
                              "nothing to close here", "remove it, or check the `{` above"});
  }
};

template <>
struct Action<g::missing_close_brace> {
  template <typename ActionInput>
  static void apply(const ActionInput& in, ParseState& state) {
    (void)in;
    // The label goes on the `{` that is still open: the innermost block on the node stack.
    std::uint32_t open = 0;
    for (auto it = state.stack.rbegin(); it != state.stack.rend(); ++it) {
      if ((*it)->type == NodeType::kBlock) {
        open = (*it)->begin;
        break;
      }
    }
    state.problems.push_back({DiagnosticKind::kUnclosedDelimiter, open, open + 1,
                              "`{` is never closed",
                              "this block is still open at the end of "
                              "the file",
                              "add the missing `}`"});
  }
};

// --- Trivia: comments and blank lines -------------------------------------------------------

class TriviaAssigner {
 public:
  TriviaAssigner(std::string_view text, std::vector<SourceRange> comments)
      : text_(text), comments_(std::move(comments)) {}

  void AssignBlock(ast::Block& block, std::uint32_t content_begin, std::uint32_t end) {
    std::uint32_t previous_end = content_begin;
    for (ast::Statement& statement : block.statements) {
      while (next_ < comments_.size() && comments_[next_].begin < statement.range.begin) {
        ast::Comment comment = MakeComment(comments_[next_++]);
        comment.blank_line_before = CountNewlines(previous_end, comment.range.begin) >= 2;
        // A comment inside the previous statement's value ends before that statement does.
        previous_end = std::max(previous_end, comment.range.end);
        statement.leading_comments.push_back(std::move(comment));
      }
      statement.blank_line_before = CountNewlines(previous_end, statement.range.begin) >= 2;
      if (statement.block) {
        AssignBlock(*statement.block, statement.block->range.begin + 1, statement.block->range.end);
      }
      previous_end = statement.range.end;
      if (next_ < comments_.size() && comments_[next_].begin >= statement.range.end &&
          comments_[next_].begin < end &&
          CountNewlines(statement.range.end, comments_[next_].begin) == 0) {
        statement.trailing_comment = MakeComment(comments_[next_++]);
        previous_end = statement.trailing_comment->range.end;
      }
    }
    while (next_ < comments_.size() && comments_[next_].begin < end) {
      ast::Comment comment = MakeComment(comments_[next_++]);
      comment.blank_line_before = CountNewlines(previous_end, comment.range.begin) >= 2;
      previous_end = std::max(previous_end, comment.range.end);
      block.closing_comments.push_back(std::move(comment));
    }
  }

 private:
  ast::Comment MakeComment(const SourceRange& range) const {
    std::string_view body = text_.substr(range.begin + 2, range.end - range.begin - 2);
    while (!body.empty() && (body.back() == ' ' || body.back() == '\t' || body.back() == '\r')) {
      body.remove_suffix(1);
    }
    return {std::string(body), range};
  }

  int CountNewlines(std::uint32_t from, std::uint32_t to) const {
    int count = 0;
    for (std::uint32_t i = from; i < to && i < text_.size(); ++i) count += text_[i] == '\n';
    return count;
  }

  std::string_view text_;
  std::vector<SourceRange> comments_;
  std::size_t next_ = 0;
};

void MarkRecoveredBlocks(ast::Block& block, const std::vector<ParseState::Problem>& problems);

void MarkStatement(ast::Statement& statement, const std::vector<ParseState::Problem>& problems) {
  if (statement.block) MarkRecoveredBlocks(*statement.block, problems);
}

// A block that contains a skipped statement is marked, so the checker does not pile
// "missing attribute" errors on top of the syntax error that caused them.
void MarkRecoveredBlocks(ast::Block& block, const std::vector<ParseState::Problem>& problems) {
  for (const auto& problem : problems) {
    if (problem.begin >= block.range.begin && problem.begin < block.range.end) {
      block.had_syntax_errors = true;
    }
  }
  for (ast::Statement& statement : block.statements) MarkStatement(statement, problems);
}

void Report(const ParseState& state, DiagnosticConsumer& diagnostics) {
  // Backtracking can run an action twice for the same place; report each place once.
  std::vector<std::pair<std::uint32_t, DiagnosticKind>> seen;
  for (const auto& problem : state.problems) {
    const auto key = std::make_pair(problem.begin, problem.kind);
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    auto diagnostic = MakeDiagnostic(problem.kind, {state.file, problem.begin, problem.end},
                                     problem.message, problem.label);
    diagnostic.help = problem.help;
    diagnostics.Consume(std::move(diagnostic));
  }
}

template <typename Rule>
std::unique_ptr<Node> RunGrammar(const SourceBuffer& buffer, FileId file, int max_depth,
                                 ParseState& state, DiagnosticConsumer& diagnostics) {
  const std::string_view text = buffer.text();
  state.base = text.data();
  state.file = file;
  state.max_depth = max_depth;
  state.stack.push_back(std::make_unique<Node>());
  pegtl::memory_input<pegtl::tracking_mode::lazy> in(text.data(), text.data() + text.size(),
                                                     buffer.path());
  try {
    if (!pegtl::parse<Rule, Action, Control>(in, state)) return nullptr;
  } catch (const DepthExceeded& exceeded) {
    diagnostics.Consume([&] {
      auto d = MakeDiagnostic(
          DiagnosticKind::kNestingTooDeep, {file, exceeded.offset, exceeded.offset + 1},
          fmt::format("blocks and expressions are nested more than {} deep", max_depth),
          "too deep here");
      d.help = "split the expression or flatten the blocks";
      return d;
    }());
    return nullptr;
  }
  state.stack.resize(1);
  return std::move(state.stack.front());
}

}  // namespace

// Bytes that are not UTF-8 in strings and comments (outside them the grammar reports them): a
// title of Latin-1 text would otherwise reach summary.json and make it invalid JSON.
void ReportInvalidUtf8(std::string_view text, FileId file, DiagnosticCollector& found) {
  for (const std::size_t at : InvalidUtf8PerLine(text)) {
    const bool reported = std::any_of(
        found.diagnostics().begin(), found.diagnostics().end(),
        [&](const Diagnostic& d) { return d.primary_range() && d.primary_range()->begin == at; });
    if (reported) continue;
    const auto begin = static_cast<std::uint32_t>(at);
    auto d = MakeDiagnostic(
        DiagnosticKind::kInvalidCharacter, {file, begin, begin + 1},
        fmt::format("byte 0x{:02X} is not UTF-8", static_cast<unsigned char>(text[at])),
        "not UTF-8");
    d.help =
        "sled files are UTF-8; save the file as UTF-8 (iconv -f latin1 -t utf-8 converts "
        "Latin-1 text)";
    found.Consume(std::move(d));
  }
}

ast::File Parse(const SourceManager& sources, FileId file, const ParseOptions& options) {
  if (!options.diagnostics) throw std::logic_error("lang::Parse: options.diagnostics is null");
  const SourceBuffer& buffer = sources.buffer(file);
  ast::File result;
  result.file = file;
  result.body.range = {file, 0, static_cast<std::uint32_t>(buffer.text().size())};

  // The grammar and the conversion find problems in different passes; report them in source
  // order.
  DiagnosticCollector found;
  ParseState state;
  auto root = RunGrammar<g::file>(buffer, file, options.max_depth, state, found);
  Report(state, found);
  if (root) {
    syntax::ConvertFile(*root, buffer.text(), file, found, result.body);
  }
  ReportInvalidUtf8(buffer.text(), file, found);
  found.SortByPosition();
  for (const Diagnostic& diagnostic : found.diagnostics()) options.diagnostics->Consume(diagnostic);
  if (!root) {
    result.body.had_syntax_errors = true;
    return result;
  }
  MarkRecoveredBlocks(result.body, state.problems);
  TriviaAssigner trivia(buffer.text(), std::move(state.comments));
  trivia.AssignBlock(result.body, 0, result.body.range.end + 1);
  return result;
}

namespace {
namespace value_grammar {
struct whole_value : pegtl::seq<g::ws, g::value, g::ws, pegtl::eof> {};
}  // namespace value_grammar
}  // namespace

std::optional<ast::Expr> ParseValue(const SourceManager& sources, FileId file,
                                    const ParseOptions& options) {
  if (!options.diagnostics) throw std::logic_error("lang::ParseValue: options.diagnostics is null");
  const SourceBuffer& buffer = sources.buffer(file);
  ParseState state;
  auto root = RunGrammar<value_grammar::whole_value>(buffer, file, options.max_depth, state,
                                                     *options.diagnostics);
  if (!root || root->children.empty()) {
    const std::uint32_t at =
        std::min<std::uint32_t>(state.farthest, static_cast<std::uint32_t>(buffer.text().size()));
    auto d = MakeDiagnostic(DiagnosticKind::kSyntaxError, {file, at, at + 1},
                            state.expected.empty()
                                ? std::string("this is not a value")
                                : fmt::format("expected {}, found {}", JoinExpected(state.expected),
                                              DescribeFound(buffer.text(), at)));
    options.diagnostics->Consume(std::move(d));
    return std::nullopt;
  }
  return syntax::ConvertValue(*root->children.at(0), buffer.text(), file, *options.diagnostics);
}

}  // namespace sled::lang
