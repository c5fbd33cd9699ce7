"""State read and set between steps; results read back; checkpoints from Python."""

import numpy as np
import pytest

import riprap
from conftest import tiny


def test_arrays_see_the_simulation_change(tiny_scenario):
    sim = riprap.Simulation(tiny_scenario)
    assert sim.n_spheres == 3 and sim.time == 0.0
    x0 = sim.positions
    assert x0.shape == (3, 3) and x0.dtype == np.float64
    sim.advance(200)
    assert sim.step == 200 and sim.time == pytest.approx(200 * sim.dt)
    x1 = sim.positions
    # Falling under gravity: every z lower, x and y as they were (no contact yet).
    order0, order1 = np.argsort(sim.ids), np.argsort(sim.ids)
    assert np.all(x1[order1, 2] < x0[order0, 2])
    assert np.all(sim.velocities[:, 2] < 0.0)
    # A copy: the array taken before does not move.
    assert not np.array_equal(x0, x1)


def test_set_state_between_steps(tiny_scenario):
    sim = riprap.Simulation(tiny_scenario)
    v = sim.velocities
    v[:, 2] = 0.5
    sim.velocities = v
    sim.advance(1)
    assert np.all(sim.velocities[:, 2] > 0.49)
    x = sim.positions
    x[:, 0] = 0.01
    sim.positions = x
    assert np.all(sim.positions[:, 0] == 0.01)
    with pytest.raises(ValueError, match=r"positions: expected an array of shape \(3, 3\)"):
        sim.positions = np.zeros((2, 3))
    with pytest.raises(ValueError, match="outside the domain"):
        sim.positions = np.full((3, 3), 5.0)


def test_add_and_remove_spheres(tiny_scenario):
    sim = riprap.Simulation(tiny_scenario)
    new = sim.add_sphere([0.01, 0.01, 0.03], 0.004, material="glass", velocity=[0, 0, -0.1])
    assert sim.n_spheres == 4 and new in sim.ids
    sim.advance(50)
    i = list(sim.ids).index(new)
    assert sim.positions[i, 2] < 0.03
    assert sim.remove_spheres([new]) == 1
    assert sim.n_spheres == 3 and new not in sim.ids
    sim.advance(10)
    with pytest.raises(ValueError, match="no material named `sand`"):
        sim.add_sphere([0.01, 0.01, 0.03], 0.004, material="sand")
    with pytest.raises(ValueError, match="no sphere 99"):
        sim.remove_spheres([99])


def test_wall_motion_changed_between_steps(tiny_scenario):
    sc = tiny_scenario
    sc["wall"].append({"name": "piston", "kind": "plane", "point": [0.0, 0.0, 0.002],
                       "normal": [0.0, 0.0, 1.0], "material": "glass"})
    sim = riprap.Simulation(sc)
    assert sim.walls[-1] == "piston"
    sim.set_wall_motion(1, {"kind": "linear", "velocity": [0.0, 0.0, 0.2], "start": sim.time})
    with pytest.raises(ValueError, match=r"key `wall\[1\].motion`"):
        sim.set_wall_motion(1, {"kind": "sideways"})
    with pytest.raises(ValueError, match="out of range"):
        sim.set_wall_motion(7, {"kind": "fixed"})


def test_checkpoint_round_trip(tiny_scenario, workdir):
    sim = riprap.Simulation(tiny_scenario)
    sim.advance(100)
    ck = str(workdir / "a.ck")
    sim.save_checkpoint(ck)
    sim.advance(100)
    again = riprap.Simulation.from_checkpoint(tiny_scenario, ck)
    assert again.step == 100
    again.advance(100)
    assert np.array_equal(again.positions, sim.positions)
    other = tiny(spheres=2)
    with pytest.raises(RuntimeError, match="different scenario"):
        riprap.Simulation.from_checkpoint(other, ck)


def test_run_until_and_drive(tiny_scenario):
    sim = riprap.Simulation(tiny_scenario)
    sim.run_until(0.005)
    assert abs(sim.time - 0.005) <= 0.5 * sim.dt
    seen = []
    calls = riprap.drive(sim, until=0.01, every=0.001, callback=lambda s: seen.append(s.time))
    assert calls == len(seen) == 6
    assert abs(sim.time - 0.01) <= 0.5 * sim.dt
    stopped = riprap.drive(sim, until=0.02, every=0.001, callback=lambda s: False)
    assert stopped == 1 and sim.time < 0.0101


