#!/usr/bin/env python3
"""The surge front of the dam break and its error against Martin & Moyce (1952).

Used by compare_dam_break.sh for both codes, so that both are measured the same way:

  dam_break_front.py openfoam CASE_DIR OUT.csv   interFoam's front, from the function object
                                                 `front` (alpha.water in the bottom row of
                                                 cells every 0.05 in T), into OUT.csv (T,Z)
  dam_break_front.py error FRONT.csv             the errors of a front (T,Z) against the table

The front is riprap's (src/validation/dam_break/mod.rs, front_position): along the bottom row of
cells, the farthest point where alpha falls through 1/2, linear between cell centres, divided by
a. Z = x/a, T = t sqrt(2g/a), a = 0.05715 m, g = 9.81 m/s2. interFoam samples the cells'
values at their centres (interpolationScheme cell).

The errors (the same arithmetic as the validation case's verdict):
- lead: the mean over Z = 2, 2.5, 3 of T_measured(Z) - T_run(Z), each T(Z) by linear
  interpolation on the rising part of the record (the validation case's criterion: 0 to 0.4);
- mean |dT|: the mean of |T_measured(Z) - T_run(Z)| over the same Z (the benchmark's error);
- front speed: the least-squares slope dZ/dT over T = 1.4 to 3.0, and the measured one's.
Only the Python standard library is used.
"""
import math
import os
import sys

A = 0.05715
G = 9.81
SCALE = math.sqrt(2.0 * G / A)
HERE = os.path.dirname(os.path.abspath(__file__))
TABLE = os.path.join(HERE, "..", "..", "src", "validation", "dam_break",
                     "martin_moyce_1952_front.csv")
SURGE = (1.4, 3.0)
LEVELS = (2.0, 2.5, 3.0)


def read_table(path):
    """(T, Z) rows of a CSV whose data lines start with a digit (comments and header skipped)."""
    rows = []
    with open(path) as f:
        for line in f:
            if line[:1].isdigit():
                t, z = line.split(",")[:2]
                rows.append((float(t), float(z)))
    return rows


def openfoam_front(case):
    """(T, Z) of interFoam's run in `case` from its samples of the bottom row of cells,
    postProcessing/front/TIME/bottomRow_alpha.water.xy (columns x [m], alpha), TIME > 0."""
    base = os.path.join(case, "postProcessing", "front")
    samples = []
    for name in os.listdir(base):
        path = os.path.join(base, name, "bottomRow_alpha.water.xy")
        if float(name) > 0 and os.path.exists(path):
            samples.append((float(name), path))
    front = []
    for t, path in sorted(samples):
        with open(path) as f:
            row = [tuple(float(v) for v in line.split()) for line in f if line.strip()]
        row.sort()
        dx = (row[-1][0] - row[0][0]) / (len(row) - 1)
        x = 0.0
        for k, (xc, c) in enumerate(row):
            if c >= 0.5:
                nxt = row[k + 1][1] if k + 1 < len(row) else c
                frac = min((c - 0.5) / (c - nxt), 1.0) if c > nxt else 0.0
                x = max(x, xc + frac * dx)
        front.append((t * SCALE, x / A))
    return front


def interpolate(rows, x):
    for (x0, y0), (x1, y1) in zip(rows, rows[1:]):
        if x0 <= x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return None


def time_at(rows, z):
    """T at which a (T, Z) record first reaches Z = z (its rising part, as the Rust)."""
    rising = []
    for t, zz in rows:
        if not rising or zz > rising[-1][0]:
            rising.append((zz, t))
    return interpolate(rising, z)


def slope(rows, lo, hi):
    pts = [(t, z) for t, z in rows if lo <= t <= hi + 1e-9]
    mt = sum(p[0] for p in pts) / len(pts)
    mz = sum(p[1] for p in pts) / len(pts)
    stz = sum((t - mt) * (z - mz) for t, z in pts)
    stt = sum((t - mt) ** 2 for t, _ in pts)
    return stz / stt


def errors(front):
    measured = read_table(TABLE)
    leads = []
    for z in LEVELS:
        tm, tr = time_at(measured, z), time_at(front, z)
        if tm is not None and tr is not None:
            leads.append(tm - tr)
    lead = sum(leads) / max(len(leads), 1)
    mean_abs = sum(abs(d) for d in leads) / max(len(leads), 1)
    return {
        "leads": leads,
        "lead": lead,
        "mean_abs": mean_abs,
        "speed": slope(front, *SURGE),
        "speed_measured": slope(measured, *SURGE),
        "z_end": front[-1][1] if front else float("nan"),
    }


def print_errors(front):
    e = errors(front)
    print("lead at Z = 2, 2.5, 3: " + " ".join(f"{d:.4f}" for d in e["leads"]))
    print(f"lead: {e['lead']:.4f}")
    print(f"mean |dT|: {e['mean_abs']:.4f}")
    print(f"front speed: {e['speed']:.4f} (measured {e['speed_measured']:.4f})")
    print(f"Z(T_end): {e['z_end']:.4f}")


def main(argv):
    if len(argv) == 4 and argv[1] == "openfoam":
        front = openfoam_front(argv[2])
        with open(argv[3], "w") as f:
            f.write("T,Z\n")
            for t, z in front:
                f.write(f"{t:.6f},{z:.6f}\n")
        print_errors(front)
    elif len(argv) == 3 and argv[1] == "error":
        print_errors(read_table(argv[2]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
