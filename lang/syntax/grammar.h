// The PEGTL grammar of .sled files (PEGTL 3.2.7). Private to lang/: only parser.cpp and the
// grammar-analysis test include it.
//
// Shape of the language (the schema in the checker gives each keyword its meaning):
//
//   file       = ws { item ws } eof
//   item       = statement | <recovery: skip to the end of the line>
//   statement  = row | header
//   row        = sum "->" sum {"->" sum}               (starts with a number, `(` or `-`)
//   header     = keyword [target] {clause} ["=" values] [block] end
//   target     = path | string
//   clause     = ("on" | "with" | "at" | "as" | "filter" | "relative_to" | "expressed_in") value
//              | ":" value
//   values     = value {"," value}
//   block      = "{" ws { item ws } "}"
//   value      = arrow
//   arrow      = sum {"->" sum}
//   sum        = product {("+" | "-") product}
//   product    = unary {("*" | "/") unary}
//   unary      = "-" unary | power
//   power      = primary ["^" unary]
//   primary    = number [unit] | tuple | call | path | string | bool
//   tuple      = "(" value {"," value} [","] ")" [unit]   (one value, no comma, no unit: a
//                parenthesised value; otherwise a vector)
//   unit       = factor {("*" | "/") factor}            (written without spaces: N*m/deg)
//   factor     = name ["^" ["-"] digits]
//
// Line rules: a header lives on one line up to its `=` or `{`; a value may continue on the next
// line only after `,`, `->`, an operator or inside parentheses (a line breaks after an operator,
// never before); a unit sits on its number's line. A statement that ends with a value or a block
// may share its line with the next (`time { end = 200 ms  output_every = 0.1 ms }`); `;` also
// separates statements. A table attribute's rows are the statement's block:
// `force = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }`.
#pragma once

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

namespace sled::lang::grammar {

namespace pegtl = tao::pegtl;
// The grammar reads best with PEGTL's rule names unqualified.
using namespace pegtl;  // NOLINT(google-build-using-namespace)

// clang-format off

// Trivia. `comment` is recorded by the parser for the formatter.
struct comment : seq< two< '/' >, until< at< eolf >, any > > {};
struct ws : star< sor< space, comment > > {};           // anything, newlines included
struct sp : star< blank > {};                           // blanks on the same line

// Reserved words: never a name, a target or a unit.
struct kw_true : keyword< 't', 'r', 'u', 'e' > {};
struct kw_false : keyword< 'f', 'a', 'l', 's', 'e' > {};
struct kw_on : keyword< 'o', 'n' > {};
struct kw_with : keyword< 'w', 'i', 't', 'h' > {};
struct kw_at : keyword< 'a', 't' > {};
struct kw_as : keyword< 'a', 's' > {};
struct kw_filter : keyword< 'f', 'i', 'l', 't', 'e', 'r' > {};
struct kw_relative_to : keyword< 'r', 'e', 'l', 'a', 't', 'i', 'v', 'e', '_', 't', 'o' > {};
struct kw_expressed_in : keyword< 'e', 'x', 'p', 'r', 'e', 's', 's', 'e', 'd', '_', 'i', 'n' > {};
struct clause_word
    : sor< kw_on, kw_with, kw_at, kw_as, kw_filter, kw_relative_to, kw_expressed_in > {};
struct reserved : sor< kw_true, kw_false, clause_word > {};

struct name : identifier {};
struct plain_name : seq< not_at< reserved >, name > {};

// Punctuation that the error messages name.
struct equals : seq< one< '=' >, not_at< one< '=' > > > {};
struct colon : one< ':' > {};
struct comma : one< ',' > {};
struct arrow_op : string< '-', '>' > {};
struct open_brace : one< '{' > {};
struct close_brace : one< '}' > {};
struct open_paren : one< '(' > {};
struct close_paren : one< ')' > {};
struct semicolon : one< ';' > {};

// Numbers: 12, 0.5, 1e-5, 2.5E+3. The sign is a unary operator.
struct exponent_part : seq< one< 'e', 'E' >, opt< one< '+', '-' > >, plus< digit > > {};
struct number : seq< plus< digit >, opt< one< '.' >, star< digit > >, opt< exponent_part >,
                     not_at< identifier_other > > {};

// Units follow a number or vector on the same line. A unit name is not followed by `=`, `.`,
// `(` or `:` (that would be the next statement, a path or a call), so `x = 5  y = 3` reads two
// statements.
struct unit_power : seq< one< '^' >, opt< one< '-' > >, plus< digit > > {};
struct unit_symbol : seq< not_at< reserved >, name,
                          not_at< sp, sor< equals, one< '.', '(', ':' > > > > {};
struct unit_factor : seq< unit_symbol, opt< unit_power > > {};
struct unit_mul : one< '*' > {};
struct unit_div : one< '/' > {};
struct unit : seq< unit_factor, star< sor< unit_mul, unit_div >, unit_factor > > {};
struct unit_suffix : opt< sp, unit > {};

struct string_char : sor< seq< one< '\\' >, one< '"', '\\', 'n', 't' > >,
                          not_one< '"', '\\', '\n', '\r' > > {};
struct close_quote : one< '"' > {};
struct string_literal : seq< one< '"' >, star< string_char >, close_quote > {};
struct boolean : sor< kw_true, kw_false > {};

struct path : list< plain_name, one< '.' > > {};

struct value;
struct block;

struct positional_argument : seq< value > {};
struct argument_name : name {};
struct named_argument : seq< argument_name, sp, equals, ws, value > {};
struct argument : sor< named_argument, positional_argument > {};
struct argument_list : opt< argument, star< ws, comma, ws, argument >, opt< ws, comma > > {};
struct call : seq< path, open_paren, ws, argument_list, ws, close_paren > {};

// `(a)` is a parenthesised value and `(a, b, c) unit` a vector. One rule reads both, so nested
// parentheses are parsed once rather than once per alternative (which would be exponential).
struct tuple_comma : seq< ws, comma > {};
struct tuple : seq< open_paren, ws, value, star< ws, comma, ws, value >, opt< tuple_comma >, ws,
                    close_paren, unit_suffix > {};
struct quantity : seq< number, unit_suffix > {};
struct value_start : not_at< sor< string< '-', '>' >, one< '}', ')', ',' >, eolf > > {};
struct primary : seq< value_start, sor< quantity, tuple, call, boolean, path,
                                        string_literal > > {};

struct op_power : one< '^' > {};
struct op_times : one< '*' > {};
struct op_divide : one< '/' > {};
struct op_plus : one< '+' > {};
struct op_minus : seq< one< '-' >, not_at< one< '>' > > > {};

struct unary;
struct power : seq< primary, opt< sp, op_power, ws, unary > > {};
struct negate : seq< op_minus, ws, unary > {};
struct unary : sor< negate, power > {};
struct product : seq< unary, star< sp, sor< op_times, op_divide >, ws, unary > > {};
struct sum : seq< product, star< sp, sor< op_plus, op_minus >, ws, product > > {};
struct arrow : seq< sum, star< sp, arrow_op, ws, sum > > {};
struct value : seq< arrow > {};

// Statements.
// A statement ends at the end of its line, a comment, `;` or `}`. One that ends with a value or
// a block may be followed by another statement on the same line.
struct line_end : sor< eolf, two< '/' >, one< ';', '}' > > {};
struct statement_end : at< sp, line_end > {};
struct soft_end : sor< statement_end, at< plus< blank > > > {};
struct row : seq< not_at< identifier_first >, sum, plus< sp, arrow_op, ws, sum >, soft_end > {};
struct keyword_name : seq< not_at< sor< kw_true, kw_false > >, name > {};
struct target : sor< string_literal, seq< path, not_at< one< '(' > > > > {};
struct clause_value : seq< value > {};
struct word_clause : seq< clause_word, sp, clause_value > {};
struct colon_clause : seq< colon, sp, clause_value > {};
struct clause : sor< word_clause, colon_clause > {};
struct statement_value : seq< value > {};
struct value_list : seq< equals, sp, statement_value, star< sp, comma, ws, statement_value > > {};
struct header_start : seq< keyword_name, opt< sp, target >, star< sp, clause > > {};
struct complete_tail : seq< sor< seq< sp, value_list, opt< sp, block > >, seq< sp, block > >,
                            soft_end > {};
struct header : seq< header_start, sor< complete_tail, statement_end > > {};
struct statement : sor< row, header > {};

// Recovery: when a statement fails, `skip` consumes the rest of its line (balancing brackets),
// and the parser reports the farthest point the statement reached and what it expected there.
// clang-format on
// A statement the grammar rejected: consume it up to the end of its line (or `;`, or the `}` of
// the enclosing block), treating brackets, strings and comments as units so that a broken
// statement with a block is skipped whole.
struct skip_statement {
  using rule_t = skip_statement;
  using subs_t = empty_list;

