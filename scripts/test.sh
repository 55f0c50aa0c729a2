#!/usr/bin/env bash
# Builds sled (GCC, warnings as errors, into build/) and runs the whole test suite.
# Arguments go to scripts/build.sh (e.g. -- -DSLED_PEERS=ON). Exits non-zero when the build fails
# or any test fails.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"${root}/scripts/build.sh" "$@"
ctest --test-dir "${root}/build" --output-on-failure --parallel "${SLED_JOBS:-$(nproc)}"
