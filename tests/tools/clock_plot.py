#!/usr/bin/python3
"""Writes docs/clock-rates.svg: the rates of change of the circular error and
of the impulse error (impulse toward equilibrium at 0.9 of the swing, Q = 1e3,
1e4, 1e5) against the semi-amplitude, for Feinstein's 1-second pendulum. Every
point is what `pendulum-g clock` prints for data/feinstein_2005_clock.json
with the semi-amplitude and Q replaced; where a Q's curve crosses the circular
error's, the two rates cancel (Feinstein Sec. IX).

Run from the repository root:  /usr/bin/python3 tests/tools/clock_plot.py build/cli/pendulum-g
"""
import json
import math
import subprocess
import sys

EXE = sys.argv[1] if len(sys.argv) > 1 else "build/cli/pendulum-g"
BASE = json.load(open("data/feinstein_2005_clock.json"))
AMPLITUDES = [30 * 2 ** (i / 4) for i in range(21)]  # 30' to 960'
QS = [1e3, 1e4, 1e5]


def clock(minutes, q):
    scene = dict(BASE, semi_amplitude={"value": minutes, "unit": "arcmin"}, Q=q)
    out = subprocess.run([EXE, "clock", "-"], input=json.dumps(scene), capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


circular = [clock(a, 1e4)["circular_error_rate"]["value"] for a in AMPLITUDES]
impulse = {q: [-clock(a, q)["impulse_error_rate"]["value"] for a in AMPLITUDES] for q in QS}
cancel = {q: clock(240, q)["cancelling_semi_amplitude"]["value"] for q in QS}

W, H, L, R, T, B = 560, 380, 70, 150, 20, 45
X0, X1, Y0, Y1 = 30, 960, 1e-5, 1


def x(a):
    return L + (W - L - R) * math.log(a / X0) / math.log(X1 / X0)


def y(v):
    return T + (H - T - B) * (1 - math.log(v / Y0) / math.log(Y1 / Y0))


def polyline(values, colour, dash=""):
    points = " ".join(f"{x(a):.1f},{y(v):.1f}" for a, v in zip(AMPLITUDES, values))
    return f"<polyline points='{points}' fill='none' stroke='{colour}' stroke-width='2' {dash}/>\n"


svg = [f"<svg xmlns='http://www.w3.org/2000/svg' width='{W}' height='{H}' font-family='sans-serif' font-size='11'>\n",
       "<rect width='100%' height='100%' fill='white'/>\n"]
for a in (30, 60, 120, 240, 480, 960):
    svg.append(f"<line x1='{x(a):.1f}' y1='{T}' x2='{x(a):.1f}' y2='{H - B}' stroke='#ddd'/>"
               f"<text x='{x(a):.1f}' y='{H - B + 14}' text-anchor='middle'>{a}</text>\n")
for p in range(-5, 1):
    svg.append(f"<line x1='{L}' y1='{y(10 ** p):.1f}' x2='{W - R}' y2='{y(10 ** p):.1f}' stroke='#ddd'/>"
               f"<text x='{L - 5}' y='{y(10 ** p) + 4:.1f}' text-anchor='end'>1e{p}</text>\n")
svg.append(f"<text x='{(L + W - R) / 2}' y='{H - 8}' text-anchor='middle'>semi-amplitude (arc minutes)</text>\n")
svg.append(f"<text transform='translate(14,{(T + H - B) / 2}) rotate(-90)' text-anchor='middle'>"
           "rate of change (s/day per arc second)</text>\n")
svg.append(polyline(circular, "black"))
svg.append(f"<text x='{W - R + 6}' y='{y(circular[-1]) + 4:.1f}'>circular error (E-4)</text>\n")
for q, colour in zip(QS, ("#c0392b", "#2471a3", "#229954")):
    svg.append(polyline(impulse[q], colour, "stroke-dasharray='5,3'"))
    svg.append(f"<text x='{W - R + 6}' y='{y(impulse[q][-1]) + 4:.1f}' fill='{colour}'>impulse, Q = {q:g}</text>\n")
    if cancel[q] is not None and X0 <= cancel[q] <= X1:
        c = 0.5 * (clock(cancel[q], q)["circular_error_rate"]["value"] - clock(cancel[q], q)["impulse_error_rate"]["value"])
        svg.append(f"<circle cx='{x(cancel[q]):.1f}' cy='{y(c):.1f}' r='4' fill='{colour}'/>\n")
svg.append(f"<text x='{L + 8}' y='{H - B - 8}'>impulse toward equilibrium at 0.9 of the swing (minus its rate)</text>\n")
svg.append("</svg>\n")
open("docs/clock-rates.svg", "w").write("".join(svg))
for q in QS:
    print(f"Q = {q:g}: rates cancel at {cancel[q]:.2f} arcmin")
