; Highlights of sled for tree-sitter editors (Neovim, Helix, Zed). Capture names follow the
; common set (nvim-treesitter's), which the others map too.

(comment) @comment @spell

(string) @string
(escape_sequence) @string.escape

(number) @number
(unit) @type.builtin
(boolean) @boolean

; The keyword of a declaration or a block, and the name it declares.
(statement
  keyword: (identifier) @keyword
  (#any-of? @keyword
    "scenario" "import" "param" "let" "body" "segment" "joint" "vehicle" "plane" "ellipsoid"
    "function" "contact" "belt" "harness" "airbag" "spring" "tension" "constraint" "load" "initial"
    "override" "output" "time" "integrator" "restart" "settle" "symmetry" "wind" "water"
    "actuator"))

(statement
  keyword: (identifier) @_declaration
  target: (path (identifier) @type.definition)
  (#any-of? @_declaration
    "param" "let" "body" "segment" "joint" "vehicle" "plane" "ellipsoid" "function" "belt"
    "harness" "airbag" "spring" "tension" "constraint" "load" "actuator"))

; Any other statement keyword is an attribute (`mass = 11.7 kg`) or an output request.
(statement
  keyword: (identifier) @property)

(clause
  word: _ @keyword.operator)

(call
  function: (path (identifier) @function.call))

(argument
  name: (identifier) @variable.parameter)

(path (identifier) @variable)

["=" "->" "+" "-" "*" "/" "^"] @operator
["{" "}" "(" ")"] @punctuation.bracket
["," ";"] @punctuation.delimiter
