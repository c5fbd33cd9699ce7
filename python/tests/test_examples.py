"""The examples of docs/PYTHON.md run (the quick ones, in their short form)."""

import subprocess
import sys


def test_gate_opened_when_settled(repo):
    r = subprocess.run([sys.executable, "python/examples/gate_when_settled.py", "--quick"],
                       cwd=repo, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    assert "gate opened" in r.stdout and "spheres still in the flume" in r.stdout
