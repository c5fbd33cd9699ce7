#!/usr/bin/env bash
# riprap's shallow-water solver against GeoClaw (issue 31) on the same problem and uniform grid:
# a square hump of water (+1 m over 20 m × 20 m) spreading over a flat bed 10 m deep in a
# 200 m × 200 m basin with walls, N × N cells (default 400: 0.5 m cells), Manning n = 0.025,
# no AMR (GeoClaw: one level), to T seconds. Alternating runs (REPEATS, default 3), one thread
# each (GeoClaw built without OpenMP; riprap --threads 1); prints the cell updates per second of
# each (cells × steps / wall time of the time stepping: GeoClaw's integration time from its
# timing.txt, riprap's flow steps from `riprap bench harbour --no-debris`) and their ratio,
# medians, and the steps each took (Δt differs: see below).
#
# Installs what it needs, cached under $CARGO_TARGET_DIR (default target/): apt's gfortran and
# make, a Python venv with clawpack (PyPI), and clawpack's source (the PyPI sdist: GeoClaw's
# Fortran, which the wheel lacks). Usage:
#   N=400 T=4 REPEATS=3 bash bench/geoclaw/compare.sh [path/to/riprap]
# GEOCLAW_FFLAGS sets gfortran's flags (default -O2, as GeoClaw's documentation builds; riprap
# is built with -C target-cpu=native, .cargo/config.toml).
#
# The two schemes differ: GeoClaw takes one step of its wave-propagation method (f-wave
# Riemann solver, transverse corrections, MC limiter) per Δt with its default cfl_desired = 0.9
# (the largest s Δt/Δx over both directions); riprap two forward-Euler stages of MUSCL-HLL
# (SSP-RK2) with its default C = 0.45 on the sum S_x/Δx + S_y/Δy, i.e. Δt = 0.225 Δx/s on a
# square grid: a quarter of GeoClaw's Δt, each at the largest its method allows. A cell update
# is one cell over one whole step of each; per simulated second GeoClaw takes 4× fewer steps,
# and the script prints that ratio too.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=${1:-riprap}
N=${N:-400}
T=${T:-4}
REPEATS=${REPEATS:-3}
cache=${CARGO_TARGET_DIR:-$root/target}
venv=$cache/geoclaw-venv
FFLAGS=${GEOCLAW_FFLAGS:--O2}
tag=$(echo "$FFLAGS" | tr -c 'A-Za-z0-9\n' '_')
src=$cache/geoclaw-src$tag/clawpack-5.14.0
run=$cache/geoclaw-run$tag-$N

command -v gfortran >/dev/null || apt-get install -y gfortran make
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install -q numpy "clawpack==5.14.0" meson-python meson ninja
fi
export PATH=$venv/bin:$PATH
if [ ! -d "$src" ]; then
    mkdir -p "$cache/geoclaw-sdist" "$(dirname "$src")"
    [ -f "$cache/geoclaw-sdist/clawpack-5.14.0.tar.gz" ] || (cd "$cache/geoclaw-sdist" \
        && pip download -q "clawpack==5.14.0" --no-binary clawpack --no-deps)
    tar xzf "$cache/geoclaw-sdist/clawpack-5.14.0.tar.gz" -C "$(dirname "$src")"
fi
# GeoClaw's objects are built in its source tree: one tree per set of flags.
export CLAW=$src FC=gfortran FFLAGS
mkdir -p "$run"
cp "$src/geoclaw/examples/tsunami/bowl-radial/Makefile" "$run/"
python "$here/setrun_hump.py" "$run" "$N" "$T"
(cd "$run" && make -s .exe >/dev/null && python setrun.py >/dev/null)

cat > "$run/riprap.toml" <<TOML
[run]
name = "hump"
end_time = $T
[shallow]
manning = 0.025
cfl = 0.45
[shallow.grid]
min = [-100.0, -100.0]
max = [100.0, 100.0]
cells = [$N, $N]
[shallow.bed]
kind = "flat"
elevation = -10.0
[shallow.initial]
level = 0.0
[[shallow.initial.region]]
min = [-10.0, -10.0]
max = [10.0, 10.0]
level = 1.0
[output]
vtk_interval = $T
series_interval = $T
checkpoint_interval = $T
plots = false
TOML

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
: > "$run/g.txt"
: > "$run/r.txt"
for r in $(seq 1 "$REPEATS"); do
    # GeoClaw: its own timing of the integration (stepgrid, ghost cells, overhead; not the
    # reading of its data files) and its cell updates, from _output/timing.txt.
    (cd "$run" && rm -rf _output && mkdir _output && cd _output && cp ../*.data . \
        && ../xgeoclaw > run.log 2>&1 \
        && awk -v c=$((N * N)) '/^total/ && !done {printf "%.6e %d %.3f\n", $4 / $2, $4 / c, $2; done = 1}' \
            timing.txt >> ../g.txt)
    echo "geoclaw run $r: $(tail -1 "$run/g.txt") (cell updates/s, steps, wall s)"
    # riprap: the flow's steps alone, timed by `riprap bench harbour` (nothing written).
    "$bin" --threads 1 bench harbour --scenario "$run/riprap.toml" --no-debris 2>/dev/null \
        | awk '/flow steps/ {for (i = 1; i <= NF; i++) if ($(i + 1) == "flow" && $(i + 2) == "steps") n = $i}
               /^wall/ {w = $2} /^flow:/ {c = $2} END {printf "%s %d %.3f\n", c, n, w}' >> "$run/r.txt"
    echo "riprap run $r: $(tail -1 "$run/r.txt") (cell updates/s, steps, wall s)"
done
g=$(awk '{print $1}' "$run/g.txt" | median)
rr=$(awk '{print $1}' "$run/r.txt" | median)
echo "medians of $REPEATS, $N × $N cells, t = $T s, 1 thread: GeoClaw $g, riprap $rr cell updates/s;" \
    "riprap / GeoClaw = $(awk -v a="$rr" -v b="$g" 'BEGIN {printf "%.2f", a / b}') per cell update"
gs=$(awk '{print $2}' "$run/g.txt" | median)
rs=$(awk '{print $2}' "$run/r.txt" | median)
gw=$(awk '{print $3}' "$run/g.txt" | median)
rw=$(awk '{print $3}' "$run/r.txt" | median)
echo "steps to t = $T s: GeoClaw $gs, riprap $rs; wall of the stepping: GeoClaw $gw s, riprap $rw s" \
    "(riprap / GeoClaw per simulated second: $(awk -v a="$rw" -v b="$gw" 'BEGIN {printf "%.2f", b / a}'))"
