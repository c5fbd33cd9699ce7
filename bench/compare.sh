#!/usr/bin/env bash
# riprap against LIGGGHTS and LAMMPS on the shared benchmarks (bench/peers/README.md), with
# compiler flags alike on both sides: riprap built for this processor (target-cpu=native, as
# .cargo/config.toml asks) against the peers built for it too (bench/peers/build_native.sh,
# -O3 -march=native), and riprap built for any x86-64 against the peers' Debian binaries.
#
# Usage:  bash bench/compare.sh            (from anywhere; takes about 4 to 6 hours on 2 cores,
#                                           twice the peers' runs of the Debian binaries alone,
#                                           plus about an hour, once, for build_native.sh)
#
# Cases (CASES, default "b1-100k b2 b1-1m"):
#   b1-100k  B1 box-settle, N = 100,000, B1_STEPS steps (default 10000): LIGGGHTS, LAMMPS and
#            both riprap binaries on 1 and 2 ranks / threads
#   b2       B2 chute (LAMMPS bench/in.chute), B2_STEPS steps (default 1000): LAMMPS and both
#            riprap binaries on 1 and 2 ranks / threads
#   b1-1m    B1, N = 1,000,000: riprap (native) on 2 threads, M1_STEPS steps (default 2000, the
#            peers' "b1probe" length; 10000 for the whole run), time and peak memory
# The codes (the CODE in the logs' names):
#   riprap            cargo build --release: target-cpu=native (.cargo/config.toml)
#   riprap-portable   RUSTFLAGS="" cargo build --release into target/portable: generic x86-64
#                     (RUSTFLAGS="" overrides the config's rustflags); the ymm/zmm instruction
#                     counts of both binaries go to RUN_DIR/machine.txt
#   liggghts, lammps  the Debian binaries (liggghts, lmp)
#   liggghts-native, lammps-native   bench/peers/build_native.sh's builds of the same Debian
#                     sources with -O3 -march=native (built first when missing: about an hour)
# Each run of a code is followed by the runs of the others before it is repeated (REPEATS
# times, default 3), so that slow phases of a shared machine hit every code alike. The table
# printed at the end (bench/compare_table.py) gives, per case and rank count, the median loop
# time of each code and the speed-ups: native riprap over the native peers, portable riprap
# over the Debian peers, native riprap over portable riprap, native peers over Debian peers
# (each: median time of the one / median time of the other); loop time only, as the peers
# report it.
#
# Env: BENCH_INPUTS  folder with gen_b1.py, in.b1.liggghts, in.b1.lammps, in.chute and
#                    data.chute.gz (default: bench/peers)
#      RUN_DIR       logs (default: runs/compare in the repository; git-ignored)
#      REPEATS, CASES, B1_N, B1_STEPS, B2_STEPS, M1_STEPS, NP_LIST (default "1 2"),
#      B1_PEERS (default "liggghts lammps"; B1's goal is against LIGGGHTS, "liggghts" alone
#      halves the peers' run time)
#      PEER_BUILDS   which builds of the peers run (default "debian native")
#      RIPRAP_BUILDS which riprap binaries run (default "native portable")
#      PEERS_NATIVE  build_native.sh's cache (default: runs/peers-native in the repository)
#      BASELINE      another riprap binary, run after this tree's native one (its own table)
# The Debian peers are installed when missing (apt-get install -y liggghts lammps openmpi-bin,
# through sudo when not root). The builds (riprap's, and build_native.sh's) run under nice -n 19.
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
PEER_BUILDS=${PEER_BUILDS:-"debian native"}
RIPRAP_BUILDS=${RIPRAP_BUILDS:-"native portable"}
PEERS_NATIVE=${PEERS_NATIVE:-$ROOT/runs/peers-native}
mkdir -p "$PEERS_NATIVE" && PEERS_NATIVE=$(cd "$PEERS_NATIVE" && pwd)
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)

for f in gen_b1.py in.b1.liggghts in.b1.lammps in.chute data.chute.gz; do
  [ -s "$INPUTS/$f" ] || { echo "missing $INPUTS/$f (set BENCH_INPUTS)"; exit 1; }
done

