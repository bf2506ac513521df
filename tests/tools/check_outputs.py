#!/usr/bin/python3
"""Compares what pendulum-g prints for every bundled input with the stored outputs.

The JSON output is an API, and a change of the code's layout must not change a byte of it
(docs/core.md, "Changing the core"). This script runs pendulum-g on every bundled scene
(reduce, as JSON and as a table), every bundled recording and table (import, as JSON and as
a table), every template, the class (batch as JSON lines, CSV and a table), the decay fit
and the clock, from the repository root, and compares stdout, stderr and the exit status
with tests/outputs/<case>.txt. The cases are found from data/ and from `template --help`,
so a new bundled file is covered as soon as it is stored. An output showing a negative
uncertainty ("+- -0.00000") fails whatever is stored.

Usage: check_outputs.py [--update] SOURCE_DIR PENDULUM_G
--update rewrites the stored outputs (and removes those of cases that are gone): review the
diff before committing; a change it shows is a change of the API.
"""
import difflib
import glob
import os
import re
import subprocess
import sys


def cases(source, exe):
    def rel(pattern):
        return sorted(os.path.relpath(p, source) for p in glob.glob(os.path.join(source, pattern)))

    scenes = rel("data/*.json") + rel("data/*/*.json")
    files = [p for p in rel("data/recordings/*") if not p.endswith(".json")] + rel("data/*.csv")
    for scene in scenes:
        # The clock's scene is the clock command's, not reduce's.
        if "clock" in os.path.basename(scene):
            yield f"clock {scene}", [exe, "clock", scene]
            continue
        yield f"reduce {scene}", [exe, "reduce", scene]
        yield f"reduce table {scene}", [exe, "reduce", "--format", "table", scene]
        if "decay" in os.path.basename(scene):
            yield f"fit-decay {scene}", [exe, "fit-decay", scene]
    for f in files:
        yield f"import {f}", [exe, "import", f]
        yield f"import table {f}", [exe, "import", "--format", "table", f]
    help_text = subprocess.run([exe, "template", "--help"], capture_output=True, text=True).stdout
    kinds = re.search(r"^Kinds: (.*)\. Example", help_text, re.M).group(1).split(", ")
    for kind in kinds:
        yield f"template {kind}", [exe, "template", kind]
    for fmt in ("jsonl", "csv", "table"):
        yield f"batch {fmt} data/class", [exe, "batch", "--jobs", "1", "--format", fmt, "data/class"]
    for degrees in ("0.5", "10", "90", "179.9"):
        yield f"amplitude {degrees}", [exe, "amplitude", "--theta0-deg", degrees]


def slug(name):
    return re.sub(r"[^A-Za-z0-9.]+", "_", name).strip("_") + ".txt"


def run(argv, source):
    r = subprocess.run(argv, capture_output=True, text=True, cwd=source, timeout=120)
    shown = ["pendulum-g"] + argv[1:]
    return f"$ {' '.join(shown)}\n--- stdout\n{r.stdout}--- stderr\n{r.stderr}--- exit {r.returncode}\n"


def main():
    args = [a for a in sys.argv[1:] if a != "--update"]
    update = "--update" in sys.argv
    if len(args) != 2:
        sys.exit(__doc__)
    source, exe = os.path.abspath(args[0]), os.path.abspath(args[1])
    stored = os.path.join(source, "tests", "outputs")
    os.makedirs(stored, exist_ok=True)
    seen, differ = set(), []
    for name, argv in cases(source, exe):
        path = os.path.join(stored, slug(name))
        seen.add(os.path.basename(path))
        got = run(argv, source)
        # An uncertainty is never negative: no "+- -0.00000" (issue 39), in any output.
        negative = re.search(r"(\+-|\u00b1) *[-\u2212]", got)
        if negative:
            differ.append(name)
            print(f"NEGATIVE UNCERTAINTY {name}: ...{got[max(negative.start() - 60, 0):negative.end() + 20]}...")
            continue
        want = open(path, encoding="utf-8").read() if os.path.exists(path) else None
        if got == want:
            continue
        if update:
            open(path, "w", encoding="utf-8").write(got)
            print(f"updated {os.path.relpath(path, source)}")
            continue
        differ.append(name)
        print(f"DIFFERS {name} ({os.path.relpath(path, source)})")
        print("".join(list(difflib.unified_diff((want or "").splitlines(True), got.splitlines(True),
                                                "stored", "now", n=1))[:40]))
    for gone in sorted(set(os.listdir(stored)) - seen):
        if update:
            os.remove(os.path.join(stored, gone))
            print(f"removed tests/outputs/{gone}")
        else:
            differ.append(gone)
            print(f"DIFFERS {gone}: stored, but no case makes it any more")
    print(f"{len(seen) - len(differ)} passed, {len(differ)} failed")
    sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
