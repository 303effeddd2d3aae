# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""One settings table (lib/isovdb/pipeline/extract_settings.cc) makes the CLI's flags and
the Python keywords of extract() and distance_field(): their names and defaults must agree
with `--help`, the type stub and docs/cli.md."""
import ast
import inspect
import re
import subprocess

import numpy as np
import pytest

import isovdb
from conftest import ROOT, ball

# The array keywords (spacing, origin, kind, threshold) are from_numpy's, for a numpy input.
NOT_SETTINGS = {"volume", "progress", "output", "grid_name", "level", "spacing", "origin", "kind", "threshold"}


def settings_of(function):
    """{keyword: default} of a function's settings, in signature order."""
    return {name: p.default for name, p in inspect.signature(function).parameters.items()
            if name not in NOT_SETTINGS}


def cli_defaults(cli, command):
    """{keyword: default as Python reads it} of the flags `isovdb COMMAND --help` lists, in order."""
    text = subprocess.run([str(cli), command, "--help"], capture_output=True, text=True, check=True).stdout
    flags = {}
    for match in re.finditer(r"^  (--[a-z-]+)(,--no-[a-z-]+\{false\})?(?: [A-Z]+(?: x \d)?)?(?:=(\S+))?",
                             text, re.M):
        flag, default = match.group(1), match.group(3)
        flags[flag[2:].replace("-", "_")] = python_value(default)
    return flags


def python_value(text):
    if text is None or text == "unset":  # docs/cli.md's word for a setting without a default
        return None
    if text in ("on", "off"):
        return text == "on"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def test_extract_keywords_are_the_cli_flags_with_their_defaults(cli):
    settings = settings_of(isovdb.extract)
    assert len(settings) >= 18 and settings["method"] == "adaptive"
    flags = cli_defaults(cli, "extract")
    listed = {name: flags[name] for name in flags if name in settings}
    assert listed == settings
    assert list(listed) == list(settings), "the CLI lists the settings in the table's order"


def test_octree_inspector_takes_every_extract_setting(cli):
    # `isovdb octree` builds the tree extract builds: same flags, same defaults.
    flags = cli_defaults(cli, "octree")
    settings = settings_of(isovdb.extract)
    assert {name: flags.get(name, "missing") for name in settings} == settings


def test_distance_field_keywords_are_the_sdf_flags_and_a_part_of_extract(cli):
    settings = settings_of(isovdb.distance_field)
    assert list(settings) == ["distance", "half_width", "sdf_chunk", "closing"]
    extract = settings_of(isovdb.extract)
    assert settings == {name: extract[name] for name in settings}
    flags = cli_defaults(cli, "sdf")
    assert {name: flags.get(name, "missing") for name in settings} == settings


@pytest.mark.parametrize("name", ["extract", "distance_field"])
def test_type_stub_matches_the_signature(name):
    tree = ast.parse((ROOT / "python_bindings" / "isovdb.pyi").read_text())
    stub = next(node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == name)
    stub_defaults = {}
    arguments = stub.args
    positional = arguments.posonlyargs + arguments.args
    for arg, default in zip(positional[len(positional) - len(arguments.defaults):], arguments.defaults):
        stub_defaults[arg.arg] = ast.literal_eval(default)
    for arg, default in zip(arguments.kwonlyargs, arguments.kw_defaults):
        if default is not None:
            stub_defaults[arg.arg] = ast.literal_eval(default)
    signature = inspect.signature(getattr(isovdb, name))
    assert [a.arg for a in positional + arguments.kwonlyargs] == list(signature.parameters)
    assert stub_defaults == {n: p.default for n, p in signature.parameters.items()
                             if p.default is not inspect.Parameter.empty}