  template <apply_mode, rewind_mode, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  static bool match(ParseInput& in, States&&... /*unused*/) {
    std::size_t i = 0;
    int depth = 0;  // open braces and parentheses
    int braces = 0;
    int parens = 0;
    const std::size_t size = in.size(1u << 30);
    const char* p = in.current();
    while (i < size) {
      const char c = p[i];
      if (depth == 0 && (c == '\n' || c == ';' || c == '}')) break;
      if (c == '\n' && braces == 0) break;  // an unclosed `(` ends with its line
      if (c == '"') {
        // A string is one unit; an unclosed one ends at its opening quote, so that a `}` later on
        // its line still closes the block.
        std::size_t j = i + 1;
        while (j < size && p[j] != '"' && p[j] != '\n') j += (p[j] == '\\' && j + 1 < size) ? 2 : 1;
        i = (j < size && p[j] == '"') ? j + 1 : i + 1;
        continue;
      }
      if (c == '/' && i + 1 < size && p[i + 1] == '/') {
        while (i < size && p[i] != '\n') ++i;
        continue;
      }
      if (c == '}' && braces == 0) break;
      if (c == '{') ++braces;
      if (c == '(') ++parens;
      if (c == '}') --braces;
      if (c == ')' && parens > 0) --parens;
      depth = braces + parens;
      ++i;
    }
    if (i == 0) return false;
    in.bump(i);
    return true;
  }
};

// clang-format off
struct stray_close : one< '}' > {};
struct skip : skip_statement {};
struct item_separator : star< sp, semicolon > {};
struct item_start : success {};
struct item : seq< item_start, sor< statement, skip > > {};

struct missing_close_brace : eof {};
struct block_items : star< not_at< one< '}' > >, not_at< eof >, item, item_separator, ws > {};
struct block : seq< open_brace, ws, block_items, sor< close_brace, missing_close_brace > > {};

struct top_items : star< not_at< eof >, sor< stray_close, item >, item_separator, ws > {};
struct file : seq< opt< utf8::bom >, ws, top_items, eof > {};

// clang-format on

}  // namespace sled::lang::grammar

namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, sled::lang::grammar::skip_statement> : analyze_any_traits<> {};
}  // namespace tao::pegtl
