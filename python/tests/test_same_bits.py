"""The same bits from Python as from the `riprap` command (issue 32)."""

import subprocess

import numpy as np

import riprap

STEPS = 300


def bits(a):
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def test_advance_gives_the_clis_bits(repo, cli, workdir):
    scenario = repo / "examples" / "gate_release.toml"
    out = workdir / "cli"
    subprocess.run(
        [cli, "--threads", "2", "run", str(scenario), "--steps", str(STEPS), "--output", str(out)],
        check=True, capture_output=True,
    )
    sim = riprap.Simulation(str(scenario))
    sim.advance(STEPS // 3)
    sim.advance(STEPS - STEPS // 3)  # two calls: a split changes nothing
    ref = riprap.Simulation.from_checkpoint(str(scenario), str(out / "checkpoint.ck"))
    assert sim.step == ref.step == STEPS
    assert sim.time == ref.time
    assert np.array_equal(sim.ids, ref.ids)
    for what in ["positions", "velocities", "angular_velocities", "forces", "torques"]:
        assert np.array_equal(bits(getattr(sim, what)), bits(getattr(ref, what))), what
    # A step loop: its steps run on this thread or on a worker, whichever is faster.
    loop = riprap.Simulation(str(scenario))
    for _ in range(STEPS):
        loop.advance(1)
    assert np.array_equal(bits(loop.positions), bits(ref.positions))
    assert np.array_equal(bits(loop.velocities), bits(ref.velocities))


def test_run_writes_the_clis_files(repo, cli, workdir):
    scenario = repo / "examples" / "gate_release.toml"
    subprocess.run(
        [cli, "run", str(scenario), "--steps", str(STEPS), "--output", str(workdir / "cli")],
        check=True, capture_output=True,
    )
    s = riprap.run(str(scenario), output=str(workdir / "py"), steps=STEPS)
    assert s["steps"] == STEPS and not s["interrupted"]
    for name in ["series.csv", "checkpoint.ck"]:
        assert (workdir / "py" / name).read_bytes() == (workdir / "cli" / name).read_bytes(), name


def test_a_python_checkpoint_continues_in_the_cli(repo, cli, workdir):
    scenario = repo / "examples" / "gate_release.toml"
    sim = riprap.Simulation(str(scenario))
    sim.advance(100)
    ck = workdir / "py.ck"
    sim.save_checkpoint(str(ck))
    subprocess.run(
        [cli, "run", str(scenario), "--restart", str(ck), "--steps", "50",
         "--output", str(workdir / "cli")],
        check=True, capture_output=True,
    )
    sim.advance(50)
    ref = riprap.Simulation.from_checkpoint(str(scenario), str(workdir / "cli" / "checkpoint.ck"))
    assert ref.step == sim.step == 150
    assert np.array_equal(bits(sim.positions), bits(ref.positions))


def test_coupled_run_until_gives_the_clis_bits(repo, cli, workdir):
    """Spheres fed into water, coupled both ways (the built-in hopper_cloud), to t = 0.03 s."""
    scenario = str(repo / "examples" / "hopper_cloud.toml")
    out = workdir / "cli"
    subprocess.run([cli, "run", scenario, "--end-time", "0.03", "--output", str(out)],
                   check=True, capture_output=True)
    sim = riprap.Simulation(scenario)
    sim.run_until(0.01, end=0.03)  # in pieces, as a run to 0.03 s steps
    calls = riprap.drive(sim, until=0.03, every=0.004, callback=lambda s: None)
    assert calls >= 4
    ref = riprap.Simulation.from_checkpoint(scenario, str(out / "checkpoint.ck"))
    assert sim.step == ref.step and sim.time == ref.time
    assert sim.n_spheres == ref.n_spheres > 0
    for what in ["positions", "velocities", "forces", "pressure"]:
        assert np.array_equal(bits(getattr(sim, what)), bits(getattr(ref, what))), what
    for a, b in zip(sim.flow_velocity, ref.flow_velocity):
        assert np.array_equal(bits(a), bits(b))
    # Landing on 0.01 s takes a shortened step the run to 0.03 s does not: other bits.
    other = riprap.Simulation(scenario)
    other.run_until(0.01)
    other.run_until(0.03)
    assert other.step == sim.step + 1
