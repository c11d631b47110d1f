#!/usr/bin/env python3
"""How long after Ctrl-C each long Python call ends (docs/benchmarks.md).
Run with the built module on PYTHONPATH:
  PYTHONPATH=build/release/python python3 bench/python_interrupt.py [NAME...]
Each call would run for seconds to hours; SIGINT is sent 1 s in, and the
time from the signal to KeyboardInterrupt is printed."""
import os
import signal
import sys
import threading
import time

import numpy as np

import aapat

CALLS = {
    "optimize": lambda: aapat.optimize(family="P(1,1,16)", starts=100000),
    "optimize (the lattice)": lambda: aapat.optimize(
        family="P(1,1,6)", filter="lanczos:lobes=2", api="d3d12-tier1",
        acuity="uniform:step=1", norm=2, starts=64),
    "enumerate": lambda: aapat.enumerate(max_per_edge=8, optimize=True, starts=200),
    "render": lambda: aapat.render("zoneplate", pattern="msaa-16", size=(4096, 4096),
                                   reference=True, reference_samples=1024),
    "engine_taa": lambda: aapat.engine_taa("checkerboard", size=(256, 256), frames=16000),
    "spectrum": lambda: aapat.spectrum("random", n=16000, size=2048),
    "spectrum_1d": lambda: aapat.spectrum_1d(["jittered"], n=100000, frequencies=100000),
    "generate (best candidate)": lambda: aapat.generate("best-candidate", 3000),
    "generate (poisson)": lambda: aapat.generate("poisson", 200000),
    "optimize_sequence": lambda: aapat.optimize_sequence(frames=72, starts=1000),
    "optimize_sequence (ratio 1.5)": lambda: aapat.optimize_sequence(frames=18, ratio=1.5,
                                                                     starts=100),
    "table2": lambda: aapat.table2(),
    "table3": lambda: aapat.table3(iterations=10**7),
    "figure10": lambda: aapat.figure10(starts=100000),
    "hardware_table": lambda: aapat.hardware_table(starts=100000),
}
ARRAYS = {}
CALLS["eval (3M patterns)"] = lambda: aapat.eval(ARRAYS["eval"])
CALLS["diff (2^25 pixels)"] = lambda: aapat.diff(ARRAYS["a"], ARRAYS["b"])

names = sys.argv[1:] or list(CALLS)
for name in names:
    if name.startswith("eval"):
        ARRAYS["eval"] = np.random.default_rng(1).uniform(-0.5, 0.5, (3_000_000, 8, 2))
    if name.startswith("diff"):
        ARRAYS["a"], ARRAYS["b"] = np.zeros((4096, 8192, 3)), np.full((4096, 8192, 3), 0.5)
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        CALLS[name]()
        print(f"{name}: finished in {time.monotonic() - start:.2f} s, before the signal")
    except KeyboardInterrupt:
        print(f"{name}: KeyboardInterrupt {time.monotonic() - start - 1.0:.3f} s after SIGINT")
    timer.cancel()
    ARRAYS.clear()
