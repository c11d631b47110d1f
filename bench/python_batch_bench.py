"""aapat.eval on 10,000 random 4-sample patterns in one vectorized call: the
Python side of bench/batch_bench.cpp (BatchE2/10000/0). Prints the median of
repeated calls in microseconds, and the numpy-to-result overhead."""
import statistics
import sys
import time

import numpy as np

import aapat

m = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
xy = np.random.default_rng(1).random((m, 4, 2)) - 0.5
aapat.eval(xy)  # warm up: the filter's tables, the thread pool
times = []
for _ in range(200):
    t0 = time.perf_counter()
    aapat.eval(xy)
    times.append(time.perf_counter() - t0)
print(f"aapat.eval({m} x 4 samples): median {statistics.median(times) * 1e6:.0f} us, "
      f"min {min(times) * 1e6:.0f} us over {len(times)} calls")
