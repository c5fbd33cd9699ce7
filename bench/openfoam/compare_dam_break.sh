#!/usr/bin/env bash
# Wall time of riprap against OpenFOAM's interFoam on the same dam break (Martin & Moyce 1952,
# riprap's validation case dam_break): the same tank, grid, fluids, free-slip walls and physical
# end time T = t sqrt(2g/a) = 3.2, each code with its own time-step control, on 1 and 2 cores,
# each measured REPEATS times, alternating riprap and interFoam so that both see the same load.
# Prints the median wall times, their ratio, and each code's front error against Martin & Moyce,
# measured the same way for both (dam_break_front.py).
#
#   bench/openfoam/compare_dam_break.sh [CELLS_PER_A] [REPEATS]     (defaults 8,16 and 3)
#
# CELLS_PER_A: a/dx, even, or a comma-separated list of them. Environment: CORES (default
# "1 2"); MAX_LOAD (e.g. 1.5: before each timed pair, wait until the 1-minute load average is
# below it, polling every 20 s, at most WAIT_S seconds, default 1800; the load is logged either
# way); RIPRAP (a riprap binary; else cargo builds one); RESULTS (the results folder; default
# runs/openfoam_dam_break/DATE under the repository).
#
# riprap: `riprap --threads T bench fluid --dam-break N --front-csv F` (src/main.rs,
# bench_dam_break: the validation case dam_break run as it is validated).
# interFoam: the case bench/openfoam/dam_break, copied and meshed (blockMesh, setFields, and
# for 2 cores decomposePar) before the runs; `interFoam`, or on 2 cores `mpirun -np 2 interFoam
# -parallel`. Wall time: the whole process of each, from start to exit (riprap: building the
# scenario and the run; interFoam: reading the case and the run). Both sample the bottom row of
# cells every 0.05 in T for the front (interFoam: its function object `front`).
#
# OpenFOAM is installed from Debian (package openfoam, v1912) when interFoam is missing, with
# sudo unless run as root. Needs python3 (standard library only).
set -euo pipefail

SIZES=${1:-8,16}
REPEATS=${2:-3}
CORES=${CORES:-1 2}
WAIT_S=${WAIT_S:-1800}
A=0.05715

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

if ! command -v interFoam >/dev/null 2>&1; then
    echo "interFoam not found: installing OpenFOAM from Debian (apt-get install openfoam)" >&2
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo=sudo
    $sudo apt-get update
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y openfoam
fi
if [ -f /usr/share/openfoam/etc/bashrc ]; then
    # The OpenFOAM environment reads unset variables.
    set +u
    # shellcheck disable=SC1091
    source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1 || true
    set -u
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

if [ -z "${RIPRAP:-}" ]; then
    (cd "$root" && cargo build --release --quiet)
    RIPRAP="${CARGO_TARGET_DIR:-$root/target}/release/riprap"
fi

out=${RESULTS:-$root/runs/openfoam_dam_break/$(date +%Y%m%d-%H%M%S)}
mkdir -p "$out"
work=$(mktemp -d "${TMPDIR:-/tmp}/riprap-of-dam-break.XXXXXX")
trap 'rm -rf "$work"' EXIT
front_py="$here/dam_break_front.py"

now() { date +%s.%N; }
load1() { cut -d' ' -f1 /proc/loadavg; }

# Waits (when MAX_LOAD is set) until the 1-minute load is below MAX_LOAD or WAIT_S have passed.
settle() {
    [ -z "${MAX_LOAD:-}" ] && return 0
    local waited=0
    while awk -v l="$(load1)" -v m="$MAX_LOAD" 'BEGIN { exit !(l >= m) }'; do
        if [ "$waited" -ge "$WAIT_S" ]; then
            echo "  (load $(load1) still above $MAX_LOAD after ${WAIT_S} s: measuring anyway)"
            return 0
        fi
        sleep 20
        waited=$((waited + 20))
    done
}

