"""The cost of driving riprap from Python against the CLI (issue 32), medians of 3.

    python python/bench/overhead.py PATH/TO/riprap [--steps N] [--threads T] [--scenario F]

On one scenario (default examples/gate_release.toml, 400 spheres, no water) and N steps:

* cli: `riprap --threads T run F --steps N` as a process (build, loop, its outputs), and the
  loop time it reports; then the same with F's outputs cut to the first and last frame (its
  `[output]` intervals set beyond the run, `skip` all but the series): the CLI's stepping;
* advance(N): `Simulation(F)` then one `advance(N)`;
* advance(1) loop: `for _ in range(N): sim.advance(1)`;
* advance(1) + positions: the same, reading `sim.positions` after each step.

Python's build of the simulation is timed apart and left out of its loop times.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import riprap


def median_of(n, f):
    return statistics.median(f() for _ in range(n))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("cli")
    p.add_argument("--steps", type=int, default=10000)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--scenario", default="examples/gate_release.toml")
    a = p.parse_args()
    riprap.set_threads(a.threads)
    n = a.steps

    loops = {}
    quiet = os.path.join(tempfile.mkdtemp(), os.path.basename(a.scenario))
    with open(a.scenario) as f:
        text = f.read()
    text = re.sub(r"^(vtk|series|checkpoint|flow)_interval\s*=.*$", r"\1_interval = 1.0e6",
                  text, flags=re.M)
    text = text.replace("[output]", '[output]\nskip = ["spheres", "walls", "blocks", "flow", '
                        '"plots"]', 1)
    with open(quiet, "w") as f:
        f.write(text)

    def cli(scenario):
        with tempfile.TemporaryDirectory() as out:
            t = time.perf_counter()
            r = subprocess.run(
                [a.cli, "--threads", str(a.threads), "run", scenario, "--steps", str(n),
                 "--output", out], check=True, capture_output=True, text=True)
            wall = time.perf_counter() - t
        loops.setdefault(scenario, []).append(
            float(re.search(r"steps? in ([0-9.]+) s", r.stderr).group(1)))
        return wall

    def build():
        t = time.perf_counter()
        riprap.Simulation(a.scenario)
        return time.perf_counter() - t

    def advance_n():
        sim = riprap.Simulation(a.scenario)
        t = time.perf_counter()
        sim.advance(n)
        return time.perf_counter() - t

    def advance_1():
        sim = riprap.Simulation(a.scenario)
        t = time.perf_counter()
        for _ in range(n):
            sim.advance(1)
        return time.perf_counter() - t

    def advance_1_read():
        sim = riprap.Simulation(a.scenario)
        t = time.perf_counter()
        for _ in range(n):
            sim.advance(1)
            sim.positions
        return time.perf_counter() - t

    rows = [("cli process (build, loop, outputs)", median_of(3, lambda: cli(a.scenario)))]
    rows.append(("cli loop as it reports it (0.1 s resolution)",
                 statistics.median(loops[a.scenario])))
    rows.append(("cli process, no outputs", median_of(3, lambda: cli(quiet))))
    rows.append(("cli loop, no outputs (0.1 s resolution)", statistics.median(loops[quiet])))
    rows.append(("python: Simulation(F) build", median_of(3, build)))
    rows.append(("python: advance(N)", median_of(3, advance_n)))
    rows.append(("python: advance(1) loop", median_of(3, advance_1)))
    rows.append(("python: advance(1) loop + positions", median_of(3, advance_1_read)))
    print(f"{a.scenario}, {n} steps, {a.threads} thread(s), python {sys.version.split()[0]}, "
          f"riprap {riprap.__version__}, {os.cpu_count()} cpus")
    for name, t in rows:
        print(f"  {name:46s} {t:8.3f} s  {1e6 * t / n:8.1f} us/step")


if __name__ == "__main__":
    main()