has() {  # has WORD LIST...: WORD is one of the words of LIST
  local w=$1; shift
  case " $* " in *" $w "*) return 0 ;; esac
  return 1
}
for b in $PEER_BUILDS; do has "$b" debian native || { echo "PEER_BUILDS: unknown $b"; exit 1; }; done
for b in $RIPRAP_BUILDS; do has "$b" native portable || { echo "RIPRAP_BUILDS: unknown $b"; exit 1; }; done

need_peers() {
  local missing=()
  if has debian $PEER_BUILDS; then
    command -v liggghts > /dev/null || missing+=(liggghts)
    command -v lmp > /dev/null || missing+=(lammps)
  fi
  command -v mpirun > /dev/null || missing+=(openmpi-bin)
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing ${missing[*]} from Debian"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q "${missing[@]}"
}

need_peers
if has native $PEER_BUILDS; then
  # Builds once (about 40 min on 2 cores), then only checks the binaries.
  CACHE=$PEERS_NATIVE bash "$ROOT/bench/peers/build_native.sh"
fi
# The binary of each peer code.
declare -A PEER_BIN=([liggghts]=liggghts [lammps]=lmp
  [liggghts-native]=$PEERS_NATIVE/bin/liggghts-native [lammps-native]=$PEERS_NATIVE/bin/lmp-native)
peer_codes() {  # peer_codes FAMILY: the codes of that peer that PEER_BUILDS asks for
  has debian $PEER_BUILDS && echo "$1"
  has native $PEER_BUILDS && echo "$1-native"
  return 0
}

mkdir -p "$RUN"
# Copies, so that rebuilding the tree during the (long) comparison does not change what runs.
if has native $RIPRAP_BUILDS; then
  echo "== building riprap (native: .cargo/config.toml's target-cpu=native)"
  ( cd "$ROOT" && nice -n 19 cargo build --release -q )
  cp "${CARGO_TARGET_DIR:-$ROOT/target}/release/riprap" "$RUN/riprap"
fi
if has portable $RIPRAP_BUILDS; then
  echo "== building riprap (portable: RUSTFLAGS=\"\", generic x86-64, in target/portable)"
  ( cd "$ROOT" && RUSTFLAGS="" CARGO_TARGET_DIR="$ROOT/target/portable" \
      nice -n 19 cargo build --release -q )
  cp "$ROOT/target/portable/release/riprap" "$RUN/riprap-portable"
fi
declare -A RIPRAP_BIN=([native]=$RUN/riprap [portable]=$RUN/riprap-portable)
declare -A RIPRAP_CODE=([native]=riprap [portable]=riprap-portable)
if [ -n "${BASELINE:-}" ]; then
  cp "$BASELINE" "$RUN/riprap-base"
  BASE=$RUN/riprap-base
fi
# Instructions on ymm (AVX/AVX2) and zmm (AVX-512) registers in each riprap binary.
declare -A YMM=() ZMM=()
for b in $RIPRAP_BUILDS; do
  read -r YMM[$b] ZMM[$b] < <(objdump -d --no-show-raw-insn "${RIPRAP_BIN[$b]}" 2> /dev/null \
    | awk '/ymm/ {y++} /zmm/ {z++} END {print y + 0, z + 0}' || echo "? ?")
done
{ echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"; echo "commit: $(git -C "$ROOT" rev-parse --short HEAD)";
  lscpu | grep -E "Model name|^CPU\(s\)|L2|L3"; free -g | head -2
  for b in $RIPRAP_BUILDS; do
    echo "riprap $b (${RIPRAP_CODE[$b]}): ${YMM[$b]} ymm, ${ZMM[$b]} zmm instructions (objdump -d)"
  done
  if has native $PEER_BUILDS && [ -s "$PEERS_NATIVE/build-info.txt" ]; then
    cat "$PEERS_NATIVE/build-info.txt"
  fi
  has debian $PEER_BUILDS && dpkg-query -W -f='${Package} ${Version} (Debian binary)\n' \
    liggghts lammps 2> /dev/null
  true
} > "$RUN/machine.txt"
cat "$RUN/machine.txt"
# The portable binary should use AVX (ymm) only where riprap chooses it at run time.
if has native $RIPRAP_BUILDS && has portable $RIPRAP_BUILDS \
    && [ "${YMM[portable]}" -gt $((YMM[native] / 4)) ] 2> /dev/null; then
  echo "!! riprap-portable has ${YMM[portable]} ymm instructions against native's" \
    "${YMM[native]}: is RUSTFLAGS=\"\" overriding target-cpu=native?"
