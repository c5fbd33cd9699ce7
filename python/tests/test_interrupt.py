"""Ctrl-C stops a run cleanly, keeping its checkpoint (issue 32)."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

SCRIPT = textwrap.dedent(
    """
    import signal, sys, riprap
    from conftest import tiny
    # A shell that starts this suite in the background (`python/ci.sh &`) ignores SIGINT, the
    # child inherits that, and Python then installs no KeyboardInterrupt handler: the signal
    # would be dropped before riprap saw it. A user's Ctrl-C reaches a Python that has one.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    mode, out = sys.argv[1], sys.argv[2]
    sc = tiny(spheres=3, end_time=1000.0)
    print("ready", flush=True)
    if mode == "run":
        try:
            riprap.run(sc, output=out)
        except KeyboardInterrupt as e:
            print("interrupted:", e, flush=True)
            s = riprap.Simulation.from_checkpoint(sc, out + "/checkpoint.ck")
            print("restarted at step", s.step, flush=True)
    else:
        sim = riprap.Simulation(sc)
        try:
            sim.advance(10**12)
        except KeyboardInterrupt:
            sim.save_checkpoint(out + ".ck")
            step = sim.step
            sim.advance(10)
            print("interrupted at step", step, "then", sim.step, flush=True)
    """
)


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize("mode", ["run", "advance"])
def test_ctrl_c_stops_cleanly(mode, workdir):
    here = os.path.dirname(__file__)
    p = subprocess.Popen(
        [sys.executable, "-c", SCRIPT, mode, str(workdir / "out")],
        cwd=here, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "PYTHONPATH": here + os.pathsep + os.environ.get("PYTHONPATH", "")},
    )
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.5)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 0, err
    if mode == "run":
        assert "interrupted: riprap.run stopped at t =" in out
        assert "checkpoint written to" in out
        step = int(out.split("restarted at step")[1])
        assert step > 0
    else:
        words = out.split()
        step, then = int(words[3]), int(words[5])
        assert step > 0 and then == step + 10
        assert (workdir / "out.ck").exists()
