"""Bad input as Python exceptions naming the key (issue 32)."""

import pytest

import riprap


def test_a_file_error_names_file_line_and_key(repo, workdir):
    text = (repo / "examples" / "single_impact.toml").read_text()
    bad = text.replace("poisson_ratio = 0.22", "poisson_ratio = 0.7", 1)
    assert bad != text, "the example changed: pick another value to spoil"
    path = workdir / "bad.toml"
    path.write_text(bad)
    with pytest.raises(riprap.ScenarioInputError) as e:
        riprap.check(str(path))
    err = e.value
    assert err.key.endswith("poisson_ratio")
    assert err.file == str(path) and err.line > 0
    assert f"{path}:{err.line}: key `{err.key}`" in str(err)
    assert isinstance(err, ValueError)
    # The same from Simulation.
    with pytest.raises(riprap.ScenarioInputError, match="poisson_ratio"):
        riprap.Simulation(str(path))


def test_a_dict_error_names_the_dict_path(tiny_scenario):
    tiny_scenario["material"][0]["poisson_ratio"] = 0.7
    with pytest.raises(riprap.ScenarioInputError) as e:
        riprap.check(tiny_scenario)
    assert e.value.key == "material[0].poisson_ratio"
    assert e.value.file == "dict" and e.value.line == 0
    assert str(e.value).startswith("dict: key `material[0].poisson_ratio`: must lie in [0, 0.5)")


def test_unknown_keys_and_types_in_a_dict(tiny_scenario):
    tiny_scenario["run"]["end_tme"] = 1.0
    with pytest.raises(riprap.ScenarioInputError, match="end_tme"):
        riprap.Simulation(tiny_scenario)
    del tiny_scenario["run"]["end_tme"]
    tiny_scenario["run"]["end_time"] = None
    with pytest.raises(TypeError, match=r"key `run.end_time`.*NoneType"):
        riprap.check(tiny_scenario)


def test_missing_file():
    with pytest.raises(riprap.ScenarioInputError, match="cannot read the scenario"):
        riprap.check("no/such/file.toml")


def test_check_returns_the_derived_quantities(repo):
    d = riprap.check(str(repo / "examples" / "single_impact.toml"))
    assert d["kind"] == "dem" and d["steps"] == 6000
    assert d["time_step"] == 5.0e-7
    assert d["spheres_at_start"] == 1
    assert "time step" in d["report"]
    assert d["pairings"] and d["pairings"][0]["contact_duration"] > 0


def test_instability_is_an_exception(tiny_scenario):
    sim = riprap.Simulation(tiny_scenario)
    v = sim.velocities
    v[0] = [0.0, 0.0, 1.0e6]
    sim.velocities = v
    with pytest.raises(riprap.InstabilityError) as e:
        sim.advance(5)
    assert e.value.what and e.value.cause and e.value.step >= 1
