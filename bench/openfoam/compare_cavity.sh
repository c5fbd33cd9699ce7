#!/usr/bin/env bash
# Time per step of riprap's flow solver against OpenFOAM's pimpleFoam on the same lid-driven
# cube: N^3 uniform cells, lid speed 1 m/s, Re = 400, the same fixed time step and number of
# steps, on 1 and 2 cores, each measured REPEATS times, alternating riprap and OpenFOAM so that
# both see the same machine load. Prints the median time per step of each and their ratio.
#
#   bench/openfoam/compare_cavity.sh [N] [STEPS] [REPEATS]      (defaults 64 30 3)
#
# riprap: `riprap --threads T bench fluid --cavity N --steps STEPS`, the median wall-clock time
# of one step (the start-up, allocating the grid, is not timed).
# OpenFOAM: the case in bench/openfoam/cavity (PISO-like PIMPLE, GAMG pressure), run for 5 and
# for 5 + STEPS steps; per step = (wall time of the long run - wall time of the short run) /
# STEPS, which leaves out reading the mesh and starting MPI. 2 cores: decomposePar into two
# subdomains, mpirun -np 2.
#
# OpenFOAM is installed from Debian (package openfoam, v1912) when pimpleFoam is missing, with
# sudo unless run as root. Needs cargo for riprap (or RIPRAP=/path/to/riprap).
set -euo pipefail

N=${1:-64}
STEPS=${2:-30}
REPEATS=${3:-3}
SHORT=5
DT=0.005
RE=400

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

if ! command -v pimpleFoam >/dev/null 2>&1; then
    echo "pimpleFoam not found: installing OpenFOAM from Debian (apt-get install openfoam)" >&2
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
    RIPRAP="$root/target/release/riprap"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/riprap-of-cavity.XXXXXX")
trap 'rm -rf "$work"' EXIT
case_dir="$work/cavity"
cp -r "$here/cavity" "$case_dir"
sed -i "s/^N .*/N       $N;/" "$case_dir/system/blockMeshDict"
sed -i "s/^deltaT .*/deltaT          $DT;/" "$case_dir/system/controlDict"
nu=$(awk -v re="$RE" 'BEGIN { printf "%.10g", 1.0 / re }')
sed -i "s/^nu .*/nu              $nu;/" "$case_dir/constant/transportProperties"
(cd "$case_dir" && blockMesh > log.blockMesh 2>&1 && decomposePar -force > log.decomposePar 2>&1)

now() { date +%s.%N; }

# Wall time [s] of pimpleFoam for $2 steps on $1 cores.
openfoam_run() {
    local cores=$1 steps=$2 t0 t1
    local end
    end=$(awk -v n="$steps" -v dt="$DT" 'BEGIN { printf "%.10g", n * dt }')
    sed -i "s/^endTime .*/endTime         $end;/" "$case_dir/system/controlDict"
    t0=$(now)
    if [ "$cores" -eq 1 ]; then
        (cd "$case_dir" && pimpleFoam > "log.pimpleFoam.$cores.$steps" 2>&1)
    else
        (cd "$case_dir" && mpirun -np "$cores" pimpleFoam -parallel \
            > "log.pimpleFoam.$cores.$steps" 2>&1)
    fi
    t1=$(now)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }'
}

# Median of the numbers given as arguments.
median() {
    printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END {
        if (NR % 2) print v[(NR + 1) / 2]; else printf "%.6g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

echo "lid-driven cube ${N}^3, Re $RE, dt $DT s, $STEPS steps, $REPEATS repeats"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A rip of
for rep in $(seq 1 "$REPEATS"); do
    for cores in 1 2; do
        r=$("$RIPRAP" --threads "$cores" bench fluid --cavity "$N" --steps "$STEPS" \
            --re "$RE" --dt "$DT" | sed -n 's/^median step time: \([0-9.eE+-]*\) s$/\1/p')
        short=$(openfoam_run "$cores" "$SHORT")
        long=$(openfoam_run "$cores" $((SHORT + STEPS)))
        o=$(awk -v a="$short" -v b="$long" -v n="$STEPS" 'BEGIN { printf "%.6f", (b - a) / n }')
        rip[$cores]="${rip[$cores]:-} $r"
        of[$cores]="${of[$cores]:-} $o"
        echo "repeat $rep, $cores core(s): riprap $r s/step, pimpleFoam $o s/step"
    done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| cores | riprap median [s/step] | pimpleFoam median [s/step] | pimpleFoam / riprap |"
echo "|---:|---:|---:|---:|"
for cores in 1 2; do
    # shellcheck disable=SC2086
    mr=$(median ${rip[$cores]})
    # shellcheck disable=SC2086
    mo=$(median ${of[$cores]})
    ratio=$(awk -v a="$mr" -v b="$mo" 'BEGIN { printf "%.1f", b / a }')
    echo "| $cores | $mr | $mo | $ratio |"
done
