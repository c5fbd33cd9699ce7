#!/usr/bin/env bash
# The Python package's checks (issue 32), called by .ci/run after the Rust suite, whose
# `riprap` binary (target/release/riprap) the same-bits tests run against. It lints the
# bindings, makes a virtual environment in target/python-venv with maturin, numpy, pandas
# and pytest from PyPI, installs this clone into it with `pip install .` (as a user does),
# and runs python/tests. The bindings build into target/ too, reusing the riprap crate the
# suite compiled.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$repo/target}"
venv="${RIPRAP_VENV:-$repo/target/python-venv}"

echo "== python: cargo fmt --check, clippy (python/Cargo.toml)"
cargo fmt --manifest-path python/Cargo.toml -- --check
cargo clippy --release --manifest-path python/Cargo.toml --all-targets -- -D warnings

echo "== python: virtual environment $venv, pip install ."
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "maturin>=1.5,<2" numpy pandas pytest
# Without build isolation: the maturin just installed builds the wheel.
export PATH="$venv/bin:$PATH"   # the build backend runs `maturin` by name
pip install --quiet --no-build-isolation "$repo"

echo "== python: pytest python/tests"
RIPRAP_BIN="${RIPRAP_BIN:-$CARGO_TARGET_DIR/release/riprap}" RIPRAP_REQUIRE_CLI=1 \
  "$venv/bin/python" -m pytest -q "$repo/python/tests"