def test_documentation_table_matches_the_cli(cli):
    text = (ROOT / "docs" / "cli.md").read_text()
    rows = re.findall(r"^\| `--([a-z-]+)` \| `([a-z_]+)` \| `([^`]+)`", text, re.M)
    settings = settings_of(isovdb.extract)
    assert [keyword for _, keyword in [(f, k) for f, k, _ in rows]] == list(settings)
    for flag, keyword, default in rows:
        assert flag.replace("-", "_") == keyword
        assert python_value(default) == settings[keyword], keyword


def test_docstring_lists_every_setting_with_its_default():
    for function in (isovdb.extract, isovdb.distance_field):
        for name, default in settings_of(function).items():
            assert f"{name} ({default!r}):" in function.__doc__, name


@pytest.fixture(scope="module")
def small_ball():
    return isovdb.from_numpy(ball((24, 24, 24), (12, 12, 12), 7).astype(np.uint8))


@pytest.mark.parametrize("kwargs, keyword", [
    ({"meta_cell": 16.5}, "meta_cell"),
    ({"intersection_free": 1}, "intersection_free"),
    ({"half_width": True}, "half_width"),
    ({"method": 3}, "method"),
])
def test_a_setting_of_the_wrong_type_raises_type_error_naming_it(small_ball, kwargs, keyword):
    with pytest.raises(TypeError, match=keyword):
        isovdb.extract(small_ball, **kwargs)


def test_an_unknown_keyword_raises_type_error(small_ball):
    with pytest.raises(TypeError, match="meta_cell_size"):
        isovdb.extract(small_ball, meta_cell_size=16)
    with pytest.raises(TypeError, match="chunk_size"):
        isovdb.distance_field(small_ball, chunk_size=16)


def test_an_unknown_keyword_names_itself_the_closest_and_every_accepted_one(small_ball):
    with pytest.raises(TypeError) as raised:
        isovdb.extract(small_ball, levle=3)
    message = str(raised.value)
    assert "unexpected keyword argument 'levle' (did you mean 'level'?)" in message
    assert all(keyword in message for keyword in inspect.signature(isovdb.extract).parameters)
    # pybind11 functions: their keywords come from the signature line of their docstring.
    with pytest.raises(TypeError, match=r"'prop' \(did you mean 'property'\?\); its keywords are: grid, property, iso"):
        isovdb.extract_reservoir("deck.grdecl", prop="PORO", iso=0.2)
    with pytest.raises(TypeError, match="'dimz' \\(did you mean 'dims'\\?\\)"):
        isovdb.read_volume("volume.raw", dimz=(2, 2, 2))


def test_an_argument_of_the_wrong_type_is_named_by_its_type_not_printed():
    # pybind11's own message printed the whole array ("Invoked with: array([[[...").
    array = np.zeros((40, 40, 40))
    with pytest.raises(TypeError) as raised:
        isovdb.extract_reservoir(array, property="PORO", iso=0.2)
    message = str(raised.value)
    assert "called with (numpy.ndarray, property=str, iso=float)" in message and "grid: Union[" in message
    assert "0." not in message and len(message) < 400  # the signature line, not numpy's repr
    with pytest.raises(TypeError, match=r"read_mesh\(\): an argument has the wrong type: called with \(int\)"):
        isovdb.read_mesh(3)


def test_wrapped_functions_keep_their_name_documentation_and_pickle_by_name():
    import pickle
    for name in ("extract", "read_volume", "euler_characteristic", "extract_reservoir", "read_mesh"):
        function = getattr(isovdb, name)
        assert function.__name__ == name and function.__doc__ and function.__doc__ == function.__wrapped__.__doc__
        assert pickle.loads(pickle.dumps(function)) is function


def test_none_keeps_the_default(small_ball):
    plain = isovdb.extract(small_ball, meta_cell=16)
    defaulted = isovdb.extract(small_ball, meta_cell=16, threads=None, qef_tolerance=None, method=None)
    assert np.array_equal(plain.triangles, defaulted.triangles)
    assert np.array_equal(plain.vertices, defaulted.vertices)
