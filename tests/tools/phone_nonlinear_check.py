#!/usr/bin/env python3
"""A body on a string at finite amplitude: pendulum-g's model against the full equations of motion.

pendulum-g times a phone (or any bob) on a string as the slow normal mode of the
small-oscillation double pendulum (lib/include/pendulum/mass.hpp, slow_mode). At finite
amplitude it took the body's amplitude psi0, converted it to the angle of the line
pivot -> centre, theta0 = c psi0 (c = slow_mode_line_over_body, the eigenvector's ratio),
and multiplied the slow mode's period by a simple pendulum's 2K(sin(theta0/2))/pi: T_c
below. It now takes the mode's own series in psi0 (kappas() below; mass.hpp,
slow_mode_amplitude_series; corrections.hpp, slow_mode_finite_amplitude): T_pg. This
script checks both against the exact planar
equations of motion of a massless, inextensible, taut string of length s (angle phi)
and a rigid body (mass m, radius of gyration k about its centre, centre d below the
knot, angle psi):

    s^2 phi'' + s d cos(phi-psi) psi'' + s d sin(phi-psi) psi'^2 + g s sin(phi) = 0
    s d cos(phi-psi) phi'' + (d^2+k^2) psi'' - s d sin(phi-psi) phi'^2 + g d sin(psi) = 0

(Lagrange's equations of T = m/2 [s^2 phi'^2 + (d^2+k^2) psi'^2 + 2 s d phi' psi' cos(phi-psi)],
V = -m g (s cos phi + d cos psi)), integrated with scipy's DOP853 at rtol 1e-12.

The slow mode at finite amplitude is its nonlinear normal mode: released from rest at
(phi0, psi0), phi0 = r psi0, with r found by shooting (brentq) so that phi and psi cross
zero at the same instant t*. The equations are invariant under (phi, psi) -> -(phi, psi)
and under time reversal, so such an orbit is periodic with period T = 4 t* and contains
no fast mode beyond what the slow one drives; the script checks that by integrating a
whole period (return to the start) and by timing 5 periods from interpolated zero
crossings of psi, and checks that the string stays taut. theta is the angle of the line
pivot -> centre, atan2(s sin phi + d sin psi, s cos phi + d cos psi); theta_max/psi_max
of the orbit is theta(0)/psi0.

It also evaluates the perturbation series of the mode's period in the body's amplitude,
T = T_slow (1 + kappa2 psi0^2 + kappa4 psi0^4 + ...), from the averaged Lagrangian with
the mode's first and third harmonics (closed form in kappas() below), against T_c's
c^2/16 and (11/3072) c^4.

Usage: python3 tests/tools/phone_nonlinear_check.py [--scan] [path/to/pendulum-g]
--scan instead prints what the series leaves, (T_nl/T_pg - 1)/psi0^6, over four bodies and
strings of 0.1-2 m beside the modes' frequency ratio: beyond the psi0^4 term the series also
fails near the 5:1 and 7:1 resonances, which kappa4 does not see (docs/phone.md).
With the CLI's path it also reduces one scene per string length (the phone, amplitude
of the body) whose trials are this script's T_pg, and prints g back, which is standard
gravity if the code does what the formulas say.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import ellipk

G = 9.80665
RTOL, ATOL = 1e-12, 1e-14


def rhs(t, y, s, d, k2):
    phi, psi, dphi, dpsi = y
    c, sn = np.cos(phi - psi), np.sin(phi - psi)
    a11, a12, a22 = s * s, s * d * c, d * d + k2
    b1 = -s * d * sn * dpsi ** 2 - G * s * np.sin(phi)
    b2 = s * d * sn * dphi ** 2 - G * d * np.sin(psi)
    det = a11 * a22 - a12 * a12
    return [dphi, dpsi, (a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det]


def tension_over_mg(y, s, d, k2):
    """The string's tension over m g along a trajectory (rows of y: phi, psi, phi', psi')."""
    phi, psi, dphi, dpsi = y
    acc = np.array([rhs(0, yy, s, d, k2) for yy in y.T]).T
    ddphi, ddpsi = acc[2], acc[3]
    # the centre's acceleration
    ax = s * (ddphi * np.cos(phi) - dphi ** 2 * np.sin(phi)) + d * (ddpsi * np.cos(psi) - dpsi ** 2 * np.sin(psi))
    ay = s * (ddphi * np.sin(phi) + dphi ** 2 * np.cos(phi)) + d * (ddpsi * np.sin(psi) + dpsi ** 2 * np.cos(psi))
    fx, fy = ax, ay + G  # string force on the body per unit mass
    return (-fx * np.sin(phi) + fy * np.cos(phi)) / G


