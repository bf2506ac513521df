#!/usr/bin/python3
"""pendulum-g's series fit against scipy.optimize.curve_fit, in one run.

Usage (Debian's python3 with python3-scipy):
    /usr/bin/python3 tests/benchmarks/compare_series_fit.py build/tests/benchmarks/bench_series_fit

Runs bench_series_fit (Google Benchmark, 7 repetitions, medians of CPU
time), exports its data sets and fitted values, times curve_fit on the same
data and the same model (T = 2 pi sqrt((L + offset)/g) (1 + theta0^2/16),
sigma given with absolute_sigma=True, Levenberg-Marquardt, the same start,
default tolerances; median CPU time of repeated fits), once as it is mostly
called (forward-difference Jacobian) and once given the model's exact
Jacobian, and prints a markdown table: median time per fit, the ratios
scipy/pendulum-g, the relative difference of the optima, and how far each
optimum is from the exact one: the Gauss-Newton step to it from there,
computed in long double (x87, 64-bit mantissa), in units of each parameter's
standard uncertainty (the largest of g and the offset).
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


def jacobian(x, g, offset):
    length, _ = x
    period = model(x, g, offset)
    return np.stack([-0.5 * period / g, 0.5 * period / (length + offset)], axis=1)


def sigmas_from_optimum(x, period, sigma, p):
    """|Gauss-Newton step to the optimum| / standard uncertainty, largest over the parameters."""
    length, theta0 = (np.asarray(a, dtype=np.longdouble) for a in x)
    t, s = np.asarray(period, dtype=np.longdouble), np.asarray(sigma, dtype=np.longdouble)
    g, offset = (np.longdouble(v) for v in p)
    m = 2 * np.pi * np.longdouble(1) * np.sqrt((length + offset) / g) * (1 + theta0 * theta0 / 16)
    j = np.stack([-0.5 * m / g, 0.5 * m / (length + offset)], axis=1) / s[:, None]
    jtj, jtr = j.T @ j, j.T @ ((m - t) / s)
    step = np.linalg.solve(jtj.astype(float), jtr.astype(float))
    return float(np.max(np.abs(step) / np.sqrt(np.diag(np.linalg.inv(jtj.astype(float))))))


def main():
    bench = sys.argv[1]
    ours = {n: t for (_, n), t in benchmark_medians(bench, "cpu_time").items()}
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([bench, "--export", tmp], check=True)
        fits = json.load(open(tmp + "/fits.json"))
        print(f"scipy {scipy.__version__}, numpy {np.__version__}; medians of CPU time in ms\n")
        print("| observations | pendulum-g | curve_fit | curve_fit / pendulum-g "
              "| curve_fit, exact Jacobian | that / pendulum-g "
              "| curve_fit − pendulum-g, relative (g, offset) | same, exact Jacobian "
              "| from the optimum, in σ: pendulum-g, curve_fit, exact Jacobian |")
        print("|---:|---:|---:|---:|---:|---:|---|---|---|")
        for f in fits:
            n = f["observations"]
            length, theta0, period, sigma = np.loadtxt(f"{tmp}/series_{n}.csv", delimiter=",", unpack=True)
            x = (length, theta0)
            common = dict(p0=f["start"], sigma=sigma, absolute_sigma=True)
            fit = lambda: curve_fit(model, x, period, **common)
            fit_exact = lambda: curve_fit(model, x, period, jac=jacobian, **common)
            popt, exact = fit()[0], fit_exact()[0]
            t_scipy = median_time(fit, time.process_time)
            t_exact = median_time(fit_exact, time.process_time)
            ours_p = (f["g"], f["length_offset"])
            d = (popt[0] / ours_p[0] - 1, popt[1] / ours_p[1] - 1)
            e = (exact[0] / ours_p[0] - 1, exact[1] / ours_p[1] - 1)
            far = [sigmas_from_optimum(x, period, sigma, p) for p in (ours_p, popt, exact)]
            print(f"| {n} | {ours[n]*1e3:.4f} | {t_scipy*1e3:.4f} | {t_scipy/ours[n]:.2f} "
                  f"| {t_exact*1e3:.4f} | {t_exact/ours[n]:.2f} "
                  f"| {d[0]:+.1e}, {d[1]:+.1e} | {e[0]:+.1e}, {e[1]:+.1e} "
                  f"| {far[0]:.0e}, {far[1]:.0e}, {far[2]:.0e} |")


if __name__ == "__main__":
    main()
