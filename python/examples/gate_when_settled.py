"""A run steered from Python: the gate of examples/gate_release.toml opened when the gravel
behind it has settled, instead of at a fixed time.

The scenario file is read as a dict (tomllib), the gate's prescribed motion taken out, and the
run driven by `riprap.drive`, which calls `steer` every 5 ms of simulated time. Once the
gravel's kinetic energy per sphere has dropped below a threshold, `steer` gives the gate the
file's motion (4 m/s downstream for 0.3 s) from that instant. Run from the repository root:

    python python/examples/gate_when_settled.py [--quick]

(--quick stops 0.2 s after the gate opens.) Prints when the gate opened and how many
spheres have left the flume by the end.
"""

import sys

import numpy as np

try:
    import tomllib  # Python 3.11+
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib

import riprap

SCENARIO = "examples/gate_release.toml"
SETTLED = 1.0e-5  # kinetic energy per sphere [J] below which the bed counts as settled


def main():
    with open(SCENARIO, "rb") as f:
        sc = tomllib.load(f)
    gate = next(i for i, w in enumerate(sc["wall"]) if w.get("name") == "gate")
    motion = sc["wall"][gate].pop("motion")  # held shut until steer() opens it
    duration = motion["stop"] - motion["start"]
    sim = riprap.Simulation(sc, base_dir="examples")
    opened = []
    quick = "--quick" in sys.argv

    def steer(s):
        if opened:
            return not (quick and s.time > opened[0] + 0.2)  # False stops the run
        ke = 0.5 * np.sum(s.masses * np.sum(s.velocities**2, axis=1)) / max(s.n_spheres, 1)
        if s.time > 0.05 and ke < SETTLED:
            t = s.time
            s.set_wall_motion(gate, {"kind": "linear", "velocity": motion["velocity"],
                                     "start": t, "stop": t + duration})
            opened.append(t)
            print(f"t = {t:.3f} s: settled (KE {ke:.2e} J per sphere): gate opened")
        return None

    riprap.drive(sim, every=0.005, callback=steer)
    if not opened:
        print("the gravel never settled below the threshold: the gate stayed shut")
    print(f"t = {sim.time:.3f} s: {sim.n_spheres} of 400 spheres still in the flume")


if __name__ == "__main__":
    main()
