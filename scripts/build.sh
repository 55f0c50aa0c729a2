#!/usr/bin/env bash
# Configures and builds sled with a CMake preset (CMakePresets.json); a thin wrapper that keeps
# the README's command and CI's calls short:
#   scripts/build.sh              preset release: GCC, Release, warnings as errors       -> build/
#   scripts/build.sh --sanitize   preset asan: Clang -O1, AddressSanitizer + UBSan       -> build-asan/
#   scripts/build.sh --fuzz       preset fuzz: Clang, the libFuzzer targets only         -> build-fuzz/
# The same by hand: cmake --preset release && cmake --build --preset release.
# Extra arguments after `--` go to the CMake configure step (e.g. -- -DSLED_BENCH=OFF).
# SLED_JOBS overrides the number of parallel jobs (default: all cores).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset=release
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sanitize) preset=asan ;;
    --fuzz) preset=fuzz ;;
    --) shift; extra+=("$@"); break ;;
    -h|--help)
      sed -n '2,9p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) echo "build.sh: unknown argument '$1' (use --sanitize, --fuzz or -- CMAKE_ARGS)" >&2; exit 2 ;;
  esac
  shift
done

cd "${root}"
cmake --preset "${preset}" "${extra[@]}"
cmake --build --preset "${preset}" --parallel "${SLED_JOBS:-$(nproc)}"
