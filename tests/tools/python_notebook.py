"""docs/python.ipynb from docs/python.md: the page's prose as markdown cells,
each ```python block as a code cell whose stored output is the ```text block
after it. Run from the repository root to write it:

    /usr/bin/python3 tests/tools/python_notebook.py

The test python_module checks that the stored notebook is what this writes
from the page, and executes it (nbclient) to the same outputs.
"""

import json
import re
import sys

PAIR = re.compile(r"```python\n(.*?)```\n\n```text\n(.*?)```\n", re.S)


def lines(text):
    """A notebook's multi-line string: a list of lines, each with its newline."""
    return text.splitlines(keepends=True)


def notebook(page):
    cells, at, count = [], 0, 0
    for match in PAIR.finditer(page):
        prose = page[at:match.start()].strip("\n")
        if prose:
            cells.append({"cell_type": "markdown", "metadata": {}, "source": lines(prose)})
        count += 1
        code, shown = match.group(1), match.group(2)
        cells.append({"cell_type": "code", "execution_count": count, "metadata": {},
                      "outputs": [{"name": "stdout", "output_type": "stream", "text": lines(shown)}] if shown else [],
                      "source": lines(code.rstrip("\n"))})
        at = match.end()
    prose = page[at:].strip("\n")
    if prose:
        cells.append({"cell_type": "markdown", "metadata": {}, "source": lines(prose)})
    return {"cells": cells,
            "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
                         "language_info": {"name": "python"}},
            "nbformat": 4, "nbformat_minor": 4}


def text(page):
    return json.dumps(notebook(page), indent=1, ensure_ascii=False) + "\n"


if __name__ == "__main__":
    with open("docs/python.md") as f:
        written = text(f.read())
    with open("docs/python.ipynb", "w") as f:
        f.write(written)
    sys.exit(0)
