#!/usr/bin/python3
"""Checks that the library's includes run one way: down (docs/core.md, "Layers").

A unit is a folder of lib/src (json/, recordings/, report/, ...) or a file of lib/src with its
public header (analysis.cpp with pendulum/analysis.hpp); the public headers that no .cpp of
the same path defines are the ground: the physics and its types, which every unit may use.
An include is an arrow from its file's unit to the included file's unit. The rules:
  1. the arrows between units, those into the ground left out, form no circle;
  2. the ground includes only the ground and units that reach no ground header themselves.
So each unit stands above all it uses, and nothing below calls up. The includes that break a
rule today are listed in KNOWN, by file and the unit it includes, with the reason and the
step that removes them; an entry that no longer breaks a rule fails the check too, so the
list only shrinks. A quoted include that names no file of lib/, and an include of a
pendulum/ header in angle brackets, fail: the check would not see where they lead.

Usage: check_layers.py SOURCE_DIR
"""
import os
import re
import sys

# (from file, to unit): why it is there, and what removes it.
KNOWN = {
    ("lib/include/pendulum/models/registry.hpp", "models/"):
        "the list of kinds is a ground header because Analysis carries ModelResults, a variant over the "
        "kinds' results; through it lower units call the kinds, whose files include analysis.hpp, "
        "plausibility.hpp and the JSON toolkit: issue 41, item 1",
}


def files(source):
    out = []
    for top in ("lib/src", "lib/include"):
        for folder, _, names in os.walk(os.path.join(source, top)):
            out += [os.path.relpath(os.path.join(folder, n), source) for n in names if n.endswith((".hpp", ".cpp", ".h"))]
    return sorted(out)


def units(all_files):
    defined = {os.path.splitext(os.path.relpath(f, "lib/src"))[0] for f in all_files
               if f.startswith("lib/src/") and f.endswith(".cpp")}

    def unit(path):
        if path.startswith("lib/src/"):
            rel = os.path.relpath(path, "lib/src")
            return rel.split("/")[0] + "/" if "/" in rel else os.path.splitext(rel)[0]
        rel = os.path.splitext(os.path.relpath(path, "lib/include/pendulum"))[0]
        if rel in defined:
            return rel.split("/")[0] + "/" if "/" in rel else rel
        return "ground"
    return unit


def includes(source, path, all_files, unresolved):
    here = os.path.dirname(path)
    text = open(os.path.join(source, path), encoding="utf-8", errors="replace").read()
    for name in re.findall(r'^\s*#\s*include\s+<(pendulum/[^>]+)>', text, re.M):
        unresolved.append(f"{path} includes <{name}>: write it in quotes, as the others")
    for name in re.findall(r'^\s*#\s*include\s+"([^"]+)"', text, re.M):
        for candidate in (os.path.normpath(os.path.join(here, name)), "lib/include/" + name):
            if candidate in all_files:
                yield candidate
                break
        else:
            unresolved.append(f'{path} includes "{name}", no file of lib/')


def main(source):
    all_files = files(source)
    unit = units(all_files)
    arrows = {}  # (from unit, to unit) -> [(from file, to file)]
    unresolved = []
    for f in all_files:
        for g in includes(source, f, all_files, unresolved):
            a, b = unit(f), unit(g)
            if a != b:
                arrows.setdefault((a, b), []).append((f, g))
    known_seen = set()
    broken = []

    def report(pair, why):
        key = (pair[0], unit(pair[1]))
        if key in KNOWN:
            known_seen.add(key)
        else:
            broken.append(f"{pair[0]} includes {pair[1]}: {why}")

    # Rule 2: what the ground includes must reach no ground header.
    drawn = {}
    for (a, b), pairs in arrows.items():
        if b != "ground":
            drawn.setdefault(a, set()).add(b)

    def reaches_ground(u, seen):
        if u in seen:
            return False
        seen.add(u)
        return any(b == "ground" for (a, b) in arrows if a == u) or any(reaches_ground(v, seen) for v in drawn.get(u, ()))

    for (a, b), pairs in arrows.items():
        if a == "ground" and reaches_ground(b, set()):
            for pair in pairs:
                report(pair, f"a ground header includes {b}, which uses the ground itself")

    # Rule 1: no circle among the units (Tarjan's strongly connected components).
    index, low, stack, on, counter = {}, {}, [], set(), [0]

    def connect(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in drawn.get(v, ()):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            circle = set()
            while True:
                w = stack.pop()
                on.discard(w)
                circle.add(w)
                if w == v:
                    break
            if len(circle) > 1:
                for (a, b), pairs in arrows.items():
                    if a in circle and b in circle:
                        for pair in pairs:
                            report(pair, "in a circle of " + ", ".join(sorted(circle)))

    for v in sorted(drawn):
        if v not in index:
            connect(v)
    stale = [f"{a} -> {b}: listed in KNOWN but no longer breaks a rule; remove it" for (a, b) in KNOWN
             if (a, b) not in known_seen]
    for line in unresolved + broken + stale:
        print(line)
    print(f"{len(all_files)} files in {len({unit(f) for f in all_files})} units, "
          f"{sum(len(p) for p in arrows.values())} includes between units; "
          f"{len(unresolved)} unresolved, {len(broken) + len(stale)} against the layers, "
          f"{len(known_seen)} known (KNOWN)")
    return 1 if unresolved or broken or stale else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
