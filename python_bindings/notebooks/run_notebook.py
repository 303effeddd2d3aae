#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Runs a notebook top to bottom and checks what it produced (ctest: python.notebook.*).

Usage: run_notebook.py NOTEBOOK.ipynb [OUT_DIR]

The notebook must be committed without outputs. It is executed by nbclient with the
"python3" kernel (python3-ipykernel: /usr/bin/python3), in its own folder, with this
process's environment: the installed module and tools (ctest installs them into a staging
prefix and sets PYTHONPATH and PATH there), ISOVDB_DATA_DIR. A notebook must not reach into
a build tree (no `build/` path, no sys.path edit): users run it against what they installed.
Then every code cell tagged "figure" must have produced an image and every cell tagged
"table" an HTML table; no cell may have failed, and the run must take less than
ISOVDB_NOTEBOOK_SECONDS (60). The executed copy goes to OUT_DIR when given.
"""
import datetime
import os
import pathlib
import sys
import time

import nbformat
from nbclient import NotebookClient

EXPECTED = {"figure": "image/png", "table": "text/html"}
BUILD_TREE_WORDS = ("sys.path", "build/", "BUILD", "ISOVDB_BUILD_DIR")


def cell_seconds(cell):
    """How long a cell ran (nbclient records the times in its metadata)."""
    times = cell.metadata.get("execution", {})
    try:
        start = datetime.datetime.fromisoformat(times["iopub.execute_input"].replace("Z", "+00:00"))
        end = datetime.datetime.fromisoformat(times["shell.execute_reply"].replace("Z", "+00:00"))
    except KeyError:
        return 0.0
    return (end - start).total_seconds()


def main():
    path = pathlib.Path(sys.argv[1]).resolve()
    notebook = nbformat.read(path, as_version=4)
    code_cells = [c for c in notebook.cells if c.cell_type == "code"]
    stale = [i for i, c in enumerate(code_cells) if c.outputs or c.execution_count is not None]
    if stale:
        sys.exit(f"{path.name}: code cells {stale} carry outputs; commit notebooks without outputs")

    for index, cell in enumerate(code_cells):
        for word in BUILD_TREE_WORDS:
            if word in cell.source:
                sys.exit(f"{path.name}: code cell {index} uses '{word}': notebooks use the installed module")

    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # quiet ipykernel's debugger warning
    client = NotebookClient(notebook, timeout=120, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}})
    start = time.perf_counter()
    client.execute()  # raises CellExecutionError (with the traceback) when a cell fails
    seconds = time.perf_counter() - start

    problems = []
    for index, cell in enumerate(code_cells):
        for tag in cell.metadata.get("tags", []):
            mime = EXPECTED.get(tag)
            if mime and not any(mime in output.get("data", {}) for output in cell.outputs):
                problems.append(f"cell {index} (tagged {tag}) produced no {mime}")
    tagged = sum(1 for c in code_cells for t in c.metadata.get("tags", []) if t in EXPECTED)
    if tagged == 0:
        problems.append("no cell is tagged figure or table: nothing to check")
    limit = float(os.environ.get("ISOVDB_NOTEBOOK_SECONDS", "60"))
    if seconds > limit:
        problems.append(f"took {seconds:.1f} s, more than {limit:.0f} s")

    if len(sys.argv) > 2:
        out = pathlib.Path(sys.argv[2])
        out.mkdir(parents=True, exist_ok=True)
        nbformat.write(notebook, out / path.name)
    print(f"{path.name}: {len(code_cells)} code cells, {tagged} checked outputs, {seconds:.1f} s")
    timed = [(cell_seconds(c), i) for i, c in enumerate(code_cells)]
    print("slowest cells: " + ", ".join(f"{i} ({s:.1f} s)" for s, i in sorted(timed, reverse=True)[:3]))
    if problems:
        sys.exit(f"{path.name}: " + "; ".join(problems))


if __name__ == "__main__":
    main()
