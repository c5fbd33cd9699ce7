#!/usr/bin/env bash
# riprap against LIGGGHTS and LAMMPS on the shared benchmarks (bench/peers/README.md).
#
# Usage:  bash bench/compare.sh            (from anywhere; takes about 2 to 3 hours on 2 cores)
#
# Cases (CASES, default "b1-100k b2 b1-1m"):
#   b1-100k  B1 box-settle, N = 100,000, B1_STEPS steps (default 10000): LIGGGHTS, LAMMPS and
#            riprap on 1 and 2 ranks / threads
#   b2       B2 chute (LAMMPS bench/in.chute), B2_STEPS steps (default 1000): LAMMPS and riprap
#            on 1 and 2 ranks / threads
#   b1-1m    B1, N = 1,000,000: riprap on 2 threads, M1_STEPS steps (default 2000, the peers'
#            "b1probe" length; 10000 for the whole run), time and peak memory
# Each run of a code is followed by the runs of the others before it is repeated (REPEATS
# times, default 3), so that slow phases of a shared machine hit every code alike. The table
# printed at the end gives, per case, the median loop time of each code and riprap's speed-up
# (median peer time / median riprap time); loop time only, as the peers report it.
#
# Env: BENCH_INPUTS  folder with gen_b1.py, in.b1.liggghts, in.b1.lammps, in.chute and
#                    data.chute.gz (default: bench/peers)
#      RUN_DIR       logs (default: runs/compare in the repository; git-ignored)
#      REPEATS, CASES, B1_N, B1_STEPS, B2_STEPS, M1_STEPS, NP_LIST (default "1 2"),
#      B1_PEERS (default "liggghts lammps"; B1's goal is against LIGGGHTS, "liggghts" alone
#      halves the run time)
# The peers are installed from Debian when missing (apt-get install -y liggghts lammps,
# through sudo when not root); riprap is built with cargo build --release.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
INPUTS=${BENCH_INPUTS:-$ROOT/bench/peers}
RUN=${RUN_DIR:-$ROOT/runs/compare}
# Absolute, as the runs start inside it (a relative RUN_DIR used to lose the riprap binary).
mkdir -p "$RUN" && RUN=$(cd "$RUN" && pwd)
REPEATS=${REPEATS:-3}
CASES=${CASES:-"b1-100k b2 b1-1m"}
B1_N=${B1_N:-100000}
B1_STEPS=${B1_STEPS:-10000}
B2_STEPS=${B2_STEPS:-1000}
M1_STEPS=${M1_STEPS:-2000}
NP_LIST=${NP_LIST:-"1 2"}
B1_PEERS=${B1_PEERS:-"liggghts lammps"}
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)

for f in gen_b1.py in.b1.liggghts in.b1.lammps in.chute data.chute.gz; do
  [ -s "$INPUTS/$f" ] || { echo "missing $INPUTS/$f (set BENCH_INPUTS)"; exit 1; }
done

need_peers() {
  local missing=()
  command -v liggghts > /dev/null || missing+=(liggghts)
  command -v lmp > /dev/null || missing+=(lammps)
  command -v mpirun > /dev/null || missing+=(openmpi-bin)
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing ${missing[*]} from Debian"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q "${missing[@]}"
}

need_peers
echo "== building riprap"
( cd "$ROOT" && cargo build --release -q )
mkdir -p "$RUN"
# A copy, so that rebuilding the tree during the (long) comparison does not change what runs.
cp "$ROOT/target/release/riprap" "$RUN/riprap"
RIPRAP=$RUN/riprap
if [ -n "${BASELINE:-}" ]; then
  cp "$BASELINE" "$RUN/riprap-base"
  BASE=$RUN/riprap-base
fi
{ echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"; echo "commit: $(git -C "$ROOT" rev-parse --short HEAD)";
  lscpu | grep -E "Model name|^CPU\(s\)|L2|L3"; free -g | head -2; } > "$RUN/machine.txt"

# run NAME cmd...: stdout+stderr -> NAME.out, GNU time -> NAME.time (peak RSS), in RUN.
run() {
  local name=$1; shift
  echo "== $name: $*"
  ( cd "$RUN" && command time -v -o "$name.time" "$@" > "$name.out" 2>&1 ) \
    || { echo "!! $name failed, see $RUN/$name.out"; return 1; }
  grep -hE "Loop time|^loop time" "$RUN/$name.out" | tail -1
}

b1_data() {
  [ -s "$RUN/b1_$1.data" ] || python3 "$INPUTS/gen_b1.py" "$1" "$RUN/b1_$1.data"
}

b1_round() {  # b1_round N STEPS REP
  local n=$1 steps=$2 rep=$3
  b1_data "$n"
  for np in $NP_LIST; do
    case " $B1_PEERS " in *" liggghts "*)
      run "b1.liggghts.$n.np$np.r$rep" "${MPIRUN[@]}" -np "$np" liggghts -var data "b1_$n.data" \
        -var nsteps "$steps" -in "$INPUTS/in.b1.liggghts" -log none ;;
    esac
    run "b1.riprap.$n.np$np.r$rep" "$RIPRAP" --threads "$np" bench b1 --n "$n" --steps "$steps"
    [ -z "${BASE:-}" ] || run "b1.base.$n.np$np.r$rep" "$BASE" --threads "$np" bench b1 \
      --n "$n" --steps "$steps"
    case " $B1_PEERS " in *" lammps "*)
      run "b1.lammps.$n.np$np.r$rep" "${MPIRUN[@]}" -np "$np" lmp -var data "b1_$n.data" \
        -var nsteps "$steps" -in "$INPUTS/in.b1.lammps" -log none ;;
    esac
  done
}

b2_round() {  # b2_round REP
  local rep=$1
  [ -s "$RUN/data.chute" ] || gzip -dc "$INPUTS/data.chute.gz" > "$RUN/data.chute"
  for np in $NP_LIST; do
    run "b2.lammps.32000.np$np.r$rep" "${MPIRUN[@]}" -np "$np" lmp -var nsteps "$B2_STEPS" \
      -in "$INPUTS/in.chute" -log none
    run "b2.riprap.32000.np$np.r$rep" "$RIPRAP" --threads "$np" bench b2 --data data.chute \
      --steps "$B2_STEPS"
    [ -z "${BASE:-}" ] || run "b2.base.32000.np$np.r$rep" "$BASE" --threads "$np" bench b2 \
      --data data.chute --steps "$B2_STEPS"
  done
}

for rep in $(seq 1 "$REPEATS"); do
  for c in $CASES; do
    case "$c" in
      b1-100k) b1_round "$B1_N" "$B1_STEPS" "$rep" ;;
      b2) b2_round "$rep" ;;
      b1-1m)
        if [ "$rep" -eq 1 ]; then
          run "b1m.riprap.1000000.np2.r1" "$RIPRAP" --threads 2 bench b1 --n 1000000 \
            --steps "$M1_STEPS"
        fi ;;
      *) echo "unknown case $c"; exit 1 ;;
    esac
  done
done

python3 "$ROOT/bench/compare_table.py" "$RUN" | tee "$RUN/table.md"
