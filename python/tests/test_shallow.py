"""A `[shallow]` scenario stepped from Python: the bits of `riprap run` (issue 32)."""

import subprocess

import numpy as np
import pytest

import riprap

STEPS = 40


def run_cli(cli, scenario, out, *args):
    subprocess.run([cli, "--threads", "2", "run", str(scenario), "--output", str(out), *args],
                   check=True, capture_output=True)


def test_advance_gives_the_clis_bits(repo, cli, workdir):
    scenario = repo / "examples" / "shallow_debris.toml"
    run_cli(cli, scenario, workdir / "cli", "--steps", str(STEPS))
    sim = riprap.Simulation(str(scenario))
    assert isinstance(sim, riprap.ShallowSimulation)
    nx, ny = sim.grid["cells"]
    assert (nx, ny) == (120, 60)
    h0, hu0, bed = sim.depth, sim.hu, sim.bed
    assert h0.shape == sim.hv.shape == bed.shape == sim.solid.shape == (ny, nx)
    names = sim.debris_names
    assert len(names) > 0 and sim.debris_centres.shape == (len(names), 3)
    assert sim.debris_orientations.shape == (len(names), 4)
    sim.advance(STEPS // 4)
    sim.advance(STEPS - STEPS // 4)  # two calls: a split changes nothing
    assert sim.step == STEPS and sim.last_time_step > 0.0
    assert not np.array_equal(sim.depth, h0) and not np.array_equal(sim.hu, hu0)
    assert np.array_equal(sim.bed, bed)
    ck = workdir / "py.ck"
    sim.save_checkpoint(str(ck))
    cli_ck = workdir / "cli" / "checkpoint.ck"
    assert ck.read_bytes() == cli_ck.read_bytes()
    assert (workdir / "py_debris.ck").read_bytes() == \
        (workdir / "cli" / "checkpoint_debris.ck").read_bytes()
    # And back: the CLI's checkpoint gives the same fields.
    ref = riprap.ShallowSimulation.from_checkpoint(str(scenario), str(cli_ck))
    assert ref.time == sim.time and np.array_equal(ref.hv, sim.hv)
    assert np.array_equal(ref.debris_centres, sim.debris_centres)


def test_run_until_in_pieces_and_a_python_checkpoint_continued_by_the_cli(repo, cli, workdir):
    scenario = repo / "examples" / "shallow_debris.toml"
    end = 4.0
    run_cli(cli, scenario, workdir / "cli", "--end-time", str(end))
    sim = riprap.Simulation(str(scenario))
    sim.run_until(1.5, end=end)  # the steps of a run to `end`, stopped on the way
    assert 1.5 <= sim.time < end
    ck = workdir / "py.ck"
    sim.save_checkpoint(str(ck))
    run_cli(cli, scenario, workdir / "restart", "--restart", str(ck), "--end-time", str(end))
    sim.run_until(end)
    assert sim.time == end
    for name in ["checkpoint.ck", "checkpoint_debris.ck"]:
        assert (workdir / "restart" / name).read_bytes() == \
            (workdir / "cli" / name).read_bytes(), name
    # The restart's rows (a fresh folder: those after the checkpoint) end the whole run's.
    for name in ["series.csv", "debris_tracks.csv"]:
        rows = (workdir / "restart" / name).read_text().splitlines()
        whole = (workdir / "cli" / name).read_text().splitlines()
        assert rows[0] == whole[0] and len(rows) > 2 and whole[-(len(rows) - 1):] == rows[1:]
    sim.save_checkpoint(str(workdir / "end.ck"))
    assert (workdir / "end.ck").read_bytes() == (workdir / "cli" / "checkpoint.ck").read_bytes()
    assert (workdir / "end_debris.ck").read_bytes() == \
        (workdir / "cli" / "checkpoint_debris.ck").read_bytes()
    with pytest.raises(ValueError, match="not a shallow-water scenario"):
        riprap.ShallowSimulation(str(repo / "examples" / "gate_release.toml"))
