#!/usr/bin/python3
"""pendulum-g's series fit against scipy.optimize.curve_fit, in one run.

Usage (Debian's python3 with python3-scipy):
    /usr/bin/python3 tests/benchmarks/compare_series_fit.py build/tests/benchmarks/bench_series_fit

Runs bench_series_fit (Google Benchmark, 7 repetitions, medians of CPU
time), exports its data sets and fitted values, times curve_fit on the same
data and the same model (T = 2 pi sqrt((L + offset)/g) (1 + theta0^2/16),
sigma given with absolute_sigma=True, Levenberg-Marquardt, the same start,
default tolerances; median CPU time of repeated fits), and prints a markdown
table: median time per fit, the ratio scipy/pendulum-g, and the relative
difference of the two optima, with scipy at its default tolerances and
converged to 1e-15.
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


def model(x, g, offset):
    length, theta0 = x
    return 2.0 * np.pi * np.sqrt((length + offset) / g) * (1.0 + theta0 * theta0 / 16.0)


def main():
    bench = sys.argv[1]
    ours = {n: t for (_, n), t in benchmark_medians(bench, "cpu_time").items()}
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([bench, "--export", tmp], check=True)
        fits = json.load(open(tmp + "/fits.json"))
        print(f"scipy {scipy.__version__}, numpy {np.__version__}; medians of CPU time in ms\n")
        print("| observations | pendulum-g | scipy curve_fit | scipy / pendulum-g "
              "| scipy − pendulum-g, relative (g, offset) | same, scipy converged |")
        print("|---:|---:|---:|---:|---|---|")
        for f in fits:
            n = f["observations"]
            length, theta0, period, sigma = np.loadtxt(f"{tmp}/series_{n}.csv", delimiter=",", unpack=True)
            x = (length, theta0)
            fit = lambda: curve_fit(model, x, period, p0=f["start"], sigma=sigma, absolute_sigma=True)
            popt, _ = fit()
            t_scipy = median_time(fit, time.process_time)
            tight, _ = curve_fit(model, x, period, p0=f["start"], sigma=sigma, absolute_sigma=True,
                                 ftol=1e-15, xtol=1e-15, gtol=1e-15, maxfev=100000)
            d = (popt[0] / f["g"] - 1, popt[1] / f["length_offset"] - 1)
            c = (tight[0] / f["g"] - 1, tight[1] / f["length_offset"] - 1)
            print(f"| {n} | {ours[n]*1e3:.4f} | {t_scipy*1e3:.4f} | {t_scipy/ours[n]:.2f} "
                  f"| {d[0]:+.1e}, {d[1]:+.1e} | {c[0]:+.1e}, {c[1]:+.1e} |")


if __name__ == "__main__":
    main()
