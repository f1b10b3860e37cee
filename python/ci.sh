#!/usr/bin/env bash
# CI of the Python package (called by .ci/run): formatting and lints of its Rust half,
# the package built and installed with pip as a user installs it (a fresh virtual
# environment, `pip install ./python[test]`), then its tests (pytest), which compare it
# with the `deckland` CLI built by `cargo test --workspace`.
#
# Needs the Rust toolchain and Python ≥ 3.9 with pip and venv (3.11 on the project's
# machines); pip fetches maturin, numpy and the test extras.
set -euo pipefail
cd "$(dirname "$0")/.."

PYTHON="${PYTHON:-python3}"
VENV="${DECKLAND_CI_VENV:-target/python-ci-venv}"

echo "== cargo fmt --check (python/)"
cargo fmt --manifest-path python/Cargo.toml --check

echo "== pip install ./python[test] into a fresh virtual environment ($VENV)"
rm -rf "$VENV"
"$PYTHON" -m venv "$VENV"
# shellcheck disable=SC1091
source "$VENV/bin/activate"
python -m pip install --quiet --disable-pip-version-check "./python[test]"

echo "== cargo clippy (python/) -- -D warnings"
# PyO3's build script reads the interpreter of the virtual environment.
cargo clippy --manifest-path python/Cargo.toml --all-targets -- -D warnings

echo "== cargo test --release (python/)"
# The release profile of the wheel pip has just built in python/target: the tests reuse
# its compiled dependencies (the CLI's figure and Parquet crates among them) instead of
# compiling them all again for a debug build.
cargo test --release --manifest-path python/Cargo.toml

echo "== the deckland CLI the tests compare with"
cargo build -p deckland-cli
export DECKLAND_BIN="$PWD/target/debug/deckland"

echo "== pytest python/tests"
# From outside python/, so that the installed package is imported, not the sources.
cd "$VENV"
python -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests"
