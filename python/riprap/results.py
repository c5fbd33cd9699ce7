"""A run's output folder read back: CSV series as numpy arrays or pandas frames.

riprap writes each CSV with a header line and numbers that parse back to the very same
float64 (src/io/csv.rs), so what is read here is what the run computed.
"""

import csv
import os

import numpy as np


def read_csv(path, frame=False):
    """Columns of a riprap CSV file as a dict of float64 arrays (or, with ``frame=True``, a
    pandas DataFrame; pandas is imported only then)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        try:
            header = next(reader)
        except StopIteration:
            raise ValueError(f"{path}: empty file, no header line") from None
        rows = [r for r in reader if r]
    data = np.array(rows, dtype=np.float64).reshape(len(rows), len(header))
    columns = {name: data[:, i].copy() for i, name in enumerate(header)}
    if frame:
        import pandas as pd

        return pd.DataFrame(columns)
    return columns


class Results:
    """The output folder of a run (``riprap run`` or ``riprap.run``)."""

    def __init__(self, folder):
        self.folder = os.fspath(folder)
        if not os.path.isdir(self.folder):
            raise FileNotFoundError(f"{self.folder}: no such output folder")

    def path(self, name):
        """The path of a file of the run, which must exist."""
        p = os.path.join(self.folder, name)
        if not os.path.exists(p):
            have = ", ".join(sorted(os.listdir(self.folder)))
            raise FileNotFoundError(f"{p}: not written by this run (the folder holds: {have})")
        return p

    def csv(self, name, frame=False):
        """Any CSV file of the run by name."""
        return read_csv(self.path(name), frame)

    def series(self, frame=False):
        """``series.csv``: energies, contacts, and the flow's columns with water."""
        return self.csv("series.csv", frame)

    def probe(self, sphere_id, frame=False):
        """``probe_<id>.csv``: one sphere's state and contacts at every step."""
        return self.csv(f"probe_{sphere_id}.csv", frame)

    def blocks(self, frame=False):
        """``blocks.csv``: each block's pose, velocity and displacement at each frame."""
        return self.csv("blocks.csv", frame)

    def gauges(self, frame=False):
        """``gauges.csv``: the wave gauges' surface elevations."""
        return self.csv("gauges.csv", frame)

    def sample(self, name, frame=False):
        """``sample_<name>.csv`` of a ``[[fluid.sample]]``."""
        return self.csv(f"sample_{name}.csv", frame)

    def armour(self, frame=False):
        """``armour.csv``: displaced and rocking units, N_od, eroded area, S."""
        return self.csv("armour.csv", frame)

    @property
    def checkpoint(self):
        """The run's last checkpoint (for ``riprap.run(..., restart=...)`` or
        ``Simulation.from_checkpoint``)."""
        return self.path("checkpoint.ck")

    def files(self):
        """The names of the files in the folder."""
        return sorted(os.listdir(self.folder))
