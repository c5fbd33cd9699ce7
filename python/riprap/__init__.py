"""riprap from Python: DEM of spheres and armour blocks coupled to an LES of the water.

The same scenarios, checks, runs and bits as the ``riprap`` command (docs/PYTHON.md):

* ``riprap.check(scenario)``: a TOML path or a dict, checked; the derived quantities as a dict
* ``riprap.run(scenario, output=...)``: ``riprap run``, the same files and checkpoints
* ``riprap.Simulation(scenario)``: step it (``advance``, ``run_until``), read and set its state
  as numpy arrays between steps; ``riprap.drive`` calls a function at output times. A
  ``[shallow]`` scenario gives a ``riprap.ShallowSimulation`` (depth, discharges, bed, debris)
* ``riprap.Results(folder)``: a run's series, probes, blocks, gauges as numpy arrays or pandas
  frames

Bad input raises ``riprap.ScenarioInputError`` (a ValueError) whose ``key`` names the key.
"""

from ._riprap import (
    InstabilityError,
    ScenarioInputError,
    ShallowSimulation,
    Simulation,
    __version__,
    check,
    run,
    set_threads,
    threads,
)
from .results import Results, read_csv
from .steer import drive

__all__ = [
    "InstabilityError",
    "Results",
    "ScenarioInputError",
    "ShallowSimulation",
    "Simulation",
    "__version__",
    "check",
    "drive",
    "read_csv",
    "run",
    "set_threads",
    "threads",
]
