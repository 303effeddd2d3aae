#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Writes the seed corpora of fuzz/corpus/: small valid inputs of every reader (a
fuzzer mutates from them), plus a few of the repository's sample files (data/, with
their provenance there). Inputs that were findings of bench/fuzz.sh are kept beside
them as corpus/<harness>/finding_* (left alone here), so ctest replays every one.
Run once with the CLI built (the .vdb seeds are made by `isovdb sdf`); the files are
committed, so nothing runs this in CI.

    /usr/bin/python3 fuzz/make_corpus.py [--cli build/isovdb]
"""
import argparse
import base64
import gzip
import os
import struct
import subprocess
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def put(harness, name, data):
    folder = os.path.join(HERE, "corpus", harness)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def copy(harness, source, name=None):
    with open(os.path.join(ROOT, source), "rb") as f:
        put(harness, name or os.path.basename(source), f.read())


def ball(n=6):
    c = (n - 1) / 2
    return bytes(int((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 <= (n / 3) ** 2)
                 for z in range(n) for y in range(n) for x in range(n))


def png(width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + bytes(r) for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def bmp(width, height, rows):
    stride = (width * 3 + 3) & ~3
    pixels = b"".join(b"".join(bytes([v, v, v]) for v in r) + b"\0" * (stride - width * 3) for r in reversed(rows))
    header = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    return b"BM" + struct.pack("<IHHI", 14 + len(header) + len(pixels), 0, 0, 14 + len(header)) + header + pixels


def glb(points, faces):
    """Binary glTF 2.0: one mesh, one triangle primitive, float positions and uint16 indices."""
    positions = b"".join(struct.pack("<3f", *p) for p in points)
    indices = b"".join(struct.pack("<3H", *f) for f in faces)
    indices += b"\0" * (-len(indices) % 4)
    lo = [min(p[a] for p in points) for a in range(3)]
    hi = [max(p[a] for p in points) for a in range(3)]
    doc = ('{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],'
           '"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4}]}],'
           '"accessors":[{"bufferView":0,"componentType":5126,"count":%d,"type":"VEC3","min":%s,"max":%s},'
           '{"bufferView":1,"componentType":5123,"count":%d,"type":"SCALAR"}],'
           '"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":%d},{"buffer":0,"byteOffset":%d,"byteLength":%d}],'
           '"buffers":[{"byteLength":%d}]}' % (len(points), lo, hi, 3 * len(faces), len(positions), len(positions),
                                                6 * len(faces), len(positions) + len(indices))).encode()
    doc += b" " * (-len(doc) % 4)
    body = positions + indices
    chunks = struct.pack("<I4s", len(doc), b"JSON") + doc + struct.pack("<I4s", len(body), b"BIN\0") + body
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default=os.path.join(ROOT, "build", "isovdb"))
    args = parser.parse_args()
    # The fuzzers' findings (finding_*, copied from bench/fuzz.sh's OUT/findings/) stay.
    for folder, _, names in os.walk(os.path.join(HERE, "corpus")):
        for name in names:
            if not name.startswith("finding_"):
                os.remove(os.path.join(folder, name))
    voxels = ball()

    # raw: 4 option bytes (type | endianness << 3 | scalar << 4, dims - 1 each) then samples.
    put("raw", "uint8_ball", bytes([1, 5, 5, 5]) + voxels)
    put("raw", "float32_ramp", bytes([6 | 16, 3, 1, 0]) + struct.pack("<8f", *range(8)))
    put("raw", "int16_big_endian", bytes([2 | 8, 1, 1, 1]) + struct.pack(">8h", *range(-4, 4)))

    header = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 6 6 6\nspacings: 1 1 1.5\n"
    put("nrrd", "raw.nrrd", (header + "encoding: raw\n\n").encode() + voxels)
    put("nrrd", "gzip.nrrd", (header + "encoding: gzip\n\n").encode() + gzip.compress(voxels, mtime=0))
    copy("nrrd", "data/nrrd/eltype_rgb_u8.nrrd")
    copy("nrrd", "data/nrrd/small.nrrd")

    mha = "ObjectType = Image\nNDims = 3\nDimSize = 6 6 6\nElementSpacing = 1 1 1\nElementType = MET_UCHAR\n"
    put("metaimage", "local.mha", (mha + "ElementDataFile = LOCAL\n").encode() + voxels)
    put("metaimage", "zlib.mha", (mha + "CompressedData = True\nElementDataFile = LOCAL\n").encode()
        + zlib.compress(voxels))

    copy("segy", "data/seismic/small.sgy")
    for name in ("delay-scalar.sgy", "interval-pos-bin-neg-trace.sgy", "decrement.sgy"):
        copy("segy", os.path.join("data/seismic/segyio", name))

    with tempfile.TemporaryDirectory() as work:
        source = os.path.join(work, "ball.nrrd")
        with open(source, "wb") as f:
            f.write((header.replace("1 1 1.5", "1 1 1") + "encoding: raw\n\n").encode() + ball())
        out = os.path.join(work, "ball.vdb")
        subprocess.run([args.cli, "sdf", source, "--threshold", "0.5", "-o", out], check=True, capture_output=True)
        copy("vdb", out, "ball_sdf.vdb")

    copy("grdecl", "data/reservoir/fault_test/regular27cell.grdecl")
    copy("grdecl", "data/reservoir/fault_test/fault1.grdecl")
    put("grdecl", "one_cell.grdecl", b"SPECGRID\n1 1 1 1 F /\nCOORD\n0 0 0 0 0 1  1 0 0 1 0 1  0 1 0 0 1 1  "
        b"1 1 0 1 1 1 /\nZCORN\n4*0 4*1 /\nACTNUM\n1 /\nPORO\n0.25 /\n")

    tetra = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    head = "ply\nformat {}\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n" \
           "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    put("ply", "ascii.ply", (head.format("ascii 1.0") + "".join("%g %g %g\n" % p for p in tetra)
                             + "".join("3 %d %d %d\n" % f for f in faces)).encode())
    put("ply", "binary.ply", head.format("binary_little_endian 1.0").encode()
        + b"".join(struct.pack("<3f", *p) for p in tetra) + b"".join(struct.pack("<B3i", 3, *f) for f in faces))

    # The same tetrahedron in the other mesh formats readMesh takes.
    put("obj", "tetra.obj", ("# tetrahedron\n" + "".join("v %g %g %g\n" % p for p in tetra)
                             + "vn 0 0 1\n" + "".join("f %d//1 %d//1 %d//1\n" % tuple(i + 1 for i in f) for f in faces)
                             + "f -4 -3 -2\n").encode())
    corners = [[tetra[i] for i in f] for f in faces]
    put("stl", "ascii.stl", ("solid tetra\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % p for p in c) + "endloop\nendfacet\n"
        for c in corners) + "endsolid tetra\n").encode())
    put("stl", "binary.stl", b"tetra".ljust(80, b" ") + struct.pack("<I", len(corners)) + b"".join(
        struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *p) for p in c) + b"\0\0" for c in corners))
    put("glb", "tetra.glb", glb(tetra, faces))
    # glTF text: the tetrahedron's buffer in a data: URI, placed by a parent's TRS and a child's matrix.
    buffer = b"".join(struct.pack("<3f", *p) for p in tetra) + b"".join(struct.pack("<3H", *f) for f in faces)
    put("gltf", "tetra_nodes.gltf", (
        '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],'
        '"nodes":[{"translation":[1,2,3],"rotation":[0,0,0.6,0.8],"scale":[1,2,-1],"children":[1]},'
        '{"mesh":0,"matrix":[2,0,0,0,0,2,0,0,0,0,2,0,0,0,1,1]}],'
        '"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],'
        '"accessors":[{"bufferView":0,"componentType":5126,"count":%d,"type":"VEC3"},'
        '{"bufferView":1,"componentType":5123,"count":%d,"type":"SCALAR"}],'
        '"bufferViews":[{"buffer":0,"byteLength":%d},{"buffer":0,"byteOffset":%d,"byteLength":%d}],'
        '"buffers":[{"byteLength":%d,"uri":"data:application/octet-stream;base64,%s"}]}'
        % (len(tetra), 3 * len(faces), 12 * len(tetra), 12 * len(tetra), 6 * len(faces), len(buffer),
           base64.b64encode(buffer).decode())).encode())
    copy("gltf", "data/meshes/Box-embedded.gltf")

    disc = [[255 if (x - 3.5) ** 2 + (y - 3.5) ** 2 < 9 else 0 for x in range(8)] for y in range(8)]
    put("slice_image", "disc.png", png(8, 8, disc))
    put("slice_image", "disc.bmp", bmp(8, 8, disc))

    # extract: dims - 2 per axis, flags (bit 0 adaptive, bit 1 one block), then one bit per voxel.
    def mask(dims, flags, inside):
        bits = [int(inside(x, y, z)) for z in range(dims[2]) for y in range(dims[1]) for x in range(dims[0])]
        packed = bytes(sum(b << i for i, b in enumerate(bits[k:k + 8])) for k in range(0, len(bits), 8))
        return bytes([d - 2 for d in dims] + [flags]) + packed
    checker = lambda x, y, z: 1 <= x <= 4 and 1 <= y <= 4 and 1 <= z <= 4 and (x + y + z) % 2 == 0  # noqa: E731
    sheet = lambda x, y, z: z == 3 and 1 <= x <= 10 and 1 <= y <= 10  # noqa: E731
    tunnel = lambda x, y, z: 1 <= x <= 7 and 1 <= y <= 7 and 1 <= z <= 7 and not (3 <= x <= 5 and 3 <= y <= 5)  # noqa
    for flags in range(4):
        put("extract", "checker_%d" % flags, mask((6, 6, 6), flags, checker))
        put("extract", "sheet_%d" % flags, mask((12, 12, 7), flags, sheet))
        put("extract", "tunnel_%d" % flags, mask((9, 9, 9), flags, tunnel))
        put("extract", "touching_box_%d" % flags, mask((5, 4, 3), flags, lambda x, y, z: True))


if __name__ == "__main__":
    main()
