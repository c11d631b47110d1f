"""aapat.eval on 10,000 random 4-sample patterns in one vectorized call: the
Python side of bench/batch_bench.cpp (BatchE2/10000/0 and /1). Like Google
Benchmark, it times a run of back-to-back calls and divides: 20 repetitions of
200 calls, and prints the median repetition's time per call."""
import statistics
import sys
import time

import numpy as np

import aapat

m = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
xy = np.random.default_rng(1).random((m, 4, 2)) - 0.5
for threads, label in [(0, "all threads"), (1, "1 thread")]:
    aapat.eval(xy, threads=threads)  # warm up: the filter's tables, the thread pool
    per_call = []
    for _ in range(20):
        t0 = time.perf_counter()
        for _ in range(200):
            aapat.eval(xy, threads=threads)
        per_call.append((time.perf_counter() - t0) / 200)
    print(f"aapat.eval({m} x 4 samples, {label}): median {statistics.median(per_call) * 1e6:.0f} us "
          f"per call over 20 x 200 calls")
