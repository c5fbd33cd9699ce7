#!/usr/bin/env bash
# Do two riprap binaries compute the same bits? Short runs that reach every contact law, walls,
# blocks, moving walls and the coupled flow, run with each binary and compared file by file.
# A change that passes here changes no result; one that does not must re-run the full
# validation cases it can touch (`riprap validate`, README "Validation").
#
# Usage:  scripts/same_bits.sh OLD_RIPRAP NEW_RIPRAP      (about 2 minutes on 2 cores)
# e.g.    git stash; cargo build --release; cp target/release/riprap /tmp/riprap-old
#         git stash pop; cargo build --release
#         scripts/same_bits.sh /tmp/riprap-old target/release/riprap
set -euo pipefail

[ $# -eq 2 ] || { sed -n '2,11p' "$0"; exit 2; }
old=$(realpath "$1"); new=$(realpath "$2")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ex=$root/examples
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The hopper under every contact law (the scenario's own is the source's Voigt-Hertz law).
mkdir -p "$work/sc"
hop=$ex/hopper_feed.toml
cp "$hop" "$work/sc/voigt_hertz.toml"
sed 's/^model = "hertz"/model = "linear"\nstiffness = 2000.0/' "$hop" > "$work/sc/voigt_linear.toml"
sed 's/^model = "hertz"/model = "apparent_linear_hertz"/' "$hop" > "$work/sc/voigt_apparent.toml"
sed 's/^model = "hertz"/model = "hertz"\ntangential_stiffness = "mindlin"/' "$hop" > "$work/sc/voigt_mindlin.toml"
sed 's/^model = "hertz"/model = "hertz_mindlin"/; s/^damping = "restitution"//' "$hop" > "$work/sc/hertz_mindlin.toml"
sed 's/^model = "hertz"/model = "hertz_mindlin_liggghts"/; s/^damping = "restitution"//' "$hop" > "$work/sc/liggghts.toml"

# Runs every case with binary $1 into $2.
runs() {
  local bin=$1 out=$2
  mkdir -p "$out"
  for s in "$work"/sc/*.toml; do
    (cd "$ex" && "$bin" --threads 1 run "$s" --end-time 0.6 --output "$out/$(basename "$s" .toml)" > /dev/null 2>&1)
  done
  (cd "$ex" && "$bin" --threads 2 run tetrapods_on_rubble.toml --steps 3000 --output "$out/blocks" > /dev/null 2>&1)
  (cd "$ex" && "$bin" --threads 2 run shaker.toml --steps 3000 --output "$out/moving_walls" > /dev/null 2>&1)
  (cd "$ex" && "$bin" --threads 2 run single_impact.toml --output "$out/single_impact" > /dev/null 2>&1)
  (cd "$ex" && "$bin" --threads 2 run sheet_flow.toml --end-time 0.03 --output "$out/coupled" > /dev/null 2>&1)
  "$bin" --threads 1 bench b1 --n 4000 --steps 20000 2>&1 | grep -E '^ +[0-9]+ ' > "$out/b1_rows.txt"
  "$bin" --threads 2 bench b2 --steps 500 --every 100 2>&1 | grep -E '^ +[0-9]+ ' > "$out/b2_rows.txt"
}
runs "$old" "$work/old"
runs "$new" "$work/new"

# Compares the results: CSV series and probes, the last frame of each kind, the benchmark rows.
differ=0
for d in "$work"/old/*; do
  name=$(basename "$d")
  if [ -f "$d" ]; then files=("$name"); else
    mapfile -t files < <(cd "$d" && { ls ./*.csv 2>/dev/null; for k in spheres blocks flow; do ls ${k}_*.vt? 2>/dev/null | tail -1; done; } | sed 's|^\./||')
    files=("${files[@]/#/$name/}")
  fi
  verdict=same
  for f in "${files[@]}"; do
    cmp -s "$work/old/$f" "$work/new/$f" || { verdict="DIFFERENT ($f)"; differ=1; break; }
  done
  printf '%-16s %s (%d files)\n' "$name" "$verdict" "${#files[@]}"
done
exit $differ