# Median of the numbers given as arguments.
median() {
    printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END {
        if (NR % 2) print v[(NR + 1) / 2]; else printf "%.6g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# The case for a/$1 in $work/case.$1, meshed and filled (and decomposed).
prepare() {
    local n=$1 c="$work/case.$1"
    local scale end every
    scale=$(awk -v a="$A" 'BEGIN { printf "%.15g", sqrt(2 * 9.81 / a) }')
    end=$(awk -v s="$scale" 'BEGIN { printf "%.12g", 3.2 / s }')
    every=$(awk -v s="$scale" 'BEGIN { printf "%.12g", 0.05 / s }')
    cp -r "$here/dam_break" "$c"
    sed -i "s/^N .*/N       $n;/; s/^NX .*/NX      $((5 * n));/; s/^NZ .*/NZ      $((5 * n / 2));/" \
        "$c/system/blockMeshDict"
    dx=$(awk -v a="$A" -v n="$n" 'BEGIN { printf "%.12g", a / n }')
    lo=$(awk -v d="$dx" 'BEGIN { printf "%.12g", d / 2 }')
    hi=$(awk -v a="$A" -v d="$dx" 'BEGIN { printf "%.12g", 5 * a - d / 2 }')
    sed -i "s/^endTime .*/endTime         $end;/; s/^writeInterval .*/writeInterval   $end;/;
        s/^\( \+writeInterval\)   0.*/\1   $every;/; s/^\( \+start\) .*/\1   ($lo $lo $lo);/;
        s/^\( \+end\) .*/\1     ($hi $lo $lo);/; s/^\( \+nPoints\) .*/\1 $((5 * n));/" \
        "$c/system/controlDict"
    (cd "$c" && blockMesh > log.blockMesh 2>&1 && setFields > log.setFields 2>&1 &&
        decomposePar -force > log.decomposePar 2>&1)
    cp "$c/system/controlDict" "$out/controlDict.a$n"
    cp "$c/system/blockMeshDict" "$out/blockMeshDict.a$n"
}

# Runs a command, printing "WALL CPU": its wall time and the CPU time (user + system) of it and
# its children [s] (CPU "-" without GNU time).
timed() {
    local t0 t1 cpu="-"
    t0=$(now)
    if [ -x /usr/bin/time ]; then
        /usr/bin/time -f "%U %S" -o "$work/cpu" "$@"
        cpu=$(awk '{ printf "%.2f", $1 + $2 }' "$work/cpu")
    else
        "$@"
    fi
    t1=$(now)
    awk -v a="$t0" -v b="$t1" -v c="$cpu" 'BEGIN { printf "%.4f %s", b - a, c }'
}

# Wall and CPU time [s] of interFoam on a/$1 and $2 cores; the run's case stays in $work/run.
openfoam_run() {
    local n=$1 cores=$2
    rm -rf "$work/run"
    cp -r "$work/case.$n" "$work/run"
    cd "$work/run"
    if [ "$cores" -eq 1 ]; then
        timed sh -c 'interFoam > log.interFoam 2>&1'
    else
        timed sh -c "mpirun -np $cores interFoam -parallel > log.interFoam 2>&1"
    fi
    cd - > /dev/null
}

# Wall and CPU time [s] of riprap on a/$1 and $2 cores; its output in $3.
riprap_run() {
    local n=$1 cores=$2 log=$3
    timed sh -c "\"\$0\" --threads $cores bench fluid --dam-break $n --front-csv '$log.front.csv' > '$log'" \
        "$RIPRAP"
}

field() { sed -n "s/^$2: \([-0-9.eE+]*\).*/\1/p" "$1" | head -1; }

{
    echo "dam break (Martin & Moyce 1952) to T = 3.2, a/dx = $SIZES, cores: $CORES, $REPEATS repeats"
    echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "riprap: $RIPRAP ($(cd "$root" && git rev-parse --short HEAD 2>/dev/null || echo '?')); interFoam: $(command -v interFoam), OpenFOAM ${WM_PROJECT_VERSION:-?}"
    echo "results: $out"
} | tee "$out/summary.txt"

declare -A rip of ripc ofc loads
for n in ${SIZES//,/ }; do
    [ $((n % 2)) -eq 0 ] || { echo "CELLS_PER_A must be even, got $n" >&2; exit 1; }
    prepare "$n"
    for rep in $(seq 1 "$REPEATS"); do
        for cores in $CORES; do
            settle
            l=$(load1)
            log="$out/riprap.a$n.c$cores.r$rep.txt"
            read -r r rc <<< "$(riprap_run "$n" "$cores" "$log")"
            read -r o oc <<< "$(openfoam_run "$n" "$cores")"
            key="$n.$cores"
            rip[$key]="${rip[$key]:-} $r"
            of[$key]="${of[$key]:-} $o"
            ripc[$key]="${ripc[$key]:-} $rc"
            ofc[$key]="${ofc[$key]:-} $oc"
            loads[$key]="${loads[$key]:-} $l"
            cp "$work/run/log.interFoam" "$out/interFoam.a$n.c$cores.r$rep.log"
            if [ "$rep" -eq 1 ]; then
                python3 "$front_py" openfoam "$work/run" "$out/interFoam.a$n.c$cores.front.csv" \
                    > "$out/interFoam.a$n.c$cores.errors.txt"
                python3 "$front_py" error "$log.front.csv" > "$out/riprap.a$n.c$cores.errors.txt"
            fi
            echo "a/$n, repeat $rep, $cores core(s), load $l: riprap $r s (CPU $rc s)," \
                "interFoam $o s (CPU $oc s)" \
                | tee -a "$out/summary.txt"
        done
    done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out/summary.txt"

{
    echo
    echo "Wall time of the whole run (CPU: user + system time of the processes, medians too)."
    echo
    echo "| a/dx | cells | cores | riprap median [s] | interFoam median [s] | interFoam / riprap | riprap CPU [s] | interFoam CPU [s] | 1-min load at the runs |"
    echo "|---:|---:|---:|---:|---:|---:|---:|---:|---|"
    for n in ${SIZES//,/ }; do
        for cores in $CORES; do
            key="$n.$cores"
            # shellcheck disable=SC2086
            mr=$(median ${rip[$key]})
            # shellcheck disable=SC2086
            mo=$(median ${of[$key]})
            ratio=$(awk -v a="$mr" -v b="$mo" 'BEGIN { printf "%.2f", b / a }')
            # shellcheck disable=SC2086
            cr=$(median ${ripc[$key]})
            # shellcheck disable=SC2086
            co=$(median ${ofc[$key]})
            echo "| $n | $((5 * n))x$((5 * n / 2)) | $cores | $mr | $mo | $ratio | $cr | $co |${loads[$key]} |"
        done
    done
    echo
    echo "Front against Martin & Moyce (dam_break_front.py, the same for both; T = t sqrt(2g/a)):"
    echo "lead = mean over Z = 2, 2.5, 3 of T_measured - T_run; error = mean |T_measured - T_run|;"
    echo "speed = dZ/dT over T = 1.4 to 3.0 (measured 1.298). Steps: riprap's, interFoam's time steps."
    echo
    echo "| a/dx | cores | code | steps | lead | mean abs dT | front speed | speed error |"
    echo "|---:|---:|---|---:|---:|---:|---:|---:|"
    for n in ${SIZES//,/ }; do
        for cores in $CORES; do
            for code in riprap interFoam; do
                e="$out/$code.a$n.c$cores.errors.txt"
                if [ "$code" = riprap ]; then
                    steps=$(sed -n 's/^steps: \([0-9]*\),.*/\1/p' "$out/riprap.a$n.c$cores.r1.txt")
                else
                    steps=$(grep -c '^Time = ' "$out/interFoam.a$n.c$cores.r1.log")
                fi
                speed=$(sed -n 's/^front speed: \([0-9.]*\) (measured \([0-9.]*\)).*/\1 \2/p' "$e")
                echo "| $n | $cores | $code | $steps | $(field "$e" lead) | $(field "$e" 'mean |dT|') |" \
                    "${speed% *} | $(awk -v s="$speed" 'BEGIN { split(s, v, " "); printf "%+.1f %%", 100 * (v[1] / v[2] - 1) }') |"
            done
            # riprap's own figures (Rust) must agree with the script's reading of its front.
            rl=$(field "$out/riprap.a$n.c$cores.r1.txt" lead)
            pl=$(field "$out/riprap.a$n.c$cores.errors.txt" lead)
            if awk -v a="$rl" -v b="$pl" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d > 2e-4) }'; then
                echo "warning: riprap's lead $rl (Rust) differs from dam_break_front.py's $pl"
            fi
        done
    done
} | tee -a "$out/summary.txt"
