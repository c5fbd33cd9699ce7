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

# The package must build riprap with the CLI's dependencies, or its bits could differ.
echo "== python: python/Cargo.lock locks riprap's dependencies as Cargo.lock does"
python3 - <<'PY'
import re, sys
def locked(path):
    text = open(path).read()
    pkgs = {}
    for name, version in re.findall(r'\[\[package\]\]\nname = "([^"]+)"\nversion = "([^"]+)"', text):
        pkgs.setdefault(name, set()).add(version)
    return pkgs
root, py = locked("Cargo.lock"), locked("python/Cargo.lock")
differ = [f"{n}: {sorted(v)} against {sorted(py.get(n, []))}" for n, v in root.items()
          if n != "riprap" and n in py and py[n] != v]
if differ:
    sys.exit("python/Cargo.lock differs from Cargo.lock (copy Cargo.lock over it, then "
             "`cargo fetch --manifest-path python/Cargo.toml` adds PyO3):\n  " + "\n  ".join(differ))
PY

echo "== python: virtual environment $venv, pip install ."
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "maturin>=1.5,<2" numpy pandas pytest
# Without build isolation: the maturin just installed builds the wheel.
export PATH="$venv/bin:$PATH"   # the build backend runs `maturin` by name
pip install --quiet --no-build-isolation "$repo"

echo "== python: pytest python/tests"
RIPRAP_BIN="${RIPRAP_BIN:-$CARGO_TARGET_DIR/release/riprap}" RIPRAP_REQUIRE_CLI=1 \
  "$venv/bin/python" -m pytest -q "$repo/python/tests"
