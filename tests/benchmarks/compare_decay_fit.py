#!/usr/bin/python3
"""pendulum-g's decay fit against scipy.optimize.curve_fit, in one run.

Usage (Debian's python3 with python3-scipy):
    /usr/bin/python3 tests/benchmarks/compare_decay_fit.py build/tests/benchmarks/bench_decay_fit

Runs bench_decay_fit (Google Benchmark, 7 repetitions, medians), exports its
data sets and fitted values, times curve_fit on the same data (median of
repeated fits, started at the truth, sigma given with absolute_sigma=True,
Levenberg-Marquardt without bounds, default tolerances), and prints a
markdown table: median time per fit, the ratio scipy/pendulum-g, how far our
fit is from the truth in its own standard uncertainties, and the relative
difference of the two optima, with scipy at its default tolerances (it stops
at a relative change of 1.5e-8) and converged to 1e-15.
"""
import json
import subprocess
import sys
import tempfile

import numpy as np
import scipy
from scipy.optimize import curve_fit

from peer_timing import benchmark_medians, median_time


def eq25(t, alpha, beta, theta0m):
    e = np.exp(-alpha * t)
    return alpha * theta0m * e / (beta * theta0m * (1.0 - e) + alpha)


def main():
    bench = sys.argv[1]
    ours = benchmark_medians(bench)
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([bench, "--export", tmp], check=True)
        fits = json.load(open(tmp + "/fits.json"))
        print(f"scipy {scipy.__version__}, numpy {np.__version__}; medians in ms\n")
        print("| points | pendulum-g | textbook Ceres | scipy curve_fit | scipy / pendulum-g "
              "| pendulum-g (α, β) − truth in σ | scipy − pendulum-g, relative (α, β) "
              "| same, scipy converged |")
        print("|---:|---:|---:|---:|---:|---|---|---|")
        for f in fits:
            n = f["points"]
            t, y, s = np.loadtxt(f"{tmp}/decay_{n}.csv", delimiter=",", unpack=True)
            truth = f["truth"]
            p0 = [truth["alpha"], truth["beta"], truth["theta0m"]]
            fit = lambda: curve_fit(eq25, t, y, p0=p0, sigma=s, absolute_sigma=True)
            popt, _ = fit()
            t_scipy = median_time(fit)
            t_ours = ours[("BM_PendulumFit", n)]
            t_text = ours[("BM_TextbookCeres", n)]
            za = (f["alpha"] - truth["alpha"]) / f["alpha_uncertainty"]
            zb = (f["beta"] - truth["beta"]) / f["beta_uncertainty"]
            da = popt[0] / f["alpha"] - 1
            db = popt[1] / f["beta"] - 1
            tight, _ = curve_fit(eq25, t, y, p0=p0, sigma=s, absolute_sigma=True,
                                 ftol=1e-15, xtol=1e-15, gtol=1e-15, maxfev=100000)
            ta = tight[0] / f["alpha"] - 1
            tb = tight[1] / f["beta"] - 1
            print(f"| {n} | {t_ours*1e3:.4f} | {t_text*1e3:.4f} | {t_scipy*1e3:.4f} | {t_scipy/t_ours:.1f} "
                  f"| {za:+.2f}, {zb:+.2f} | {da:+.1e}, {db:+.1e} | {ta:+.1e}, {tb:+.1e} |")


if __name__ == "__main__":
    main()