def test_results_as_arrays_and_frames(tiny_scenario, workdir):
    s = riprap.run(tiny_scenario, output=str(workdir / "run"))
    assert s["time"] == pytest.approx(0.02, abs=1e-5)  # a whole number of steps
    r = riprap.Results(s["output"])
    series = r.series()
    assert series["time"][0] == 0.0 and series["time"][-1] == s["time"]
    assert np.all(series["spheres"] == 3)
    pd = pytest.importorskip("pandas")
    frame = r.series(frame=True)
    assert isinstance(frame, pd.DataFrame) and list(frame.columns)[:2] == ["time", "step"]
    with pytest.raises(FileNotFoundError, match="not written by this run"):
        r.gauges()
    # The checkpoint continues from Python.
    sim = riprap.Simulation.from_checkpoint(tiny_scenario, r.checkpoint)
    assert sim.time == s["time"]
    row = sim.series()
    assert row["time"] == series["time"][-1]
    assert row["kinetic_energy_translational"] == series["kinetic_energy_translational"][-1]


def test_flow_fields(workdir):
    sc = {
        "run": {"name": "box", "end_time": 0.05},
        "domain": {"min": [0.0, 0.0, 0.0], "max": [0.04, 0.04, 0.04]},
        "fluid": {
            "cells": [8, 8, 8],
            "boundaries": {"z_max": {"kind": "wall", "velocity": [0.01, 0.0, 0.0]}},
        },
    }
    sim = riprap.Simulation(sc)
    grid = sim.flow_grid
    assert grid["cells"] == [8, 8, 8]
    u, v, w = sim.flow_velocity
    assert u.shape == (8, 8, 9) and v.shape == (8, 9, 8) and w.shape == (9, 8, 8)
    assert not np.any(u)
    sim.run_until(0.5)  # flow-only steps: the adaptive step, shortened to land on t
    assert sim.time == pytest.approx(0.5, rel=1e-9)
    sim.advance(3)
    assert sim.step > 3
    u, v, w = sim.flow_velocity
    assert u[-1].max() > 0.0  # the lid drags the top cells along
    assert sim.pressure.shape == (8, 8, 8)
    assert sim.water_fraction is None


def test_blocks(repo):
    sim = riprap.Simulation(str(repo / "examples" / "tetrapods_on_rubble.toml"))
    n = len(sim.block_ids)
    assert n > 0
    assert sim.block_centres.shape == (n, 3)
    q = sim.block_orientations
    assert q.shape == (n, 4) and np.allclose(np.linalg.norm(q, axis=1), 1.0)
    z0 = sim.block_centres[:, 2].copy()
    sim.advance(20)
    assert not np.array_equal(sim.block_centres[:, 2], z0)
    member = int(np.flatnonzero(sim.bodies >= 0)[0])
    with pytest.raises(ValueError, match="member of block"):
        sim.remove_spheres([int(sim.ids[member])])


