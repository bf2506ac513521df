#!/usr/bin/python3
"""pendulum-g's recording reader and reduction against pandas + numpy, in one run.

Usage (Debian's python3 with python3-pandas, python3-scipy):
    /usr/bin/python3 tests/benchmarks/compare_recordings.py build/tests/benchmarks/bench_recordings

Writes the one-hour 500 Hz phyphox gyroscope recording (1.8 million rows)
with `bench_recordings --write`, runs the Google Benchmark (5 repetitions,
median, peak RSS of that process), then times the Python peer on the same
file (median of 5): pandas.read_csv (C engine), the principal axis of the
mean-removed rates (numpy.linalg.eigh), crossings with the same hysteresis
(+-0.3 of the peak level, vectorised), each crossing by linear interpolation
between the two samples around zero, and the same least-squares model of the
crossing times (numpy.linalg.lstsq). Prints the medians, the ratio, both
periods and both peak memories (ru_maxrss of each process).
"""
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
import pandas as pd


def reduce_with_pandas(path):
    df = pd.read_csv(path)
    t = df["Time (s)"].to_numpy()
    x = df[["Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)"]].to_numpy()
    x = x - x.mean(axis=0)
    _, vectors = np.linalg.eigh(np.cov(x.T))
    s = x @ vectors[:, -1]
    h = 0.3 * np.sqrt(2.0) * s.std()
    state = np.where(s > h, 1, np.where(s < -h, -1, 0))
    beyond = np.nonzero(state)[0]
    side = state[beyond]
    switch = beyond[1:][side[1:] != side[:-1]]  # first sample beyond the other threshold
    signs = np.nonzero(np.signbit(s[:-1]) != np.signbit(s[1:]))[0]
    k = signs[np.searchsorted(signs, switch) - 1]  # last zero crossing before it
    tc = t[k] - s[k] * (t[k + 1] - t[k]) / (s[k + 1] - s[k])
    i = np.arange(len(tc), dtype=float)
    xc = i - (len(tc) - 1) / 2.0
    design = np.column_stack([np.ones_like(xc), xc, xc * xc, np.where(i % 2 == 1, -1.0, 1.0)])
    beta = np.linalg.lstsq(design, tc - tc[0], rcond=None)[0]
    return 2.0 * beta[1], len(df)


def main():
    bench = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "pendulum_g_bench_recording_1h_500Hz.csv")
        subprocess.run([bench, "--write", path], check=True)
        env = dict(os.environ, TMPDIR=tmp)
        out = json.loads(subprocess.run(
            [bench, "--benchmark_filter=BM_ReadAndReduce", "--benchmark_repetitions=5",
             "--benchmark_format=json"],
            check=True, capture_output=True, text=True, env=env).stdout)
        runs = [b for b in out["benchmarks"] if b.get("run_type") == "iteration"]
        ours = float(np.median([b["real_time"] for b in runs])) / 1e3  # ms -> s
        ours_cpu = float(np.median([b["cpu_time"] for b in runs])) / 1e3
        our_period = float(runs[-1]["label"].split()[1])
        our_rss = max(b["peak_rss_MiB"] for b in runs)
        rows = int(runs[-1]["rows"])
        times, cpu = [], []
        for _ in range(5):
            start, start_cpu = time.perf_counter(), time.process_time()
            period, n = reduce_with_pandas(path)
            times.append(time.perf_counter() - start)
            cpu.append(time.process_time() - start_cpu)
        theirs, theirs_cpu = float(np.median(times)), float(np.median(cpu))
        peer_rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
        size = os.path.getsize(path) / 2**20
    print(f"pandas {pd.__version__}, numpy {np.__version__}; {rows} rows, {size:.0f} MiB of CSV\n")
    print("| | median wall time (s) | median CPU time (s) | period (s) | peak memory (MiB) |")
    print("|---|---|---|---|---|")
    print(f"| pendulum-g analyse_recording | {ours:.3f} | {ours_cpu:.3f} | {our_period:.7f} | {our_rss:.0f} |")
    print(f"| pandas read_csv + numpy | {theirs:.3f} | {theirs_cpu:.3f} | {period:.7f} | {peer_rss:.0f} |")
    print(f"\nratio pandas/pendulum-g: {theirs / ours:.1f} (wall), {theirs_cpu / ours_cpu:.1f} (CPU)")
    assert n == rows


if __name__ == "__main__":
    main()
