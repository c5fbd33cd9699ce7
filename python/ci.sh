#!/usr/bin/env bash
# The Python package's checks (issue 32), called by .ci/run after the Rust suite, whose
# `riprap` binary (target/release/riprap) the same-bits tests run against. It lints the
# bindings, makes a virtual environment in target/python-venv with maturin, numpy, pandas
# and pytest from PyPI, installs this clone into it with `pip install .` (as a user does),
# and runs python/tests. The bindings build into target/ too, reusing the riprap crate the
# suite compiled (python/ is a member of the root workspace and shares its Cargo.lock).
set -euo pipefail
cd "$(dirname "$0")/.."

# A fresh CI machine may have only the Rust toolchain: without a Python that can make a virtual
# environment with pip, install Debian's (sudo only when not root).
if ! python3 -c 'import venv, ensurepip' >/dev/null 2>&1; then
  echo "== python: apt-get install python3 python3-venv python3-pip"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "python/ci.sh: no python3 with venv and ensurepip, and neither root nor sudo to install it" >&2; exit 1; }
    sudo="sudo -n"
  fi
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq >/dev/null
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    python3 python3-venv python3-pip >/dev/null
fi

repo=$(pwd)
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$repo/target}"
venv="${RIPRAP_VENV:-$repo/target/python-venv}"

# python/ is a member of the root workspace (not a default one): one Cargo.lock, so the package
# builds riprap with the CLI's locked dependencies, into the same target directory. The wheel
# still compiles riprap once more, with serde, clap, thiserror and postcard (and their derive
# macros): PyO3's macros enable two more features of syn (extra-traits, visit-mut), which changes
# their hashes, and so riprap's. Its other dependencies are the suite's.
echo "== python: cargo fmt --check, clippy (-p riprap-python)"
cargo fmt -p riprap-python -- --check
cargo clippy --release -p riprap-python --all-targets -- -D warnings

echo "== python: virtual environment $venv, pip install ."
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "maturin>=1.5,<2" numpy pandas pytest
# Without build isolation: the maturin just installed builds the wheel.
export PATH="$venv/bin:$PATH"   # the build backend runs `maturin` by name
pip install --quiet --no-build-isolation "$repo"

echo "== python: pytest python/tests"
RIPRAP_BIN="${RIPRAP_BIN:-$CARGO_TARGET_DIR/release/riprap}" RIPRAP_REQUIRE_CLI=1 \
  "$venv/bin/python" -m pytest -q "$repo/python/tests"
