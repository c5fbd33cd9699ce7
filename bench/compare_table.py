#!/usr/bin/env python3
"""Median table of the runs that bench/compare.sh leaves in RUN_DIR.

Usage: python3 bench/compare_table.py RUN_DIR

Log names are BENCH.CODE.N.npP.rR.out (with GNU time's BENCH.CODE.N.npP.rR.time). Loop times:
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
    print("| case | ranks / threads | steps | LIGGGHTS loop s | LAMMPS loop s | riprap loop s "
          "| riprap particle-steps/s | speed-up vs LIGGGHTS | speed-up vs LAMMPS "
          "| peak RSS MB (L / M / r) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for (bench, n, np_), codes in sorted(runs.items()):
        med = {c: statistics.median(r[0] for r in v) for c, v in codes.items()}
        cnt = {c: len(v) for c, v in codes.items()}
        rss = {c: max((r[3] or 0) for r in v) for c, v in codes.items()}
        steps = next(iter(codes.values()))[0][1]
        cell = lambda c: ("%.2f (%d)" % (med[c], cnt[c])) if c in med else ""
        rate = ("%.3g" % (n * steps / med["riprap"])) if "riprap" in med else ""
        ratio = lambda c: ("%.2f" % (med[c] / med["riprap"])) if c in med and "riprap" in med else ""
        mem = " / ".join("%.0f" % rss[c] if c in rss else "-" for c in ("liggghts", "lammps", "riprap"))
        label = {"b1": "B1 N=%d" % n, "b2": "B2 chute", "b1m": "B1 N=%d" % n}.get(bench, bench)
        print("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, np_, steps, cell("liggghts"), cell("lammps"), cell("riprap"), rate,
            ratio("liggghts"), ratio("lammps"), mem))
    print()
    print("Loop times are medians over the runs (count in parentheses); speed-up = peer median / "
          "riprap median. Peak RSS is per process (per rank for the MPI peers).")
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
            label = {"b1": "B1 N=%d" % n, "b2": "B2 chute", "b1m": "B1 N=%d" % n}.get(bench, bench)
            print("| %s | %d | %s | %.2f | %.2f | %.3f | %s |" % (
                label, np_, codes["riprap"][0][1], statistics.median(b), statistics.median(r),
                statistics.median(b) / statistics.median(r),
                "; ".join("%.2f, %.2f" % p for p in zip(b, r))))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "runs/compare")
