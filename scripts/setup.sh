#!/usr/bin/env bash
# Installs what a fresh Debian 12 machine lacks to build and test sled. Idempotent: when every
# package is already installed it does nothing (and does not touch apt), so a second run is fast.
set -euo pipefail

packages=(
  build-essential
  cmake
  ninja-build
  clang
  clang-format
  clang-tidy          # scripts/lint.sh tidy, run by CI
  libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes for clang 14
  llvm                # llvm-symbolizer: file and line in sanitizer reports
  libeigen3-dev
  libsuitesparse-dev
  tao-pegtl-dev
  libfmt-dev
  googletest
  libgtest-dev
  libgmock-dev
  libbenchmark-dev
  libmujoco-dev       # test- and benchmark-only peer (tests/verification, tests/bench)
  libsundials-dev     # benchmark-only peer: CVODE (tests/bench/cvode_peer.cpp)
  nlohmann-json3-dev  # sled report reads summary.json; sled lsp speaks JSON-RPC with it
  nodejs              # test-only: the TextMate grammar test (editors/tests, with npm)
  libtree-sitter-dev  # test-only: runs the tree-sitter grammar's parser (editors/tests)
  chromium            # test-only: loads the report page headless (tests/report)
  slurm-wlm           # test-only: a one-node cluster for `sled sweep --slurm`
  munge               #   (scripts/slurm_cluster.sh, scripts/slurm_sweep_test.sh)
)

# The TextMate grammar test's npm packages (vscode-textmate, vscode-oniguruma: the tokenizer
# VS Code uses), pinned by editors/tests/package-lock.json; skipped where npm is not installed
# (the test then reports itself skipped).
install_npm_packages() {
  local here
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  if command -v npm >/dev/null 2>&1 && [[ ! -d "${here}/editors/tests/node_modules" ]]; then
    npm ci --prefix "${here}/editors/tests" --no-audit --no-fund
  fi
}
trap install_npm_packages EXIT

missing=()
for package in "${packages[@]}"; do
  if ! dpkg -s "${package}" >/dev/null 2>&1; then
    missing+=("${package}")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
  else
    echo "setup: not root and no sudo; install as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update
"${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
