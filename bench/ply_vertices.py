# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""The vertex positions of a binary little-endian PLY file (float x, y, z first), for the
benchmarks that measure meshes against analytic or reference surfaces."""
from pathlib import Path

import numpy as np


def read_ply_vertices(path):
    data = Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    count, props, in_vertex = 0, [], False
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif words[:1] == ["property"] and in_vertex:
            props.append(words[1])
    assert all(p == "float" for p in props), props
    return np.frombuffer(data[end:end + 4 * len(props) * count], "<f4").reshape(count, len(props))[:, :3]
