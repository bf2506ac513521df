#!/usr/bin/python3
"""Runs every command shown in README.md and docs/*.md and compares its output.

The convention (docs/output.md, "Command output in the docs"):
- a fenced block whose first line starts with "$ " is checked: each "$ " line is a
  command (a line ending in a backslash continues it), the lines up to the next
  "$ " line its exact output, stdout and stderr as one terminal shows them;
- a line "..." (indented or not) stands for any number of omitted lines;
- each command runs with bash in a copy of the repository (a block starts at its root
  and its "cd" and "$?" hold for the block's later commands), in which
  `pendulum-g` and `build/cli/pendulum-g` are the built binary and `class/` and
  `fresh/` are the seeded classes of build/tests/make_class and make_fresh_class;
  the commands of one page share that copy, in the page's order;
- a block that shows volatile output (timings, benchmark figures) is not checked
  when the last non-blank line before it is "<!-- unchecked: REASON -->";
- a block with no info string after its fence is output, so it must be one of those two:
  a page fails when one shows lines no command of it prints and no reason says why
  (code, scenes and diagrams name their language: ```json, ```sh, ```text);
- a block after "<!-- file: NAME -->" (a scene the page shows) is written to NAME in the
  copy, for the page's later commands.
docs/python.md is executed by tests/python/test_pendulum_g.py instead.

Usage: check_docs.py [--update] SOURCE_DIR PENDULUM_G MAKE_CLASS MAKE_FRESH_CLASS [PAGE...]
--update rewrites each block that differs from the real output (an abridged block keeps
its lines, each replaced by the real line nearest it): review the diff before committing.
"""
import difflib
import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^(```+|~~~+)")
UNCHECKED = re.compile(r"^<!--\s*unchecked:\s*(\S.*?)\s*-->$")
AS_FILE = re.compile(r"^<!--\s*file:\s*(\S+)\s*-->$")
SKIPPED_PAGES = {"docs/python.md"}


def blocks(text):
    """(first line number, lines, the comment before it, the info string) of each fenced block."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i].strip())
        if not m:
            i += 1
            continue
        start, fence = i, m.group(1)
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            j += 1
        before = next((l.strip() for l in reversed(lines[:start]) if l.strip()), "")
        yield start + 1, lines[i + 1:j], before, lines[i].strip()[len(fence):].strip()
        i = j + 1


def commands(body):
    """(command, expected output lines) of a checked block."""
    out, i = [], 0
    while i < len(body):
        command = body[i][2:]
        while command.endswith("\\") and i + 1 < len(body):
            i += 1
            command = command + "\n" + body[i]
        i += 1
        expected = []
        while i < len(body) and not body[i].startswith("$ "):
            expected.append(body[i])
            i += 1
        out.append((command, expected))
    return out


def normalise(lines):
    lines = [l.rstrip() for l in lines]
    while lines and not lines[-1]:
        lines.pop()
    return lines


def matches(expected, actual):
    """Whether actual is expected with each "..." line standing for 0 or more lines."""
    segments = [[]]
    for line in expected:
        if line.strip() == "...":
            segments.append([])
        else:
            segments[-1].append(line)
    if len(segments) == 1:
        return expected == actual
    first, last, middle = segments[0], segments[-1], segments[1:-1]
    if actual[:len(first)] != first or len(actual) < len(first) + len(last):
        return False
    if last and actual[len(actual) - len(last):] != last:
        return False
    pos, end = len(first), len(actual) - len(last)
    for seg in middle:
        if not seg:
            continue
        found = next((k for k in range(pos, end - len(seg) + 1) if actual[k:k + len(seg)] == seg), None)
        if found is None:
            return False
        pos = found + len(seg)
    return True


def copy_of_repository(source, exe, make_class, make_fresh_class):
    root = tempfile.mkdtemp(prefix="check_docs-")
    work = os.path.join(root, "repo")
    shutil.copytree(source, work, symlinks=True,
                    ignore=shutil.ignore_patterns(".git", "build*", "*.png"))
    os.makedirs(os.path.join(work, "build", "cli"))
    os.symlink(exe, os.path.join(work, "build", "cli", "pendulum-g"))
    bindir = os.path.join(root, "bin")
    os.makedirs(bindir)
    os.symlink(exe, os.path.join(bindir, "pendulum-g"))
    for tool, folder in ((make_class, "class"), (make_fresh_class, "fresh")):
        os.makedirs(os.path.join(work, folder))
        subprocess.run([tool, os.path.join(work, folder)], check=True)
    return root, work, bindir


def regenerated(command, expected, actual):
    """The shown output made real: all of it, or for an excerpt (with "..." or a command
    ending in "# excerpt") the real line nearest each shown line, in order, with "..."
    where lines are left out."""
    if not any(l.strip() == "..." for l in expected) and not command.endswith("# excerpt"):
        return actual
    out, pos = [], 0
    for line in expected:
        if line.strip() == "...":
            continue
        key = line.split("  ")[0]  # a table's row name: the same row with new figures
        scores = [(difflib.SequenceMatcher(None, line, a).ratio() + (key != "" and a.startswith(key + "  ")),
                   -k) for k, a in enumerate(actual[pos:], pos)]
        if not scores or max(scores)[0] < 0.5:
            continue  # the line is no longer in the output
        k = -max(scores)[1]
        if k > pos or (not out and k > 0):
            out.append("...")
        out.append(actual[k])
        pos = k + 1
    if pos < len(actual):
        out.append("...")
    return out


def check_page(source, page, tools, update):
    path = os.path.join(source, page)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    found = list(blocks(text))
    checked = [(n, body) for n, body, before, _ in found
               if body and body[0].startswith("$ ") and not UNCHECKED.match(before)]
    files = {n: AS_FILE.match(before).group(1) for n, body, before, _ in found if AS_FILE.match(before)}
    for n, body, before, info in found:
        m = UNCHECKED.match(before)
        if before.startswith("<!--") and "unchecked" in before and not m:
            raise SystemExit(f"{page}:{n}: an unchecked block needs a reason: {before}")
        if not info and not m and not (body and body[0].startswith("$ ")):
            raise SystemExit(f"{page}:{n}: a block of output that no command of the page prints; expected "
                             "its command (\"$ ...\" first), or \"<!-- unchecked: REASON -->\" before it, "
                             "or an info string (```json, ```text) if it is not output")
    if not checked:
        return 0, []
    root, work, bindir = copy_of_repository(source, *tools)
    env = dict(os.environ, PATH=bindir + os.pathsep + os.environ["PATH"], LC_ALL="C.UTF-8",
               COLUMNS="100")
    failures, count, lines = [], 0, text.split("\n")
    try:
        for n, body, before, _ in found:
            if n in files:  # a file the page shows, which its later commands read
                with open(os.path.join(work, files[n]), "w", encoding="utf-8") as f:
                    f.write("\n".join(body) + "\n")
            if (n, body) not in checked:
                continue
            cwd, status = work, 0  # a block's "cd" and "$?" hold for its later commands
            new_body = []
            for command, expected in commands(body):
                count += 1
                where = os.path.join(root, "cwd")
                run = subprocess.run(["bash", "-c", f"(exit {status})\n" + command +
                                      '\n__s=$?; pwd > "$0"; exit $__s', where],
                                     cwd=cwd, env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, timeout=300)
                status = run.returncode
                if os.path.exists(where):
                    with open(where) as f:
                        cwd = f.read().strip()
                    os.remove(where)
                actual = normalise(run.stdout.decode("utf-8", "replace").split("\n"))
                new_body += ["$ " + command.split("\n")[0]] + command.split("\n")[1:]
                if matches(normalise(expected), actual):
                    new_body += expected
                else:
                    failures.append((f"{page}:{n}", command, expected, actual))
                    new_body += regenerated(command, normalise(expected), actual)
            lines[n:n + len(body)] = [new_body] + [None] * (len(body) - 1)  # same length
    finally:
        shutil.rmtree(root)
    if update and failures:
        flat = []
        for l in lines:
            if isinstance(l, list):
                flat += l
            elif l is not None:
                flat.append(l)
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(flat))
    return count, failures


def main(argv):
    update = "--update" in argv
    argv = [a for a in argv if a != "--update"]
    if len(argv) < 5:
        sys.stderr.write(__doc__)
        return 2
    source, tools = argv[1], [os.path.abspath(a) for a in argv[2:5]]
    pages = argv[5:] or ["README.md"] + sorted(
        "docs/" + name for name in os.listdir(os.path.join(source, "docs")) if name.endswith(".md"))
    total, failures = 0, []
    for page in pages:
        if page in SKIPPED_PAGES:
            continue
        count, failed = check_page(source, page, tools, update)
        total += count
        failures += failed
    for where, command, expected, actual in failures:
        print(f"{where}: $ {command}\n--- shown\n" + "\n".join(expected) +
              "\n--- real output\n" + "\n".join(actual) + "\n")
    print(f"{total} commands in the docs, {len(failures)} with output other than shown" +
          (" (rewritten from the real output: review the diff)" if update and failures else ""))
    return 1 if failures or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
