// Tree-sitter grammar of sled (.sled scenarios and modules), for Neovim, Helix, Zed and other
// editors built on tree-sitter. It follows the parser of lang/syntax/grammar.h: a file is a list
// of statements, each `keyword [target] [clause...] [= value, ...] [{ block }]`, or a table row
// `value -> value [-> value...]`; what a keyword means is the checker's business, not the
// grammar's. Differences, all harmless for highlighting and folding: line breaks are not
// significant here (sled ends a statement at a line break), so a keyword alone on a line before
// another statement can read as that statement's keyword with a target.
//
// Two tokens come from the external scanner (src/scanner.c), where sled's rules need more than a
// regular expression: the unit after a number or a vector (on the same line, no blanks inside
// as in `N*m/deg` and `m/s^2`, and not a word that starts a statement, a path or a call, that is
// one followed by `=`, `.`, `(` or `:`), and the binary minus, which like every operator must be
// on the line of its left operand (a line that starts with `-` starts a new table row).
//
// Generate and test with the tree-sitter CLI: `tree-sitter generate && tree-sitter test`
// (editors/tests/tree_sitter_test.sh also parses every .sled file of the repository).

const CLAUSE_WORDS = ['on', 'with', 'at', 'as', 'filter', 'relative_to', 'expressed_in'];

const PREC = {
  arrow: 1,
  sum: 2,
  product: 3,
  unary: 4,
  power: 5,
};

module.exports = grammar({
  name: 'sled',

  extras: $ => [/\s/, $.comment],

  externals: $ => [$.unit, $._binary_minus],

  word: $ => $.identifier,

  conflicts: $ => [
    // `keyword` then a name on the next line: that statement's target, or a new statement.
    [$.statement],
  ],

  rules: {
    source_file: $ => repeat($._item),

    _item: $ => choice($.statement, $.row, ';'),

    statement: $ => prec.right(seq(
      field('keyword', choice($.identifier, alias(choice(...CLAUSE_WORDS), $.identifier))),
      optional(field('target', choice($.string, $.path))),
      repeat($.clause),
      optional(seq('=', commaSep1(field('value', $._value)))),
      optional(field('body', $.block)),
    )),

    clause: $ => seq(
      field('word', choice(...CLAUSE_WORDS, ':')),
      field('value', $._value),
    ),

    block: $ => seq('{', repeat($._item), '}'),

    // `25 mm -> 2 kN`: a row of a table block.
    row: $ => prec.right(seq(
      $._row_start,
      repeat1(seq('->', $._sum)),
    )),
    // A row never starts with a name (that is a statement's keyword).
    _row_start: $ => choice($.quantity, $.vector, $.unary, $.string,
                            alias($._row_binary, $.binary)),
    _row_binary: $ => choice(
      prec.left(PREC.sum, seq($._row_start, choice('+', alias($._binary_minus, '-')), $._sum)),
      prec.left(PREC.product, seq($._row_start, choice('*', '/'), $._sum)),
      prec.right(PREC.power, seq($._row_start, '^', $._sum)),
    ),

    _value: $ => choice($.arrow, $._sum),

    arrow: $ => prec.left(PREC.arrow, seq($._sum, repeat1(seq('->', $._sum)))),

    _sum: $ => choice(
      $.quantity,
      $.vector,
      $.call,
      $.boolean,
      $.path,
      $.string,
      $.unary,
      $.binary,
    ),

    binary: $ => choice(
      prec.left(PREC.sum, seq($._sum, choice('+', alias($._binary_minus, '-')), $._sum)),
      prec.left(PREC.product, seq($._sum, choice('*', '/'), $._sum)),
      prec.right(PREC.power, seq($._sum, '^', $._sum)),
    ),

    unary: $ => prec(PREC.unary, seq('-', $._sum)),

    quantity: $ => seq(field('number', $.number), optional(field('unit', $.unit))),

    // `(x, y, z) unit`, and a parenthesised expression `(a + b)`.
    vector: $ => seq(
      '(',
      commaSep1($._value),
      optional(','),
      ')',
      optional(field('unit', $.unit)),
    ),

    call: $ => seq(
      field('function', $.path),
      token.immediate('('),
      optional(seq(commaSep1($.argument), optional(','))),
      ')',
    ),

    argument: $ => choice(
      seq(field('name', $.identifier), '=', field('value', $._value)),
      field('value', $._value),
    ),

    path: $ => prec.right(seq($.identifier, repeat(seq(token.immediate('.'), $.identifier)))),

    boolean: _ => choice('true', 'false'),

    number: _ => /\d+(\.\d*)?([eE][+-]?\d+)?/,

    string: $ => seq('"', repeat(choice($.escape_sequence, /[^"\\\n\r]+/)), '"'),
    escape_sequence: _ => /\\["\\nt]/,

    identifier: _ => /[A-Za-z_][A-Za-z0-9_]*/,

    comment: _ => token(seq('//', /[^\n]*/)),
  },
});

function commaSep1(rule) {
  return seq(rule, repeat(seq(',', rule)));
}
