#!/usr/bin/env python3
"""Reads back, with VTK's own XML readers, the files that `tests/vtk_reader.rs` writes, and
compares every value with what was written (the same formulas as the Rust test).

Usage: python3 read_back.py DIR   (DIR holds series.pvd and the files it lists)
Needs the `vtk` and `numpy` Python packages (`pip install vtk`). Exits 0 when all match.
VTK's Python package has no .pvd reader (that one is ParaView's), so the collection is
parsed as XML and each file it lists is read on its own, as ParaView does.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

N = 1500  # points, triangles + 2, and image cells
IMAGE = (10, 15, 10)


class Errors:
    """Collects the warnings and errors a reader reports (VTK does not raise them)."""

    def __init__(self, reader):
        self.messages = []
        reader.AddObserver("ErrorEvent", self.note)
        reader.AddObserver("WarningEvent", self.note)

    def note(self, _obj, event):
        self.messages.append(event)


def expected(precision):
    i = np.arange(N, dtype=np.float64)
    f = np.float32 if precision == "float32" else np.float64
    pos = np.stack([i / 8, i * 0.25 - 3, 1000 + i / 1024], axis=1)
    return {
        "Points": pos,
        "id": 3 * np.arange(N, dtype=np.int64) - 7,
        "diameter": (0.01 + i * 2.0**-20).astype(f),
        "velocity": np.stack([i / 3, -i / 7, np.ones(N)], axis=1).astype(f),
        "wear": (np.arange(N - 2) * 0.25).astype(f),
        "p": (i / 3).astype(f),
        "u": np.stack([i, -i / 7, np.full(N, 0.5)], axis=1).astype(f),
    }


def same(name, got, want):
    got = vtk_to_numpy(got) if not isinstance(got, np.ndarray) else got
    want = want.reshape(got.shape) if want.size == got.size else want
    if got.dtype != want.dtype or got.shape != want.shape or not np.array_equal(got, want):
        raise AssertionError(f"{name}: read {got.dtype}{got.shape}, wrote {want.dtype}{want.shape}")


def check(path):
    precision = "float32" if "float32" in path.name else "float64"
    want = expected(precision)
    reader = {
        ".vtu": vtk.vtkXMLUnstructuredGridReader,
        ".vtp": vtk.vtkXMLPolyDataReader,
        ".vti": vtk.vtkXMLImageDataReader,
    }[path.suffix]()
    errors = Errors(reader)
    reader.SetFileName(str(path))
    reader.Update()
    if errors.messages:
        raise AssertionError(f"{path.name}: the reader reported {errors.messages}")
    data = reader.GetOutput()
    if path.suffix == ".vti":
        dims = data.GetDimensions()
        assert dims == tuple(n + 1 for n in IMAGE), dims
        assert data.GetOrigin() == (-1.0, 0.0, 0.5) and data.GetSpacing() == (0.125, 0.25, 0.5)
        cells = data.GetCellData()
        same("p", cells.GetArray("p"), want["p"])
        same("u", cells.GetArray("u"), want["u"])
        return
    same("Points", data.GetPoints().GetData(), want["Points"])
    if path.suffix == ".vtu":
        assert data.GetNumberOfCells() == N
        assert all(data.GetCellType(k) == vtk.VTK_VERTEX for k in (0, N // 2, N - 1))
        pd = data.GetPointData()
        same("id", pd.GetArray("id"), want["id"])
        same("diameter", pd.GetArray("diameter"), want["diameter"])
        same("velocity", pd.GetArray("velocity"), want["velocity"])
    else:
        assert data.GetNumberOfPolys() == N - 2
        ids = vtk.vtkIdList()
        data.GetCellPoints(N - 3, ids)
        assert [ids.GetId(k) for k in range(3)] == [N - 3, N - 2, N - 1]
        same("wear", data.GetCellData().GetArray("wear"), want["wear"])


def main(folder):
    root = ET.parse(folder / "series.pvd").getroot()
    assert root.get("type") == "Collection", root.attrib
    files = [d.get("file") for d in root.iter("DataSet")]
    assert len(files) == 12, files
    for name in files:
        check(folder / name)
        print(f"read back {name}")
    print(f"all {len(files)} files read back with VTK {vtk.vtkVersion.GetVTKVersion()}")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