def test_add_and_remove_blocks(repo):
    sim = riprap.Simulation(str(repo / "examples" / "tetrapods_on_rubble.toml"))
    assert sim.block_templates == ["quarry_rock", "tetrapod"]
    n, spheres = len(sim.block_ids), sim.n_spheres
    top = int(np.argmax(sim.block_centres[:, 2]))  # a tetrapod, the highest: room above it
    old, centre = int(sim.block_ids[top]), sim.block_centres[top].copy()
    assert sim.remove_blocks([old]) == 1
    assert len(sim.block_ids) == n - 1 and old not in sim.block_ids
    members = spheres - sim.n_spheres
    assert members == 9  # resolution 2: 9 spheres per tetrapod
    new = sim.add_block("tetrapod", centre, rotation=[0.0, 0.0, 0.3], velocity=[0.0, 0.0, -0.1])
    assert len(sim.block_ids) == n and sim.n_spheres == spheres and new != old
    sim.advance(20)
    z = sim.block_centres[list(sim.block_ids).index(new), 2]
    assert z < centre[2]
    with pytest.raises(ValueError, match="no block template named `cube9`"):
        sim.add_block("cube9", [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="outside the domain"):
        sim.add_block("tetrapod", [0.5, 0.4, 5.0])
    with pytest.raises(ValueError, match="no block 12345"):
        sim.remove_blocks([12345])


def test_steps_release_the_gil():
    """A Python thread runs while the simulation steps."""
    import threading

    sc = tiny(end_time=100.0)
    sim = riprap.Simulation(sc)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    t = threading.Thread(target=count)
    t.start()
    try:
        before = len(ticks)
        sim.advance(200000)  # a few tenths of a second of stepping in one call
        during = len(ticks) - before
    finally:
        stop.set()
        t.join()
    assert during > 10


def test_block_records_from_a_run(repo, workdir):
    s = riprap.run(str(repo / "examples" / "tetrapods_on_rubble.toml"),
                   output=str(workdir / "blocks"), steps=10)
    r = riprap.Results(s["output"])
    blocks = r.blocks()
    assert len(blocks["time"]) >= 650  # a row per block and frame: 400 stones, 250 tetrapods
    frame = r.blocks(frame=True) if _has_pandas() else None
    if frame is not None:
        assert len(frame) == len(blocks["time"])


def _has_pandas():
    try:
        import pandas  # noqa: F401
    except ImportError:
        return False
    return True


def test_flow_fields_can_be_set():
    sc = {
        "run": {"name": "tank", "end_time": 0.05},
        "domain": {"min": [0.0, 0.0, 0.0], "max": [0.04, 0.04, 0.04]},
        "fluid": {"cells": [8, 8, 8], "air": {"water_level": 0.02}},
    }
    sim = riprap.Simulation(sc)
    u, v, w = sim.flow_velocity
    u2 = u.copy()
    u2[:, :, 1:-1] = 0.1
    sim.flow_velocity = [u2, v, w]
    u3 = sim.flow_velocity[0]
    assert np.array_equal(u3[:, :, 1:-1], u2[:, :, 1:-1])
    assert not np.any(u3[:, :, 0]) and not np.any(u3[:, :, -1])  # the walls' faces
    with pytest.raises(ValueError, match="expected"):
        sim.flow_velocity = [u2[:, :, :-1], v, w]
    a = sim.water_fraction
    assert a.shape == (8, 8, 8) and a[:4].min() == 1.0 and a[4:].max() == 0.0
    a2 = np.zeros_like(a)
    a2[:2] = 1.0  # the water level at 0.01 m
    sim.water_fraction = a2
    assert np.array_equal(sim.water_fraction, a2)
    sim.advance(2)  # the flow carries the new water: its volume is kept (closed box)
    assert abs(sim.water_fraction.sum() - a2.sum()) < 1e-8 * a2.sum()
    with pytest.raises(ValueError, match=r"outside \[0, 1\]"):
        sim.water_fraction = a2 * 1.5


def test_a_block_can_be_moved_in_place(repo):
    sim = riprap.Simulation(str(repo / "examples" / "tetrapods_on_rubble.toml"))
    top = int(np.argmax(sim.block_centres[:, 2]))  # the highest: room above it
    bid, centre = int(sim.block_ids[top]), sim.block_centres[top].copy()
    lifted = centre + [0.0, 0.0, 0.05]
    turn = [0.0, 0.0, np.sin(0.15), np.cos(0.15)]  # 0.3 rad about z, (x, y, z, w)
    sim.set_block_pose(bid, lifted, orientation=turn, velocity=[0.0, 0.0, 0.0])
    assert np.allclose(sim.block_centres[top], lifted, atol=1e-12)
    assert np.allclose(sim.block_orientations[top], turn, atol=1e-12)
    members = sim.bodies == bid
    m = sim.masses[members]
    com = (sim.positions[members] * m[:, None]).sum(axis=0) / m.sum()
    assert np.allclose(com, lifted, atol=1e-9)  # the members in the rigid shape, there
    sim.advance(20)
    z = sim.block_centres[list(sim.block_ids).index(bid), 2]
    assert lifted[2] - 0.01 < z < lifted[2]  # it falls from where it was put
    with pytest.raises(ValueError, match="no block"):
        sim.set_block_pose(10**9, lifted)
    with pytest.raises(ValueError, match="outside the domain"):
        sim.set_block_pose(bid, lifted + [0.0, 0.0, 100.0])


def linked_blocks():
    """Five three-sphere rods resting on a plane, two wires (rod 0 to a post, rods 1 to 2)
    and four bonds (between rod members, and between two free spheres)."""
    mat = {"name": "concrete", "density": 2400.0, "young_modulus": 1.0e8,
           "poisson_ratio": 0.2, "friction_coefficient": 0.5, "restitution_coefficient": 0.3}
    return {
        "run": {"name": "linked", "end_time": 0.01},
        "domain": {"min": [0.0, 0.0, -0.05], "max": [0.5, 0.2, 0.2]},
        "material": [mat],
        "wall": [{"kind": "plane", "material": "concrete", "point": [0.0, 0.0, 0.0],
                  "normal": [0.0, 0.0, 1.0]}],
        "block_template": [{"name": "rod", "shape": "three_sphere_rod", "material": "concrete",
                            "nominal_diameter": 0.02}],
        "blocks": [{"kind": "list", "template": "rod", "blocks": [
            {"position": [0.05 + 0.08 * i, 0.1, 0.012]} for i in range(5)]}],
        "spheres": [{"kind": "list", "material": "concrete", "spheres": [
            {"position": [0.1, 0.03, 0.011], "diameter": 0.02},
            {"position": [0.12, 0.03, 0.011], "diameter": 0.02}]}],
        "wire": [
            {"ends": [{"point": [0.05, 0.1, 0.1]}, {"block": 0, "point": [0.0, 0.0, 0.0]}],
             "stiffness": 1.0e3},
            {"ends": [{"block": 1, "point": [0.0, 0.0, 0.0]},
                      {"block": 2, "point": [0.0, 0.0, 0.0]}], "stiffness": 1.0e3},
        ],
        "output": {"skip": ["spheres", "walls", "plots"]},
    }


def test_blocks_with_wires_and_bonds_are_removed_with_their_links():
    plain = riprap.Simulation(linked_blocks())
    ids, bodies = plain.ids, plain.bodies
    member = {b: [int(i) for i in ids[bodies == b]] for b in range(5)}
    free = [int(i) for i in ids[bodies < 0]]
    # Bonds: rod 1-rod 2, rod 2-rod 3, the free pair, rod 3-rod 4 (scenario order).
    pairs = [[member[1][-1], member[2][0]], [member[2][-1], member[3][0]], free,
             [member[3][-1], member[4][0]]]
    scenario = linked_blocks()
    scenario["bond"] = [{"between": "pairs", "spheres": pairs, "normal_stiffness": 1.0e4,
                         "shear_stiffness": 1.0e4}]
    sim = riprap.Simulation(scenario)
    assert sim.wire_ends.tolist() == [[-1, 0], [1, 2]]
    assert sim.bond_spheres.tolist() == pairs
    sim.advance(10)
    n, spheres = len(sim.block_ids), sim.n_spheres
    # Rod 2 carries wire 1 and bonds 0 and 1: they go with it, the others keep their order.
    assert sim.remove_blocks([2]) == 1
    assert len(sim.block_ids) == n - 1 and sim.n_spheres == spheres - 3
    assert sim.wire_ends.tolist() == [[-1, 0]]
    assert sim.bond_spheres.tolist() == [pairs[2], pairs[3]]
    # A free sphere's bonds go with it too.
    assert sim.remove_spheres([free[0]]) == 1
    assert sim.bond_spheres.tolist() == [pairs[3]]
    # Rod 0's wire to the post goes with rod 0.
    assert sim.remove_blocks([0]) == 1
    assert sim.wire_ends.shape == (0, 2) and len(sim.wires_broken) == 0
    z = sim.block_centres[:, 2].copy()
    sim.advance(50)  # steps on with what is left
    assert sim.step == 60 and np.all(np.isfinite(sim.block_centres))
    assert not np.array_equal(sim.block_centres[:, 2], z)
    assert not sim.bonds_broken.any()