def slow_mode(s, d, k2):
    """lambda = omega^2/g of the slow mode, phi/psi = a, theta/psi = c (mass.hpp)."""
    l = s + d
    b = d * l + k2
    lam = 2 * d / (b + np.sqrt(b * b - 4 * s * d * k2))
    a = lam * d / (1 - lam * s)
    return lam, a, (s * a + d) / l


def kappas(s, d, k2):
    """T/T_slow = 1 + kappa2 psi0^2 + kappa4 psi0^4 + O(psi0^6), psi0 the body's amplitude.

    Per unit mass and g, with tau = omega t, Om = omega^2/g, Om0 = lambda, and the trial orbit
    (phi, psi) = A v cos(tau) + A^3 [(u, 0) cos(tau) + w cos(3 tau)], v = (a, 1), the averaged
    Lagrangian <L> (stationary on a periodic orbit of fixed period) is
      A^2 (Om P - Q)/4 + A^4 [L4 + u P1 (Om - Om0)/2] + A^6 [L6 + w.f + w.H w/2 + u^2 c'/4 + b u],
      P = v.Mv, Q = s a^2 + d, P1 = s^2 a + s d, M = [[s^2, s d], [s d, d^2+k^2]], K = diag(s, d),
      L4 = (s a^4 + d)/64 - Om s d a (a-1)^2/16,  L6 = Om s d a (a-1)^4/384 - (s a^6 + d)/2304,
      H = (9 Om M - K)/2,  f = (s a^3/48 - Om s d (a-1)(a-3)/16,  d/48 - Om s d a (a-1)(3a-1)/16),
      c' = Om s^2 - s,  b = s a^3/16 - Om s d (a-1)(3a-1)/16.
    Stationary in w (w = -H^-1 f), u (u = -(Om2 P1 + 2 b)/c') and A, with Om = Om0 + Om2 A^2 +
    Om4 A^4: Om2 = -8 L4/P (kappa2 = -Om2/(2 Om0), exactly (s a^4 + d - 4 lambda s d a (a-1)^2) /
    (16 (s a^2 + d))), and psi0 = A + A^3 w_2. The point bob (a = 1) gives 1/16 and 11/3072.
    """
    lam, a, _ = slow_mode(s, d, k2)
    om = lam
    m = np.array([[s * s, s * d], [s * d, d * d + k2]])
    kk = np.diag([s, d])
    p = a * a * s * s + 2 * a * s * d + d * d + k2
    l4 = (s * a ** 4 + d) / 64 - om * s * d * a * (a - 1) ** 2 / 16
    dl4 = -s * d * a * (a - 1) ** 2 / 16
    f = np.array([s * a ** 3 / 48 - om * s * d * (a - 1) * (a - 3) / 16,
                  d / 48 - om * s * d * a * (a - 1) * (3 * a - 1) / 16])
    h = (9 * om * m - kk) / 2
    w = -np.linalg.solve(h, f)
    l6 = om * s * d * a * (a - 1) ** 4 / 384 - (s * a ** 6 + d) / 2304 + 0.5 * f @ w
    om2 = -8 * l4 / p
    p1, b, cp = s * s * a + s * d, s * a ** 3 / 16 - om * s * d * (a - 1) * (3 * a - 1) / 16, om * s * s - s
    u = -(om2 * p1 + 2 * b) / cp
    shape = om2 * p1 * u + 0.75 * cp * u * u + 3 * b * u  # the first harmonic's change of shape
    om4 = -(8 * om2 * dl4 + 12 * l6 + 4 * shape) / p
    x2, x4 = om2 / om, (om4 - 2 * w[1] * om2) / om
    return -x2 / 2, 3 * x2 * x2 / 8 - x4 / 2


