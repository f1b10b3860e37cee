#!/bin/sh
# The README's two hero images: `deckland land --seed 1` (the realistic default), its
# approach.png and plan_view.png. The numbers of their captions are checked against the
# binary by crates/deckland-cli/tests/readme_numbers.rs; run this after a change that
# moves them, then correct the captions where the test says. A README is read on a
# screen: the figures are drawn 160 mm wide at 150 dpi (945 px), not a journal column.
set -eu
cd "$(dirname "$0")/../.."
out=target/hero
cargo run --release -- land --seed 1 --figure-width-mm 160 --figure-dpi 150 --out "$out" --force
cp "$out/approach.png" docs/images/approach.png
cp "$out/plan_view.png" docs/images/plan-view.png
echo "wrote docs/images/approach.png and docs/images/plan-view.png from $out"
