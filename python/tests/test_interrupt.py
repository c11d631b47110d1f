"""Ctrl-C ends a long call, with or without a progress callback: the call
runs while the calling thread keeps hearing signals, and the library stops
at its next step (aapat::throw_if_interrupted). Each call below would run for
minutes; a SIGINT sent 0.3 s in must end it with KeyboardInterrupt, and the
next call must run normally (the request is cleared). The latency itself is
measured by bench/python_interrupt.py, not here."""
import os
import signal
import threading

import numpy as np
import pytest

import aapat

LONG_CALLS = {
    "optimize": lambda: aapat.optimize(family="P(1,1,16)", starts=100000, threads=1),
    "optimize, a progress callable": lambda: aapat.optimize(
        family="P(1,1,16)", starts=100000, threads=1, progress=lambda done, total, note: None),
    "optimize, the lattice": lambda: aapat.optimize(
        family="P(1,1,6)", api="d3d12-tier1", filter="lanczos:lobes=2", starts=64),
    "optimize_sequence, upscaled": lambda: aapat.optimize_sequence(frames=18, ratio=1.5,
                                                                   starts=1000),
    "table3 (epigraph)": lambda: aapat.table3(patterns=100000, method="slsqp"),
    "render": lambda: aapat.render("zoneplate", pattern="msaa-16", size=(4096, 4096),
                                   reference=True, reference_samples=4096),
    "engine_taa": lambda: aapat.engine_taa("checkerboard", size=(256, 256), frames=16000),
    "spectrum": lambda: aapat.spectrum("random", n=16000, size=2048),
    "generate": lambda: aapat.generate("best-candidate", 3100),
    "eval of a batch": lambda: aapat.eval(
        np.random.default_rng(1).uniform(-0.4, 0.4, (200000, 64, 2))),
}


@pytest.mark.parametrize("name", sorted(LONG_CALLS))
def test_ctrl_c_ends_a_long_call(name):
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            LONG_CALLS[name]()
    finally:
        timer.cancel()
    # The request is cleared: the next call runs to its end.
    assert aapat.optimize(family="P(1,1,2)", starts=2, seed=1).e2 > 0