def first_zero(r, psi0, s, d, k2, t_end):
    def ev(t, y, *args):
        return y[1]
    ev.terminal, ev.direction = True, -1
    sol = solve_ivp(rhs, (0, t_end), [r * psi0, psi0, 0, 0], method='DOP853', rtol=RTOL, atol=ATOL,
                    args=(s, d, k2), events=ev)
    return sol.t_events[0][0], sol.y_events[0][0]


def nonlinear_mode(psi0, s, d, k2):
    """The slow mode's periodic orbit at body amplitude psi0: phi0/psi0, period, checks."""
    lam, a, _ = slow_mode(s, d, k2)
    t_lin = 2 * np.pi / np.sqrt(G * lam)
    r = brentq(lambda r: first_zero(r, psi0, s, d, k2, t_lin)[1][0], 0.9 * a, 1.02 * a, xtol=1e-15, rtol=1e-15)
    tq, _ = first_zero(r, psi0, s, d, k2, t_lin)
    period = 4 * tq
    y0 = np.array([r * psi0, psi0, 0, 0])
    # five periods: return to the start and the period from psi's zero crossings
    def ev(t, y, *args):
        return y[1]
    ev.direction = -1
    sol = solve_ivp(rhs, (0, 5 * period + tq), y0, method='DOP853', rtol=RTOL, atol=ATOL, args=(s, d, k2),
                    events=ev, dense_output=True)
    crossings = sol.t_events[0]
    period_zc = np.polyfit(np.arange(len(crossings)), crossings, 1)[0]
    back = np.max(np.abs(sol.sol(period) - y0) / np.array([psi0, psi0, psi0 * np.sqrt(G * lam), psi0 * np.sqrt(G * lam)]))
    ts = np.linspace(0, period, 400)
    ys = sol.sol(ts)
    theta = np.arctan2(s * np.sin(ys[0]) + d * np.sin(ys[1]), s * np.cos(ys[0]) + d * np.cos(ys[1]))
    tension = tension_over_mg(ys, s, d, k2).min()
    return dict(r=r, period=period, period_zc=period_zc, back=back,
                theta_over_psi=np.max(np.abs(theta)) / np.max(np.abs(ys[1])), tension=tension)


def release_on_linear_ratio(psi0, s, d, k2, periods=10):
    """Released from rest at the small-oscillation ratio: mean period from psi's zero crossings."""
    lam, a, _ = slow_mode(s, d, k2)
    t_lin = 2 * np.pi / np.sqrt(G * lam)
    def ev(t, y, *args):
        return y[1]
    ev.direction = -1
    sol = solve_ivp(rhs, (0, (periods + 0.3) * t_lin), [a * psi0, psi0, 0, 0], method='DOP853', rtol=RTOL,
                    atol=ATOL, args=(s, d, k2), events=ev)
    t = sol.t_events[0]
    return (t[-1] - t[0]) / (len(t) - 1)


def amplitude_factor(theta0):
    return 2 * ellipk(np.sin(theta0 / 2) ** 2) / np.pi


def line_period(psi0, s, d, k2):
    """T_c, pendulum-g before: the slow mode's period times 2K(sin(theta0/2))/pi, theta0 = c psi0."""
    lam, _, c = slow_mode(s, d, k2)
    return 2 * np.pi / np.sqrt(G * lam) * amplitude_factor(c * psi0)


def pendulum_g_period(psi0, s, d, k2):
    """T_pg: theta0 = 4 sqrt(kappa2) psi0 in the factor, and the rest of kappa4 (slow_mode_finite_amplitude)."""
    lam, _, c = slow_mode(s, d, k2)
    k2_, k4_ = kappas(s, d, k2)
    ce = 4 * np.sqrt(k2_)
    return 2 * np.pi / np.sqrt(G * lam) * amplitude_factor(ce * psi0) * (1 + (k4_ - 11 / 3072 * ce ** 4) * psi0 ** 4)


