"""A parameter sweep: the porosity of a bed of glass beads against their restitution.

The same 1000 beads (3 mm) are rained into a box periodic across, once per restitution
coefficient e, and left to settle; the porosity n of the settled bed is measured in a slab
two diameters away from the floor and from the surface (the floor orders the first layers).
The scenario is a Python dict: each run changes one value. Run from the repository root:

    python python/examples/sweep_restitution_porosity.py [--quick]

Prints one line per e (a few seconds each; --quick settles for less time and takes only three
values) and writes sweep_restitution_porosity.csv.
"""

import copy
import csv
import sys
import time

import numpy as np

import riprap

D = 0.003  # bead diameter [m]
L = 0.024  # box width across (periodic) [m]

BASE = {
    "run": {"name": "bed", "end_time": 0.5},
    "domain": {"min": [0.0, 0.0, 0.0], "max": [L, L, 0.26], "periodic": [True, True, False]},
    "contact": {"model": "hertz", "damping": "restitution"},
    "material": [{
        "name": "glass", "density": 2500.0, "young_modulus": 5.0e7, "poisson_ratio": 0.25,
        "friction_coefficient": 0.4, "restitution_coefficient": 0.5,
    }],
    "wall": [{"name": "floor", "kind": "plane", "point": [0.0, 0.0, 0.0],
              "normal": [0.0, 0.0, 1.0], "material": "glass"}],
    "spheres": [{"kind": "random", "material": "glass", "min": [0.0, 0.0, 0.004],
                 "max": [L, L, 0.25], "seed": 3, "sizes": [{"diameter": D, "count": 1000}]}],
}


def slab_porosity(z, r, lo, hi, area):
    """1 - (volume of the spheres between the planes z = lo and z = hi) / (slab volume)."""
    a = np.clip(lo - z, -r, r)
    b = np.clip(hi - z, -r, r)
    # Volume of a sphere between heights a and b from its centre: π ∫ (r² - s²) ds.
    solid = np.pi * ((r * r * b - b**3 / 3) - (r * r * a - a**3 / 3))
    return 1.0 - solid.sum() / (area * (hi - lo))


def settled_bed(e, end_time):
    sc = copy.deepcopy(BASE)
    sc["material"][0]["restitution_coefficient"] = e
    sc["run"]["end_time"] = end_time
    sim = riprap.Simulation(sc)
    sim.run_until(end_time)
    z, r = sim.positions[:, 2], sim.radii
    top = np.percentile(z + r, 90)
    n = slab_porosity(z, r, 2 * D, top - 2 * D, L * L)
    kinetic = 0.5 * np.sum(sim.masses * np.sum(sim.velocities**2, axis=1))
    return n, top, kinetic


def main():
    quick = "--quick" in sys.argv
    values = [0.1, 0.5, 0.9] if quick else [0.1, 0.3, 0.5, 0.7, 0.9]
    end_time = 0.4 if quick else BASE["run"]["end_time"]
    rows = []
    print(f"{'e':>5} {'porosity':>9} {'bed top [mm]':>13} {'KE left [J]':>12} {'wall [s]':>9}")
    for e in values:
        t0 = time.perf_counter()
        n, top, ke = settled_bed(e, end_time)
        rows.append((e, n, top, ke))
        print(f"{e:5.2f} {n:9.4f} {1e3 * top:13.2f} {ke:12.3e} {time.perf_counter() - t0:9.1f}")
    with open("sweep_restitution_porosity.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["restitution", "porosity", "bed_top_m", "kinetic_energy_J"])
        w.writerows(rows)


if __name__ == "__main__":
    main()
