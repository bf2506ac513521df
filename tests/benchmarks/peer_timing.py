"""What the scipy comparisons share: running a Google Benchmark program for its
medians, and the median time of a Python call."""
import json
import subprocess
import time

import numpy as np


def benchmark_medians(bench, field="real_time"):
    """{(name, size): seconds} from 7 repetitions of `bench`, medians of `field`."""
    runs = json.loads(subprocess.run(
        [bench, "--benchmark_repetitions=7", "--benchmark_report_aggregates_only=true",
         "--benchmark_format=json"], check=True, capture_output=True, text=True).stdout)
    out = {}
    for b in runs["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name, n = b["run_name"].split("/")
        out[(name, int(n))] = b[field] * {"us": 1e-6, "ms": 1e-3, "ns": 1e-9}[b["time_unit"]]
    return out


def median_time(fn, clock=time.perf_counter, budget_s=1.0, min_reps=7):
    """Median duration of fn() on `clock` over at least min_reps calls and budget_s."""
    times = []
    start = clock()
    while len(times) < min_reps or clock() - start < budget_s:
        t0 = clock()
        fn()
        times.append(clock() - t0)
        if len(times) >= 2000:
            break
    return float(np.median(times))
