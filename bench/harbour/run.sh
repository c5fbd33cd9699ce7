#!/usr/bin/env bash
# The harbour benchmark of issue 31 (README.md beside this file): REPEATS alternating runs of
# the flow with its debris and of the flow alone, over END simulated seconds, on THREADS
# threads; prints each run's report and the medians. Usage:
#   END=20 REPEATS=3 THREADS=2 bash bench/harbour/run.sh [path/to/riprap]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-riprap}
END=${END:-20}
REPEATS=${REPEATS:-3}
THREADS=${THREADS:-2}
tmp=$(mktemp -d)
for r in $(seq 1 "$REPEATS"); do
    for mode in debris flow; do
        extra=""
        [ "$mode" = flow ] && extra="--no-debris"
        echo "== run $r, $mode"
        "$bin" --threads "$THREADS" bench harbour --scenario "$here/harbour.toml" \
            --end-time "$END" $extra 2>/dev/null | tee -a "$tmp/$mode.txt"
    done
done
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
for mode in debris flow; do
    f="$tmp/$mode.txt"
    wall=$(grep -o '^wall [0-9.]*' "$f" | awk '{print $2}' | median)
    flow=$(grep -o 'flow [0-9.]* s (' "$f" | awk '{print $2}' | median)
    deb=$(grep -o 'debris [0-9.]* s (' "$f" | awk '{print $2}' | median)
    cups=$(grep -o '^flow: [0-9.e+]*' "$f" | awk '{print $2}' | median)
    hour=$(grep -o 'simulated: [0-9.]* s wall' "$f" | awk '{print $2}' | median)
    echo "median of $REPEATS ($mode): wall $wall s, flow $flow s, debris $deb s, \
$cups cell updates/s, one hour ≈ $hour s"
done
rm -rf "$tmp"