fi

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

b1_peer() {  # b1_peer FAMILY N STEPS NP REP: the builds of one peer asked for
  local fam=$1 n=$2 steps=$3 np=$4 rep=$5 code
  has "$fam" $B1_PEERS || return 0
  for code in $(peer_codes "$fam"); do
    run "b1.$code.$n.np$np.r$rep" "${MPIRUN[@]}" -np "$np" "${PEER_BIN[$code]}" \
      -var data "b1_$n.data" -var nsteps "$steps" -in "$INPUTS/in.b1.$fam" -log none || true
  done
}

b1_riprap() {  # b1_riprap BUILD N STEPS NP REP
  local b=$1 n=$2 steps=$3 np=$4 rep=$5
  has "$b" $RIPRAP_BUILDS || return 0
  run "b1.${RIPRAP_CODE[$b]}.$n.np$np.r$rep" "${RIPRAP_BIN[$b]}" --threads "$np" bench b1 \
    --n "$n" --steps "$steps"
}

b1_round() {  # b1_round N STEPS REP
  local n=$1 steps=$2 rep=$3
  b1_data "$n"
  for np in $NP_LIST; do
    b1_peer liggghts "$n" "$steps" "$np" "$rep"
    b1_riprap native "$n" "$steps" "$np" "$rep"
    [ -z "${BASE:-}" ] || run "b1.base.$n.np$np.r$rep" "$BASE" --threads "$np" bench b1 \
      --n "$n" --steps "$steps"
    b1_peer lammps "$n" "$steps" "$np" "$rep"
    b1_riprap portable "$n" "$steps" "$np" "$rep"
  done
}

b2_round() {  # b2_round REP
  local rep=$1 i
  local codes=($(peer_codes lammps)) builds=($RIPRAP_BUILDS)
  [ -s "$RUN/data.chute" ] || gzip -dc "$INPUTS/data.chute.gz" > "$RUN/data.chute"
  for np in $NP_LIST; do
    # LAMMPS (Debian), riprap (native), LAMMPS (native), riprap (portable), as asked for.
    for ((i = 0; i < 2; i++)); do
      if [ -n "${codes[i]:-}" ]; then
        run "b2.${codes[i]}.32000.np$np.r$rep" "${MPIRUN[@]}" -np "$np" "${PEER_BIN[${codes[i]}]}" \
          -var nsteps "$B2_STEPS" -in "$INPUTS/in.chute" -log none || true
      fi
      [ -z "${builds[i]:-}" ] || b2_riprap "${builds[i]}" "$np" "$rep"
      if [ "$i" -eq 0 ] && [ -n "${BASE:-}" ]; then
        run "b2.base.32000.np$np.r$rep" "$BASE" --threads "$np" bench b2 --data data.chute \
          --steps "$B2_STEPS"
      fi
    done
  done
}

b2_riprap() {  # b2_riprap BUILD NP REP
  local b=$1 np=$2 rep=$3
  has "$b" $RIPRAP_BUILDS || return 0
  run "b2.${RIPRAP_CODE[$b]}.32000.np$np.r$rep" "${RIPRAP_BIN[$b]}" --threads "$np" bench b2 \
    --data data.chute --steps "$B2_STEPS"
}

for rep in $(seq 1 "$REPEATS"); do
  for c in $CASES; do
    case "$c" in
      b1-100k) b1_round "$B1_N" "$B1_STEPS" "$rep" ;;
      b2) b2_round "$rep" ;;
      b1-1m)
        if [ "$rep" -eq 1 ]; then
          b=$(has native $RIPRAP_BUILDS && echo native || echo portable)
          run "b1m.${RIPRAP_CODE[$b]}.1000000.np2.r1" "${RIPRAP_BIN[$b]}" --threads 2 bench b1 \
            --n 1000000 --steps "$M1_STEPS"
        fi ;;
      *) echo "unknown case $c"; exit 1 ;;
    esac
  done
done

python3 "$ROOT/bench/compare_table.py" "$RUN" | tee "$RUN/table.md"
