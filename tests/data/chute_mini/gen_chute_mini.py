#!/usr/bin/env python3
"""Writes data.chute_mini: a small version of LAMMPS's chute benchmark (B2) for tests.

LJ units, sphere diameter 1, density 1. Box [0, 16) x [0, 6) periodic, z in [0, 12].
A rough base of 96 frozen spheres (type 2) on a jittered 16 x 6 grid near z = 0.5, and 768
flowing spheres (type 1) on a 16 x 6 x 8 simple cubic lattice of spacing 1 above it (each
sphere just touching its neighbours) with deterministic pseudo-random velocities (mean 1 down
the slope along x, spread ±0.5 in every component) and spins (±1), so that the lattice
collapses at once into a dense flow on the base: contacts form, slide and break throughout.

Usage: python3 gen_chute_mini.py data.chute_mini
"""
import sys


def lcg(seed):
    state = seed
    while True:
        state = (6364136223846793005 * state + 1442695040888963407) % 2**64
        yield (state >> 11) / float(2**53)


def main(path):
    rnd = lcg(12345)
    u = lambda: next(rnd) - 0.5
    atoms, vels = [], []
    aid = 0
    for j in range(6):
        for i in range(16):
            aid += 1
            x, y, z = i + 0.5 + 0.3 * u(), j + 0.5 + 0.3 * u(), 0.5 + 0.2 * u()
            atoms.append((aid, 2, x, y, z))
            vels.append((aid, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))
    for k in range(8):
        for j in range(6):
            for i in range(16):
                aid += 1
                x, y, z = i + 0.5, j + 0.5, 1.65 + 1.0 * k
                atoms.append((aid, 1, x, y, z))
                vels.append((aid, 1.0 + u(), u(), u(), 2.0 * u(), 2.0 * u(), 2.0 * u()))
    with open(path, "w") as f:
        f.write("riprap test: mini chute (gen_chute_mini.py)\n\n")
        f.write("%d atoms\n\n2 atom types\n\n" % len(atoms))
        f.write("0 16 xlo xhi\n0 6 ylo yhi\n0 12 zlo zhi\n\nAtoms\n\n")
        for a in atoms:
            f.write("%d %d 1 1 %.17g %.17g %.17g 0 0 0\n" % a)
        f.write("\nVelocities\n\n")
        for v in vels:
            f.write("%d %.17g %.17g %.17g %.17g %.17g %.17g\n" % v)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "data.chute_mini")
