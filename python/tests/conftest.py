import os
import pathlib
import shutil

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def repo():
    return REPO


@pytest.fixture
def cli():
    """The `riprap` binary built by `cargo test --release` / `cargo build --release`
    (RIPRAP_BIN overrides; CARGO_TARGET_DIR is looked in too)."""
    candidates = [os.environ.get("RIPRAP_BIN")]
    if os.environ.get("CARGO_TARGET_DIR"):
        candidates.append(os.path.join(os.environ["CARGO_TARGET_DIR"], "release", "riprap"))
    candidates.append(str(REPO / "target" / "release" / "riprap"))
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    if os.environ.get("RIPRAP_REQUIRE_CLI"):
        pytest.fail(f"no riprap binary among {candidates}")
    pytest.skip("no riprap binary: build it with `cargo build --release` or set RIPRAP_BIN")


def tiny(name="tiny", spheres=3, end_time=0.02):
    """A few glass beads dropped in a box: a scenario as a dict, fast to run."""
    return {
        "run": {"name": name, "end_time": end_time},
        "domain": {"min": [0.0, 0.0, 0.0], "max": [0.02, 0.02, 0.04]},
        "material": [
            {
                "name": "glass",
                "density": 2500.0,
                "young_modulus": 1.0e7,
                "poisson_ratio": 0.25,
                "friction_coefficient": 0.5,
                "restitution_coefficient": 0.5,
            }
        ],
        "wall": [
            {"kind": "box", "min": [0.0, 0.0, 0.0], "max": [0.02, 0.02, 0.04], "inside": True,
             "material": "glass"}
        ],
        "spheres": [
            {
                "kind": "list",
                "spheres": [
                    {"position": [0.005 + 0.005 * i, 0.01, 0.01 + 0.006 * i], "diameter": 0.004,
                     "material": "glass"}
                    for i in range(spheres)
                ],
            }
        ],
        "output": {"skip": ["spheres", "walls", "plots"]},
    }


@pytest.fixture
def tiny_scenario():
    return tiny()


@pytest.fixture
def workdir(tmp_path):
    yield tmp_path
    shutil.rmtree(tmp_path, ignore_errors=True)
