#!/usr/bin/env python3
"""Fits the Cephes-style K(m) = P(x) - ln(x) Q(x), x = 1 - m, with P and Q of
degree 10, used only as a peer in bench_amplitude.cpp. Weighted least squares
on the relative error of K at Chebyshev points of [0, 1] and log-spaced points
down to x = 1e-16 (where K -> ln 4 - ln(x)/2), solved with 60 digits
(mpmath, Debian python3-mpmath). Prints the C++ coefficient arrays and the
largest relative error of the fit on a finer grid.
Run: python3 tests/benchmarks/fit_ellpk.py"""
from mpmath import mp, mpf, ellipk, log, cos, pi, matrix, lu_solve, nstr

mp.dps = 60
DEGREE = 10
xs = [(1 - cos((2 * i + 1) * pi / 800)) / 2 for i in range(400)]
xs += [mpf(10) ** (-16 + 14 * i / 199) for i in range(200)]
rows, rhs = [], []
for x in xs:
    k = ellipk(1 - x)
    lx = log(x)
    rows.append([x ** j / k for j in range(DEGREE + 1)] + [-lx * x ** j / k for j in range(DEGREE + 1)])
    rhs.append(mpf(1))
n = 2 * (DEGREE + 1)
ata = matrix(n, n)
atb = matrix(n, 1)
for r, b in zip(rows, rhs):
    for i in range(n):
        atb[i] += r[i] * b
        for j in range(n):
            ata[i, j] += r[i] * r[j]
c = lu_solve(ata, atb)
p = [c[i] for i in range(DEGREE + 1)]
q = [c[DEGREE + 1 + i] for i in range(DEGREE + 1)]
worst = 0
for i in range(2001):
    x = mpf(10) ** (-16 * (1 - i / 2000)) if i < 1000 else mpf(i - 1000) / 1000
    if x == 0:
        continue
    k = ellipk(1 - x)
    fit = sum(pj * x ** j for j, pj in enumerate(p)) - log(x) * sum(qj * x ** j for j, qj in enumerate(q))
    worst = max(worst, abs(fit / k - 1))
print("// P, lowest power first")
print(",\n".join(nstr(v, 20) for v in p))
print("// Q")
print(",\n".join(nstr(v, 20) for v in q))
print("// largest relative error of the fit:", nstr(worst, 3))
