#!/usr/bin/env bash
# Tests the tree-sitter grammar (editors/tree-sitter-sled) through the parser generated from it
# (src/parser.c, committed as tree-sitter grammars are) and the tree-sitter runtime library,
# with editors/tests/tree_sitter_check.c built against both (CMake target
# sled_tree_sitter_check):
#   1. the corpus tests (test/corpus/*.txt) parse to their expected trees;
#   2. every .sled file of the repository that sled parses without a syntax error (E01xx) parses
#      without an ERROR or MISSING node;
#   3. in each of those files, the statements tree-sitter finds (their keywords, and `row` for
#      table rows, in reading order) are exactly those of sled's own parser
#      (`sled check --dump-ast`).
# After changing grammar.js, regenerate src/ with `tree-sitter generate` (editors/tree-sitter-sled/
# README.md) before running this.
#
#   bash editors/tests/tree_sitter_test.sh SLED TREE_SITTER_CHECK
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sled="$1"
check="$2"
grammar="${root}/editors/tree-sitter-sled"

failed=0
"${check}" corpus "${grammar}"/test/corpus/*.txt || failed=1

files=()
while IFS= read -r file; do
  diagnostics="$("${sled}" check --diagnostics=compact --no-lints "${root}/${file}" 2>&1 \
                 >/dev/null || true)"
  [[ "${diagnostics}" == *"error[E01"* ]] && continue
  files+=("${root}/${file}")
done < <(git -C "${root}" ls-files '*.sled')
"${check}" parse "${files[@]}" || failed=1

same=0
different=0
for file in "${files[@]}"; do
  # (sled exits 1 for a file with errors of the checker; the tree is printed all the same)
  expected="$({ "${sled}" check --dump-ast "${file}" 2>/dev/null || true; } |
              sed -nE 's/^[[:space:]]*\(([A-Za-z_][A-Za-z0-9_]*).*/\1/p')"
  actual="$("${check}" keywords "${file}")"
  if [[ "${expected}" == "${actual}" ]]; then
    same=$((same + 1))
  else
    different=$((different + 1))
    echo "FAILED: ${file#"${root}/"}: statements differ from sled's parser (< sled, > tree-sitter):"
    diff <(echo "${expected}") <(echo "${actual}") | head -6 || true
  fi
done
echo "statements: ${same} passed, ${different} failed"
[[ ${different} -eq 0 ]] || failed=1

exit "${failed}"
