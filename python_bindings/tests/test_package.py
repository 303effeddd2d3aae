# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Packaging: the stub matches the module, and `cmake --install` puts an importable module in dist-packages."""
import ast
import os
import pathlib
import subprocess
import sys

import pytest

import isovdb

STUB = pathlib.Path(__file__).resolve().parents[1] / "isovdb.pyi"


def test_stub_names_every_public_function_and_class():
    tree = ast.parse(STUB.read_text())
    stubbed = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(isovdb) if not name.startswith("_")}
    assert public == stubbed


def test_every_public_object_has_a_docstring():
    for name in dir(isovdb):
        if not name.startswith("_"):
            assert (getattr(isovdb, name).__doc__ or "").strip(), name


def test_cmake_install_into_a_destdir(tmp_path):
    build = pathlib.Path(os.environ.get("ISOVDB_BUILD_DIR", STUB.parents[1] / "build"))
    if not (build / "CMakeCache.txt").exists():
        pytest.fail(f"no CMake build at {build} (set ISOVDB_BUILD_DIR)")
    env = dict(os.environ, DESTDIR=str(tmp_path))
    subprocess.run(["cmake", "--install", str(build), "--component", "python"], check=True, env=env,
                   capture_output=True)
    modules = list(tmp_path.rglob("isovdb*.so"))
    assert len(modules) == 1
    site = modules[0].parent
    assert site.name == "dist-packages" and (site / "isovdb.pyi").exists()
    # the installed module imports by itself (no build tree on the path) and works
    code = "import isovdb, numpy; v = isovdb.from_numpy(numpy.ones((2, 2, 2), bool)); print(isovdb.__file__, v.kind)"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    done = subprocess.run([sys.executable, "-c", code], check=True, env=env, capture_output=True, text=True,
                          cwd=tmp_path)
    imported, kind = done.stdout.split()
    assert pathlib.Path(imported).parent == site and kind == "mask"