PHONE = dict(name='phone', k2=(0.075 ** 2 + 0.16 ** 2) / 12, d=0.08)   # 7.5 x 16 cm face in its plane
BALL = dict(name='ball', k2=0.4 * 0.0305 ** 2, d=0.0305)                # Nelson & Olsson's 6.10 cm ball
CASES = [(PHONE, s) for s in (0.1, 0.3, 1.0)] + [(BALL, s) for s in (0.1, 0.3, 1.0, 3.0044 - 0.0305)]
AMPLITUDES = (2, 5, 10, 20, 30)


def check_cli(cli):
    """Reduce a phone scene whose trials are pendulum_g_period(); g back must be standard gravity."""
    print('\nThe CLI on the phone (amplitude 10 deg of the body, no air), trials = T_pg:')
    for s in (0.1, 0.3, 1.0):
        period = pendulum_g_period(np.radians(10), s, PHONE['d'], PHONE['k2'])
        scene = {
            "schema": "pendulum-g/scene/1", "title": "nonlinear check",
            "amplitude": {"value": 10, "unit": "deg", "of": "body"},
            "bob": {"shape": "box", "width": {"value": 7.5, "unit": "cm"}, "height": {"value": 16, "unit": "cm"},
                    "depth": {"value": 0.8, "unit": "cm"}, "mass": {"value": 190, "unit": "g"}},
            "length": {"value": s * 100, "uncertainty": 0.01, "unit": "cm", "measured_to": "top_of_bob"},
            "timing": {"oscillations_per_trial": 1, "unit": "s", "resolution": 1e-9,
                       "trials": [round(period, 12)] * 3},
        }
        with tempfile.NamedTemporaryFile('w', suffix='.json', delete=False) as fh:
            json.dump(scene, fh)
        try:
            out = subprocess.run([cli, 'reduce', '--amplitude-method', 'agm', fh.name], capture_output=True, text=True)
        finally:
            os.unlink(fh.name)
        res = json.loads(out.stdout)
        g = res['g']['value'] if isinstance(res.get('g'), dict) else res['g']
        print(f'  s = {s:.1f} m: g = {g:.10f} m/s^2, g/9.80665 - 1 = {g / G - 1:+.1e}')


def frequency_ratio(s, d, k2):
    """The fast mode's frequency over the slow one's (plausibility.cpp, slow_mode_rest)."""
    l = s + d
    b = d * l + k2
    root = np.sqrt(b * b - 4 * s * d * k2)
    return np.sqrt((b + root) ** 2 / (4 * s * d * k2))


SCAN_BODIES = [PHONE, dict(name='side', k2=PHONE['k2'], d=0.0375),          # the phone on its side
               dict(name='can', k2=0.033 ** 2 / 4 + 0.115 ** 2 / 12, d=0.0575),  # 6.6 x 11.5 cm cylinder, upright
               BALL]


def scan():
    print('What the series leaves, (T_nl/T_pg - 1)/psi0^6, and the modes\' frequency ratio (fast/slow);')
    print('coef = kappa4 - (11/3072)(4 sqrt kappa2)^4; "-": no mode within the shooting\'s bracket, phi0/psi0 of')
    print('0.9-1.02 times the small oscillations\'; "?" after a value: the mode failed a check (see the main table)')
    print(f'{"body":5} {"s (m)":>6} {"ratio":>6} {"coef":>10}' + ''.join(f' {d:>7}deg' for d in (5, 10, 20, 30)))
    for body in SCAN_BODIES:
        d, k2 = body['d'], body['k2']
        for s in (0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 1.0, 2.0):
            k2_, k4_ = kappas(s, d, k2)
            coef = k4_ - 11 / 3072 * (4 * np.sqrt(k2_)) ** 4
            cells = []
            for deg in (5, 10, 20, 30):
                psi0 = np.radians(deg)
                try:
                    nm = nonlinear_mode(psi0, s, d, k2)
                    left = nm['period'] / pendulum_g_period(psi0, s, d, k2) - 1
                    ok = nm['back'] < 1e-8 and abs(nm['period_zc'] / nm['period'] - 1) < 1e-10 and nm['tension'] > 0
                    cells.append(f' {left / psi0 ** 6:+9.2e}{" " if ok else "?"}')
                except ValueError:  # brentq: no sign change, no mode
                    cells.append(f' {"-":>10}')
            print(f'{body["name"]:5} {s:6.2f} {frequency_ratio(s, d, k2):6.3f} {coef:+10.3e}' + ''.join(cells),
                  flush=True)


