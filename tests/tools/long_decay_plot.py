#!/usr/bin/python3
"""Writes docs/long-decay.svg: the error of g, in its own standard uncertainties,
of each way of reducing a long decay (docs/recordings.md, "A long decay, swing
by swing") against the start amplitude, each way's cost in its label. Every
point is a row of one run of the benchmark:

    build/tests/benchmarks/bench_long_decay --benchmark_min_time=0.05 \\
        --benchmark_format=json > long_decay.json

Run from the repository root:  /usr/bin/python3 tests/tools/long_decay_plot.py long_decay.json
"""
import json
import math
import re
import sys

METHODS = [("(a) start amplitude, no decay correction", "#c0392b"),
           ("(a') start amplitude with Eq. 50", "#e67e22"),
           ("(b) mean amplitude", "#2471a3"),
           ("(c) swing by swing", "#229954")]

rows = {}  # (start in deg, method): (|error| in sigmas, CPU time in us), None where refused
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    m = re.match(r"BM_Reduce/start_deg:(\d+)/method:(\d)$", b["name"])
    if m:
        key = (int(m.group(1)), int(m.group(2)))
        rows[key] = None if b.get("error_occurred") else (abs(b["g_error_sigma"]), b["cpu_time"])
starts = sorted({s for s, _ in rows})

W, H, L, R, T, B = 620, 380, 60, 250, 20, 45
Y0, Y1 = 0.01, 1e4


def x(deg):
    return L + (W - L - R) * deg / 90.0


def y(v):
    v = min(max(v, Y0), Y1)
    return T + (H - T - B) * (1 - math.log(v / Y0) / math.log(Y1 / Y0))


svg = [f"<svg xmlns='http://www.w3.org/2000/svg' width='{W}' height='{H}' font-family='sans-serif' font-size='11'>\n",
       "<rect width='100%' height='100%' fill='white'/>\n"]
for deg in range(0, 91, 15):
    svg.append(f"<line x1='{x(deg):.1f}' y1='{T}' x2='{x(deg):.1f}' y2='{H - B}' stroke='#ddd'/>"
               f"<text x='{x(deg):.1f}' y='{H - B + 14}' text-anchor='middle'>{deg}</text>\n")
for p in range(-2, 5):
    svg.append(f"<line x1='{L}' y1='{y(10 ** p):.1f}' x2='{W - R}' y2='{y(10 ** p):.1f}' stroke='#ddd'/>"
               f"<text x='{L - 5}' y='{y(10 ** p) + 4:.1f}' text-anchor='end'>{10 ** p:g}</text>\n")
svg.append(f"<line x1='{L}' y1='{y(2):.1f}' x2='{W - R}' y2='{y(2):.1f}' stroke='black' stroke-dasharray='4,3'/>"
           f"<text x='{L + 4}' y='{y(2) - 4:.1f}'>2 sigma</text>\n")
svg.append(f"<text x='{(L + W - R) / 2}' y='{H - 8}' text-anchor='middle'>start amplitude (deg)</text>\n")
svg.append(f"<text transform='translate(14,{(T + H - B) / 2}) rotate(-90)' text-anchor='middle'>"
           "|g - truth| in its own standard uncertainties</text>\n")
for method, (label, colour) in enumerate(METHODS):
    points = [(s, rows[(s, method)]) for s in starts if rows.get((s, method))]
    svg.append("<polyline points='" + " ".join(f"{x(s):.1f},{y(e):.1f}" for s, (e, _) in points) +
               f"' fill='none' stroke='{colour}' stroke-width='2'/>\n")
    for s, (e, _) in points:
        svg.append(f"<circle cx='{x(s):.1f}' cy='{y(e):.1f}' r='3' fill='{colour}'/>\n")
    costs = [c for _, (_, c) in points]
    refused = [s for s in starts if (s, method) in rows and rows[(s, method)] is None]
    text = f"{label}: {min(costs):.0f}-{max(costs):.0f} us" + (f" (refused at {refused[0]} deg)" if refused else "")
    svg.append(f"<text x='{W - R + 8}' y='{T + 14 + 40 * method}' fill='{colour}'>"
               + "".join(f"<tspan x='{W - R + 8}' dy='{0 if i == 0 else 13}'>{part}</tspan>"
                         for i, part in enumerate(text.split(": "))) + "</text>\n")
svg.append("</svg>\n")
open("docs/long-decay.svg", "w").write("".join(svg))
