#!/usr/bin/env python3
"""Median table of the runs that bench/compare.sh leaves in RUN_DIR.

Usage: python3 bench/compare_table.py RUN_DIR

Log names are BENCH.CODE.N.npP.rR.out, with GNU time's BENCH.CODE.N.npP.rR.time (CODE: liggghts,
lammps, their -native builds, riprap, riprap-portable, base). Loop times:
LAMMPS/LIGGGHTS "Loop time of X on P procs for S steps with N atoms"; riprap "loop time: X s".
Peak RSS: GNU time's "Maximum resident set size" (per process: per rank for MPI runs).
"""
import glob
import os
import re
import statistics
import sys

PEER = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
OURS = re.compile(r"^loop time: ([0-9.eE+-]+) s")
STEPS = re.compile(r"(\d+) steps, (\d+) thread")
NAMES = {"liggghts": "LIGGGHTS", "lammps": "LAMMPS", "riprap": "riprap"}


def rss_mb(path):
    try:
        for line in open(path):
            if "Maximum resident set size" in line:
                return int(line.split(":")[-1]) / 1024.0
    except OSError:
        pass
    return None


def parse(path):
    text = open(path, errors="replace").read()
    m = PEER.search(text)
    if m:
        return float(m.group(1)), int(m.group(3)), int(m.group(4))
    loop = steps = n = None
    for line in text.splitlines():
        mo = OURS.match(line)
        if mo:
            loop = float(mo.group(1))
        ms = STEPS.search(line)
        if ms:
            steps = int(ms.group(1))
        if line.startswith("spheres: "):
            n = int(line.split()[1])
        mb = re.match(r"B2 chute: (\d+) atoms", line)
        if mb:
            n = int(mb.group(1))
    if loop is None:
        return None
    return loop, steps, n


def main(run):
    runs = {}
    for out in sorted(glob.glob(os.path.join(run, "*.out"))):
        name = os.path.basename(out)[:-4]
        parts = name.split(".")
        if len(parts) != 5:
            continue
        bench, code, n, np_, _rep = parts
        got = parse(out)
        if not got:
            continue
        loop, steps, atoms = got
        rss = rss_mb(os.path.join(run, name + ".time"))
        runs.setdefault((bench, int(n), int(np_[2:])), {}).setdefault(code, []).append(
            (loop, steps, atoms, rss))
    # The codes: the peers' Debian binaries and their -O3 -march=native builds
    # (bench/peers/build_native.sh); riprap built with target-cpu=native and for any x86-64.
    codes_all = ["liggghts", "liggghts-native", "lammps", "lammps-native", "riprap",
                 "riprap-portable"]
    heads = {"liggghts": "LIGGGHTS Debian", "liggghts-native": "LIGGGHTS native",
             "lammps": "LAMMPS Debian", "lammps-native": "LAMMPS native",
             "riprap": "riprap native", "riprap-portable": "riprap portable"}
    short = {"liggghts": "L", "liggghts-native": "Ln", "lammps": "M", "lammps-native": "Mn",
             "riprap": "r", "riprap-portable": "rp"}
    # Speed-ups: median loop time of the second code / that of the first (> 1: the first is
    # faster).
    ratios = [("riprap", "liggghts-native", "riprap native vs LIGGGHTS native"),
              ("riprap", "lammps-native", "riprap native vs LAMMPS native"),
              ("riprap-portable", "liggghts", "riprap portable vs LIGGGHTS Debian"),
              ("riprap-portable", "lammps", "riprap portable vs LAMMPS Debian"),
              ("riprap", "riprap-portable", "riprap native vs portable"),
              ("liggghts-native", "liggghts", "LIGGGHTS native vs Debian"),
              ("lammps-native", "lammps", "LAMMPS native vs Debian"),
              # The former table's two speed-ups (riprap native against the Debian binaries),
              # kept to compare with earlier tables.
              ("riprap", "liggghts", "riprap native vs LIGGGHTS Debian (former)"),
              ("riprap", "lammps", "riprap native vs LAMMPS Debian (former)")]
    label_of = lambda bench, n: {"b1": "B1 N=%d" % n, "b2": "B2 chute",
                                 "b1m": "B1 N=%d" % n}.get(bench, bench)
    rows = []
    for (bench, n, np_), codes in sorted(runs.items()):
        med = {c: statistics.median(r[0] for r in v) for c, v in codes.items()}
        cnt = {c: len(v) for c, v in codes.items()}
        rss = {c: max((r[3] or 0) for r in v) for c, v in codes.items()}
        steps = next(iter(codes.values()))[0][1]
        rows.append((label_of(bench, n), np_, steps, n, med, cnt, rss))

    print("Loop time, s (median of the runs; their count in parentheses):")
    print()
    print("| case | ranks / threads | steps | " + " | ".join(heads[c] for c in codes_all)
          + " | riprap particle-steps/s (native / portable) | peak RSS MB ("
          + " / ".join(short[c] for c in codes_all) + ") |")
    print("|---|---:|---:|" + "---:|" * len(codes_all) + "---:|---|")
    for label, np_, steps, n, med, cnt, rss in rows:
        cell = lambda c: ("%.2f (%d)" % (med[c], cnt[c])) if c in med else ""
        rate = " / ".join(("%.3g" % (n * steps / med[c])) if c in med else "-"
                          for c in ("riprap", "riprap-portable"))
        mem = " / ".join("%.0f" % rss[c] if c in rss else "-" for c in codes_all)
        print("| %s | %d | %s | %s | %s | %s |" % (
            label, np_, steps, " | ".join(cell(c) for c in codes_all), rate, mem))
    print()
    print("Speed-ups (median loop time of the second code / median of the first; > 1: the first "
          "is faster):")
    print()
    print("| case | ranks / threads | " + " | ".join(r[2] for r in ratios) + " |")
    print("|---|---:|" + "---:|" * len(ratios))
    for label, np_, steps, n, med, cnt, rss in rows:
        ratio = lambda a, b: ("%.2f" % (med[b] / med[a])) if a in med and b in med else ""
        print("| %s | %d | %s |" % (label, np_, " | ".join(ratio(a, b) for a, b, _ in ratios)))
    print()
    print("native: riprap with target-cpu=native (.cargo/config.toml), the peers built from "
          "their Debian sources with -O3 -march=native (bench/peers/build_native.sh); portable: "
          "riprap for any x86-64 (RUSTFLAGS=\"\"); Debian: the distribution's generic x86-64 "
          "binaries. Peak RSS is per process (per rank for the MPI peers).")
    base = [(k, c) for k, c in sorted(runs.items()) if "base" in c and "riprap" in c]
    if base:
        # BASELINE runs: the same riprap case with another binary, right after this tree's.
        print()
        print("| case | threads | steps | baseline loop s | riprap loop s | speed-up over baseline "
              "| runs (baseline, riprap) each |")
        print("|---|---:|---:|---:|---:|---:|---|")
        for (bench, n, np_), codes in base:
            b = [r[0] for r in codes["base"]]
            r = [x[0] for x in codes["riprap"]]
            label = label_of(bench, n)
            print("| %s | %d | %s | %.2f | %.2f | %.3f | %s |" % (
                label, np_, codes["riprap"][0][1], statistics.median(b), statistics.median(r),
                statistics.median(b) / statistics.median(r),
                "; ".join("%.2f, %.2f" % p for p in zip(b, r))))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "runs/compare")
