#!/usr/bin/env bash
# The style checks CI runs (docs/architecture.md, conventions):
#   scripts/lint.sh format          clang-format: every C++ file of the tree is formatted as
#                                   .clang-format says (lists the files that are not)
#   scripts/lint.sh tidy [FILE...]  clang-tidy with the checks of .clang-tidy on FILEs (default:
#                                   the CI set below), warnings as errors
#   scripts/lint.sh tidy --all      clang-tidy on every source file of the libraries, the program,
#                                   the tests and the examples
#   scripts/lint.sh                 format, then tidy on the CI set
# clang-tidy reads the compile commands of a Clang build: build-asan/ (scripts/build.sh
# --sanitize), or the folder in $SLED_LINT_BUILD. $SLED_JOBS sets the parallel jobs.
#
# The CI set: every source of lang/ (the language and the legacy translator) and sled/ (the API),
# and the sources changed by the last commit: 37 files took 98 s of CPU time (user, measured
# with /usr/bin/time on a loaded machine). The whole tree has 232 sources, about six times as
# many: too long for CI on 2 cores; run `tidy --all` before a large change.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "${root}"
jobs="${SLED_JOBS:-$(nproc)}"
build="${SLED_LINT_BUILD:-build-asan}"

# Every tracked C++ file of the project's own code.
cpp_files() {
  git ls-files -- '*.cpp' '*.h' | grep -E '^(lang|compiler|runtime|output|sled|tests|examples)/'
}

# The translation units clang-tidy checks (headers are checked through them).
ci_tidy_set() {
  {
    git ls-files -- 'lang/*.cpp' 'sled/*.cpp'
    git diff --name-only --diff-filter=d HEAD~1 -- '*.cpp' 2>/dev/null || true
  } | grep -E '^(lang|compiler|runtime|output|sled|tests|examples)/' | sort -u
}

check_format() {
  local bad
  bad="$(cpp_files | xargs clang-format --dry-run 2>&1 | grep -oE '^[^:]+\.(cpp|h):' | sort -u || true)"
  if [[ -n "${bad}" ]]; then
    echo "lint: not clang-formatted (run clang-format -i on them):" >&2
    echo "${bad//:/}" >&2
    return 1
  fi
  echo "lint: clang-format: $(cpp_files | wc -l) files formatted"
}

check_tidy() {
  if [[ ! -f "${build}/compile_commands.json" ]]; then
    echo "lint: no ${build}/compile_commands.json; build with scripts/build.sh --sanitize first" >&2
    return 1
  fi
  local files=("$@")
  if [[ ${#files[@]} -eq 0 ]]; then
    mapfile -t files < <(ci_tidy_set)
  elif [[ "${files[0]}" == "--all" ]]; then
    mapfile -t files < <(cpp_files | grep '\.cpp$')
  fi
  # Only files the build compiles (a test left out without its peer library is not there).
  local compiled=()
  for file in "${files[@]}"; do
    if grep -q "\"file\": \"${root}/${file}\"" "${build}/compile_commands.json"; then
      compiled+=("${file}")
    fi
  done
  echo "lint: clang-tidy on ${#compiled[@]} files with ${jobs} jobs"
  if [[ ${#compiled[@]} -eq 0 ]]; then return 0; fi
  local log status
  log="$(mktemp)"
  set +e
  printf '%s\n' "${compiled[@]}" |
    xargs -P "${jobs}" -n 1 clang-tidy -p "${build}" --quiet --use-color=false >"${log}" 2>&1
  status=$?
  set -e
  grep -vE '^[0-9]+ warnings? (and [0-9]+ errors? )?generated\.$|^Suppressed [0-9]+ warnings|^Use -header-filter' \
    "${log}" || true
  rm -f "${log}"
  if [[ ${status} -ne 0 ]]; then
    echo "lint: clang-tidy found problems (above)" >&2
    return 1
  fi
}

case "${1:-}" in
  format) check_format ;;
  tidy) shift; check_tidy "$@" ;;
  "") check_format && check_tidy ;;
  -h|--help) sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' ;;
  *) echo "lint.sh: unknown argument '$1' (format, tidy [--all|FILE...])" >&2; exit 2 ;;
esac
