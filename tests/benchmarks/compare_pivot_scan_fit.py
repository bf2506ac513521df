#!/usr/bin/python3
"""pendulum-g's pivot-scan fit against scipy.optimize.curve_fit, in one run.

Usage (Debian's python3 with python3-scipy):
    /usr/bin/python3 tests/benchmarks/compare_pivot_scan_fit.py build/tests/benchmarks/bench_pivot_scan_fit

Runs bench_pivot_scan_fit (Google Benchmark, 7 repetitions, medians of CPU
time), exports its data sets, starts and fitted values, times curve_fit on the
same data and the same model (T = 2 pi sqrt((k^2 + h^2)/(g h)) (1 + theta0^2/16),
h = |x - x_c|; sigma given with absolute_sigma=True, Levenberg-Marquardt, the
same start, default tolerances; median CPU time of repeated fits), and prints a
markdown table: median time per fit, the ratio scipy/pendulum-g, and the
largest relative difference of the two optima's parameters.
"""
import json
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy
from scipy.optimize import curve_fit

from peer_timing import benchmark_medians, median_time


def model(x, g, k, center):
    position, theta0 = x
    h = np.abs(position - center)
    return 2.0 * np.pi * np.sqrt((k * k + h * h) / (g * h)) * (1.0 + theta0 * theta0 / 16.0)


def main():
    bench = sys.argv[1]
    ours = {n: t for (_, n), t in benchmark_medians(bench, "cpu_time").items()}
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([bench, "--export", tmp], check=True)
        fits = json.load(open(tmp + "/fits.json"))
        print(f"scipy {scipy.__version__}, numpy {np.__version__}; medians of CPU time in ms\n")
        print("| observations | pendulum-g | scipy curve_fit | scipy / pendulum-g "
              "| scipy − pendulum-g, largest relative (g, k, x_c) |")
        print("|---:|---:|---:|---:|---|")
        for f in fits:
            n = f["observations"]
            position, theta0, period, sigma = np.loadtxt(f"{tmp}/scan_{n}.csv", delimiter=",", unpack=True)
            x = (position, theta0)
            fit = lambda: curve_fit(model, x, period, p0=f["start"], sigma=sigma, absolute_sigma=True)
            popt, _ = fit()
            t_scipy = median_time(fit, time.process_time)
            d = np.max(np.abs(popt / np.array(f["parameters"]) - 1))
            print(f"| {n} | {ours[n]*1e3:.4f} | {t_scipy*1e3:.4f} | {t_scipy/ours[n]:.2f} | {d:.1e} |")


if __name__ == "__main__":
    main()
