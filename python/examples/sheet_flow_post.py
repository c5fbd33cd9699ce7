"""Post-processing of a sheet-flow run (examples/sheet_flow.toml) from Python.

Reads the run's output folder: series.csv (the flow's energy, the spheres' mean height),
sample_mid_plane.csv (the flow on the vertical mid-plane, one row per cell and time) and the
last checkpoint (every sphere's position and size), and prints

* the free-stream and near-bed velocity over time, from the mid-plane, averaged along x;
* the vertical sorting: the mean height of each of the three sizes, at the start and now;
* the solid concentration profile c(z) of the last state, in slabs of one small diameter.

Run from the repository root, after `riprap run examples/sheet_flow.toml` (hours) or with
`--run T` to first run the first T seconds from Python (T = 0.02: a few minutes on 2 cores):

    python python/examples/sheet_flow_post.py [OUTPUT_FOLDER] [--run T]

pandas is used for the group-by when it is installed, numpy alone otherwise.
"""

import sys

import numpy as np

import riprap

SCENARIO = "examples/sheet_flow.toml"


def main():
    args = [a for a in sys.argv[1:]]
    run_for = None
    if "--run" in args:
        i = args.index("--run")
        run_for = float(args[i + 1])
        del args[i : i + 2]
    folder = args[0] if args else "output/sheet_flow"
    if run_for is not None:
        s = riprap.run(SCENARIO, output=folder, end_time=run_for)
        print(f"ran to t = {s['time']:.4f} s in {s['wall_seconds']:.0f} s ({s['steps']} fluid steps)")
    res = riprap.Results(folder)

    series = res.series()
    print(f"series.csv: {len(series['time'])} rows to t = {series['time'][-1]:.4f} s; mean "
          f"sphere height {1e3 * series['mean_height'][0]:.2f} -> "
          f"{1e3 * series['mean_height'][-1]:.2f} mm; flow KE now "
          f"{series['fluid_kinetic_energy'][-1]:.3e} J")

    # The mid-plane, averaged along x at each height and time.
    try:
        frame = res.sample("mid_plane", frame=True)
        profiles = frame.groupby(["time", "z"])["velocity_x"].mean().unstack("z")
        times, heights, u = profiles.index.values, profiles.columns.values, profiles.values
    except ImportError:
        plane = res.sample("mid_plane")
        times, heights = np.unique(plane["time"]), np.unique(plane["z"])
        u = np.array([[plane["velocity_x"][(plane["time"] == t) & (plane["z"] == z)].mean()
                       for z in heights] for t in times])
    near = np.searchsorted(heights, 0.06)  # 1 cm above the bed's surface (5 cm)
    print("\nmid-plane u averaged along x [m/s]:")
    print(f"{'t [s]':>8} {'u(top)':>9} {'u(z = %.1f mm)' % (1e3 * heights[near]):>16}")
    for t, row in zip(times, u):
        print(f"{t:8.4f} {row[-1]:9.4f} {row[near]:16.4f}")

    # Sizes and heights from the last checkpoint.
    sim = riprap.Simulation.from_checkpoint(SCENARIO, res.checkpoint)
    start = riprap.Simulation(SCENARIO)
    free = ~sim.fixed
    d = np.round(2e3 * sim.radii, 2)  # mm
    d0 = np.round(2e3 * start.radii, 2)
    print(f"\nvertical sorting at t = {sim.time:.4f} s (free spheres):")
    print(f"{'d [mm]':>8} {'count':>6} {'mean z at t = 0 [mm]':>21} {'now [mm]':>9}")
    for size in np.unique(d[free]):
        now = sim.positions[free & (d == size), 2].mean()
        then = start.positions[~start.fixed & (d0 == size), 2].mean()
        print(f"{size:8.2f} {np.sum(free & (d == size)):6d} {1e3 * then:21.2f} {1e3 * now:9.2f}")

    # Solid concentration in slabs of one small diameter (volume of the spheres' slices).
    z, r = sim.positions[:, 2], sim.radii
    lo, hi = sim.flow_grid["origin"][2], 0.07
    slab = 2 * r.min()
    edges = np.arange(lo, hi + slab, slab)
    g = sim.flow_grid
    area = g["cells"][0] * g["spacing"][0] * g["cells"][1] * g["spacing"][1]
    print("\nsolid concentration c(z):")
    for a, b in zip(edges[:-1], edges[1:]):
        ca = np.clip(a - z, -r, r)
        cb = np.clip(b - z, -r, r)
        v = np.pi * ((r * r * cb - cb**3 / 3) - (r * r * ca - ca**3 / 3))
        c = v.sum() / (area * (b - a))
        print(f"  z = {1e3 * a:6.2f}-{1e3 * b:6.2f} mm  c = {c:5.3f} " + "#" * int(40 * c))


if __name__ == "__main__":
    main()
