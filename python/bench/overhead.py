"""The cost of driving riprap from Python against the CLI (issue 32).

    python python/bench/overhead.py PATH/TO/riprap [--steps N] [--threads T] [--scenario F]
                                                   [--rounds R]

On one scenario (default examples/gate_release.toml, 400 spheres, no water) and N steps:

* cli: `riprap --threads T run F --steps N` as a process (build, loop, its outputs), and the
  loop time it reports; then the same with F's outputs cut to the first and last frame (its
  `[output]` intervals set beyond the run, `skip` all but the series): the CLI's stepping;
* advance(N): `Simulation(F)` then one `advance(N)`;
* advance(1) loop: `for _ in range(N): sim.advance(1)`;
* advance(1) + positions: the same, reading `sim.positions` after each step.

Python's build of the simulation is timed apart and left out of its loop times. The cases run
in turn, R rounds (default 3), so that a change in the machine's load touches all of them; it
prints the median and the least of each.
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


def main():
    p = argparse.ArgumentParser()
    p.add_argument("cli")
    p.add_argument("--steps", type=int, default=10000)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--scenario", default="examples/gate_release.toml")
    p.add_argument("--rounds", type=int, default=3)
    a = p.parse_args()
    riprap.set_threads(a.threads)
    n = a.steps

    loops = {}
    quiet = os.path.join(tempfile.mkdtemp(), os.path.basename(a.scenario))
    with open(a.scenario) as f:
        text = f.read()
    text = re.sub(r"^(vtk|series|checkpoint|flow)_interval\s*=.*$", r"\1_interval = 1.0e6",
                  text, flags=re.M)
    text = re.sub(r"^\[output\]", '[output]\nskip = ["spheres", "walls", "blocks", "flow", '
                  '"plots"]', text, count=1, flags=re.M)
    with open(quiet, "w") as f:
        f.write(text)

    def cli(scenario):
        with tempfile.TemporaryDirectory() as out:
            t = time.perf_counter()
            r = subprocess.run(
                [a.cli, "--threads", str(a.threads), "run", scenario, "--steps", str(n),
                 "--output", out], capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"{scenario}: riprap run failed:\n{r.stderr}")
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

    cases = [
        ("cli process (build, loop, outputs)", lambda: cli(a.scenario)),
        ("cli process, no outputs", lambda: cli(quiet)),
        ("python: Simulation(F) build", build),
        ("python: advance(N)", advance_n),
        ("python: advance(1) loop", advance_1),
        ("python: advance(1) loop + positions", advance_1_read),
    ]
    times = {name: [] for name, _ in cases}
    for _ in range(a.rounds):
        for name, f in cases:
            times[name].append(f())
    rows = [(name, times[name]) for name, _ in cases]
    rows.insert(1, ("cli loop as it reports it (0.1 s resolution)", loops[a.scenario]))
    rows.insert(3, ("cli loop, no outputs (0.1 s resolution)", loops[quiet]))
    print(f"{a.scenario}, {n} steps, {a.threads} thread(s), python {sys.version.split()[0]}, "
          f"riprap {riprap.__version__}, {os.cpu_count()} cpus")
    print(f"  {'':46s} {'median':>9s} {'least':>9s} {'median':>11s}")
    for name, ts in rows:
        t, least = statistics.median(ts), min(ts)
        print(f"  {name:46s} {t:7.3f} s {least:7.3f} s {1e6 * t / n:7.1f} us/step")


if __name__ == "__main__":
    main()