def main():
    if '--scan' in sys.argv:
        scan()
        return
    print(__doc__.split('\n')[0])
    print('T_nl: the nonlinear normal mode\'s period; T_c: the factor at c psi0 alone (pendulum-g before);')
    print('T_pg: the slow mode\'s series in psi0 (pendulum-g);')
    print('T_rel: released from rest at the small-oscillation ratio (mean of 10 periods).\n')
    head = (f'{"body":5} {"s (m)":>6} {"psi0":>4} {"T_nl/T_c-1":>15} {"T_nl/T_pg-1":>14} {"T_rel/T_nl-1":>13}'
            f' {"theta/psi":>10} {"c":>8} {"phi0/psi0":>9} {"checks":>8}')
    print(head)
    print('-' * len(head))
    worst = 0.0
    for body, s in CASES:
        d, k2 = body['d'], body['k2']
        _, a, c = slow_mode(s, d, k2)
        for deg in AMPLITUDES:
            psi0 = np.radians(deg)
            nm = nonlinear_mode(psi0, s, d, k2)
            t_rel = release_on_linear_ratio(psi0, s, d, k2)
            err = nm['period'] / line_period(psi0, s, d, k2) - 1
            err_c = nm['period'] / pendulum_g_period(psi0, s, d, k2) - 1
            ok = nm['back'] < 1e-8 and abs(nm['period_zc'] / nm['period'] - 1) < 1e-10 and nm['tension'] > 0
            print(f'{body["name"]:5} {s:6.3f} {deg:4d} {err:+15.2e} {err_c:+14.1e} {t_rel / nm["period"] - 1:+13.1e}'
                  f' {nm["theta_over_psi"]:10.5f} {c:8.5f} {nm["r"] / a:9.5f} {"ok" if ok else "FAILED":>8}')
            if body is PHONE and deg <= 20:
                worst = max(worst, abs(err_c))
        print()
    print('phi0/psi0 is over the small-oscillation ratio; checks: back at the start after one period to 1e-8,')
    print('5 periods from zero crossings agree to 1e-10, the string taut.\n')

    print('The period as a series in the body\'s amplitude, T/T_slow = 1 + kappa2 psi0^2 + kappa4 psi0^4 + ...')
    print('(closed form: kappas(); fit: the nonlinear mode at psi0 = 1..6 deg, cubic in psi0^2)')
    print(f'{"body":5} {"s (m)":>6} {"kappa2":>10} {"fit":>10} {"c^2/16":>10} {"kappa4":>11} {"fit":>11}'
          f' {"11c^4/3072":>11}')
    for body, s in CASES:
        d, k2 = body['d'], body['k2']
        lam, _, c = slow_mode(s, d, k2)
        t_lin = 2 * np.pi / np.sqrt(G * lam)
        x = np.radians(np.arange(1, 7)) ** 2
        y = [nonlinear_mode(np.sqrt(xx), s, d, k2)['period'] / t_lin - 1 for xx in x]
        fit = np.polyfit(x, y, 3)[::-1]
        k2_, k4_ = kappas(s, d, k2)
        print(f'{body["name"]:5} {s:6.3f} {k2_:10.7f} {fit[1]:10.7f} {c * c / 16:10.7f} {k4_:+11.3e} {fit[2]:+11.3e}'
              f' {11 * c ** 4 / 3072:+11.3e}')
    print(f'\nWorst |T_nl/T_pg - 1| for the phone on 0.1-1 m strings up to 20 deg (of the table): {worst:.1e}')
    if len(sys.argv) > 1:
        check_cli(sys.argv[1])


if __name__ == '__main__':
    main()
