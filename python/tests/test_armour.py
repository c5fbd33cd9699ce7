"""`[armour]` from Python: a checkpoint saved by `Simulation` carries the damage counters
(the reference profile, the units, the rocking counters) as the CLI's does, so that the CLI
continues it to the same bits and the same damage report (issue 32)."""

import math
import re
import shutil
import subprocess

import riprap

# tests/armour_output.rs's set-up: flat four-sphere stones (D_n = 4 cm) 1 mm above a 1:2 plane,
# dry and without gravity; one spins about the slope's normal (it rocks), one glides up it.
BASE = """[run]
name = "armour"
end_time = 0.1
reference_velocity = 1.0

[domain]
min = [0.0, 0.0, 0.0]
max = [1.0, 0.12, 0.5]
periodic = [false, true, false]
gravity = [0.0, 0.0, 0.0]

[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.7
restitution_coefficient = 0.2

[[wall]]
kind = "plane"
material = "rock"
point = [0.3, 0.0, 0.0]
normal = [-0.4472136, 0.0, 0.8944272]

[[block_template]]
name = "stone"
shape = "spheres"
material = "rock"
spheres = [[0.25, 0.2, 0.0, 0.6], [0.25, -0.2, 0.0, 0.6], [-0.25, 0.2, 0.0, 0.6], [-0.25, -0.2, 0.0, 0.6]]
nominal_diameter = 0.04

[output]
series_interval = 0.01
checkpoint_interval = 0.02
skip = ["spheres", "walls", "plots"]

[armour]
toe = [0.3, 0.0]
slope = 2.0
nominal_diameter = 0.04
layer_thickness = 0.04
crest_level = 0.2
wave_period = 0.05
interval = 0.01
"""


def stone(s, y, v=(0.0, 0.0, 0.0), w=(0.0, 0.0, 0.0)):
    c, si, h = 2.0 / math.sqrt(5.0), 1.0 / math.sqrt(5.0), 0.017
    x, z = 0.3 + s * c - h * si, s * si + h * c
    return (f"  {{ position = [{x!r}, {y!r}, {z!r}], rotation = [0.0, -0.4636476, 0.0], "
            f"velocity = [{v[0]!r}, {v[1]!r}, {v[2]!r}], "
            f"angular_velocity = [{w[0]!r}, {w[1]!r}, {w[2]!r}] }},\n")


def scenario(path):
    blocks = "\n[[blocks]]\nkind = \"list\"\ntemplate = \"stone\"\nblocks = [\n"
    blocks += stone(0.04, 0.03, w=(-35.77709, 0.0, 71.55418))
    blocks += stone(0.04, 0.09)
    blocks += stone(0.104, 0.03, v=(0.894427, 0.0, 0.447214))
    blocks += stone(0.104, 0.09)
    path.write_text(BASE + blocks + "]\n")
    return str(path)


def cli_run(cli, path, out, *args):
    subprocess.run([cli, "--threads", "2", "run", path, "--output", str(out), *args],
                   check=True, capture_output=True)


def without_cost(md):
    """The report less its wall-time section (`## Cost`)."""
    return re.sub(r"## Cost\n.*?(?=\n## |\Z)", "", md, flags=re.S)


def test_a_python_checkpoint_of_an_armour_scenario_continues_in_the_cli(cli, workdir):
    path = scenario(workdir / "armour.toml")
    whole = workdir / "whole"
    cli_run(cli, path, whole)
    sim = riprap.Simulation(path)
    steps = round(sim.end_time / sim.dt)
    cut = steps // 2
    assert sim.armour["reference_time"] == 0.0 and len(sim.armour["units"]) == 4
    # The CLI's first half, and Python's: the same checkpoint, armour state included.
    half = workdir / "half"
    cli_run(cli, path, half, "--steps", str(cut))
    sim.advance(cut // 3)
    sim.advance(cut - cut // 3)
    ck = workdir / "py.ck"
    sim.save_checkpoint(str(ck))
    assert ck.read_bytes() == (half / "checkpoint.ck").read_bytes()
    # The CLI continues Python's checkpoint in a copy of the whole run's folder, less the files
    # written at the end (armour.csv is cut at the checkpoint's time by the restart): the rows,
    # units and report of the uninterrupted run. (Not in `half`: a run stopped by --steps
    # writes a closing row there that the uninterrupted run does not have.)
    cont = workdir / "cont"
    shutil.copytree(whole, cont)
    ends = ["checkpoint.ck", "armour_units.csv", "armour_profile.csv", "armour_report.md"]
    for name in ends:
        (cont / name).unlink()
    cli_run(cli, path, cont, "--restart", str(ck))
    for name in ends[:3] + ["armour.csv", "series.csv"]:
        assert (cont / name).read_bytes() == (whole / name).read_bytes(), name
    report = (whole / "armour_report.md").read_text()
    assert "## Cost" in report
    assert without_cost((cont / "armour_report.md").read_text()) == without_cost(report)
    # And Python to the end: the spinning stone has rocked, as the CLI counted.
    sim.run_until(sim.end_time)
    assert sim.step == steps and sim.armour["rocks"].sum() >= 1
    sim.save_checkpoint(str(ck))
    assert ck.read_bytes() == (whole / "checkpoint.ck").read_bytes()
    # Loaded back, the counters are the checkpoint's.
    back = riprap.Simulation.from_checkpoint(path, str(ck))
    assert back.armour["rocks"].tolist() == sim.armour["rocks"].tolist()
