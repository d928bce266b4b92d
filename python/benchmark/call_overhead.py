# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The cost of the Python call against the C++ call on one cloud (doc/python.md).

    PYTHONPATH=build/python /usr/bin/python3 python/benchmark/call_overhead.py \
        build/bin/df_l1_python_call_benchmark CLOUD [PAIRS] [--python-default-malloc]

The C++ benchmark runs in a process of its own (the tool's malloc settings, the stages
as the tool runs them), one call per request; this process makes the Python call,
skeletonize(), on the same points (same malloc settings). Each pair is a C++ call and a
Python call made one after the other, in alternating order, so that both see the same
machine (a shared one drifts by tens of per cent within minutes). The first pair is
left out (TBB's threads start, pages fault in). Prints the medians and the median of
the ratios of the pairs.
"""

import statistics
import subprocess
import sys
import time

import numpy as np

import df_l1_skeleton as dfl1

benchmark, cloud = sys.argv[1], sys.argv[2]
pairs = int(sys.argv[3]) if len(sys.argv) > 3 else 30
python_heap = "--python-default-malloc" not in sys.argv  # else only the C++ side has the tool's settings
if python_heap:
    dfl1.keep_large_buffers_on_heap()
points = np.array(dfl1.read_point_cloud(cloud).points)
cpp_process = subprocess.Popen([benchmark, cloud, "0", "heap"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, text=True)


def cpp_call():
    cpp_process.stdin.write("run\n")
    cpp_process.stdin.flush()
    return float(cpp_process.stdout.readline())


def python_call():
    start = time.perf_counter()
    skeleton = dfl1.skeletonize(points)
    return time.perf_counter() - start, skeleton


cpp, py, ratios = [], [], []
for i in range(pairs + 1):
    if i % 2 == 0:
        c = cpp_call()
        p, skeleton = python_call()
    else:
        p, skeleton = python_call()
        c = cpp_call()
    if i > 0:
        cpp.append(c)
        py.append(p)
        ratios.append(p / c)
cpp_process.stdin.close()
cpp_process.wait()
print(f"{cloud}: {len(points)} points, skeleton of {len(skeleton.vertices)} vertices, {pairs} pairs"
      + ("" if python_heap else ", Python with glibc's default malloc settings"))
print(f"C++ call:    median {statistics.median(cpp):.4f} s, min {min(cpp):.4f} s")
print(f"Python call: median {statistics.median(py):.4f} s, min {min(py):.4f} s")
print(f"Python / C++: median of the pair ratios {statistics.median(ratios):.3f} "
      f"(quartiles {statistics.quantiles(ratios, n=4)[0]:.3f} to {statistics.quantiles(ratios, n=4)[2]:.3f}), "
      f"ratio of the minima {min(py) / min(cpp):.3f}")
