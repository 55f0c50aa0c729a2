#!/usr/bin/env bash
# Configures and builds sled with CMake and Ninja.
#   scripts/build.sh              GCC, Release, warnings as errors               -> build/
#   scripts/build.sh --sanitize   Clang, -O1, AddressSanitizer + UBSan, -Werror  -> build-asan/
#   scripts/build.sh --fuzz       Clang, the libFuzzer targets only, -Werror     -> build-fuzz/
# Extra arguments after `--` go to the CMake configure step (e.g. -- -DSLED_BENCH=OFF).
# SLED_JOBS overrides the number of parallel jobs (default: all cores).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mode=default
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sanitize) mode=sanitize ;;
    --fuzz) mode=fuzz ;;
    --) shift; extra+=("$@"); break ;;
    -h|--help)
      sed -n '2,7p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) echo "build.sh: unknown argument '$1' (use --sanitize, --fuzz or -- CMAKE_ARGS)" >&2; exit 2 ;;
  esac
  shift
done

jobs="${SLED_JOBS:-$(nproc)}"
target=()
case "${mode}" in
  default)
    dir="${root}/build"
    args=(-DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ -DSLED_WERROR=ON)
    ;;
  sanitize)
    dir="${root}/build-asan"
    # -O1 keeps the sanitized build and its tests fast enough for CI; line tables (no NDEBUG,
    # so assertions stay on) give sanitizer reports with file and line.
    args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only"
          -DCMAKE_CXX_COMPILER=clang++ -DSLED_WERROR=ON -DSLED_SANITIZE=ON)
    ;;
  fuzz)
    dir="${root}/build-fuzz"
    args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only"
          -DCMAKE_CXX_COMPILER=clang++ -DSLED_WERROR=ON -DSLED_FUZZ=ON -DSLED_BENCH=OFF)
    target=(--target sled_fuzzers)  # only the fuzzers: the tests are built and run elsewhere
    ;;
esac

cmake -S "${root}" -B "${dir}" -G Ninja "${args[@]}" "${extra[@]}"
cmake --build "${dir}" --parallel "${jobs}" "${target[@]}"
