"""A run steered from Python: a function called at output times."""


def drive(sim, until=None, every=None, callback=None):
    """Advances ``sim`` to ``until`` (default: the scenario's end time), calling
    ``callback(sim)`` at the start and every ``every`` seconds of simulated time (default:
    a fiftieth of the run) and at the end. The callback may read and change the state
    (``positions``, ``set_wall_motion``, ...); returning ``False`` stops the run there.
    Stepping is ``sim.run_until(t, end=until)`` to each output time t: the steps of one
    ``run_until(until)`` (of ``riprap run`` to that end), so a callback that changes nothing
    changes no bit. Without water an output time is rounded to a whole step; with water the
    callback comes at the first step boundary at or past it, as the CLI writes its outputs.
    Returns the number of callbacks made."""
    end = sim.end_time if until is None else float(until)
    span = end - sim.time
    if every is None:
        every = span / 50.0 if span > 0 else 1.0
    if not every > 0:
        raise ValueError(f"drive: every must be a positive time [s], got {every}")
    calls = 0
    t = sim.time
    while True:
        if callback is not None:
            calls += 1
            if callback(sim) is False:
                return calls
        if end - sim.time < 0.5 * sim.dt:
            return calls
        t = min(t + every, end)
        sim.run_until(t, end=end)
