#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Peer benchmark: isovdb's four contouring methods against OpenVDB's own path, VTK and
scikit-image, end to end (read -> mesh file), in the same session and on the same inputs,
every output mesh validated by `isovdb check`. Prints one table; "time ratio" is a row's
wall time over isovdb --method regular's on the same input.

Run on demand, never in CI:
    /usr/bin/python3 bench/peers.py [--sizes 256,512] [--work DIR] [--build build] [--rows A,B,...]
It builds nothing: run scripts/build.sh first (BUILD/isovdb, BUILD/data/isovdb-sample).
Peers are Debian's python3-vtk9 and python3-skimage; a missing package or a crash
prints a row with the error instead of stopping the run.

Inputs: salt-dome at each --sizes, blobs (2000 random ellipsoids: a surface-heavy body)
at each --blob-sizes, gyroid-slab at 256 (generated into --work when missing) and the frog
skeleton (data/frog/frogtissue.mhd, label 13).

Protocol:
  isovdb  `isovdb -q extract IN -o OUT.ply --method M --stats S.json`; time = wall time
          around the process, peak RSS = memory.peak_rss_bytes of the stats.
  openvdb BUILD/bench/isovdb-openvdb-path: the mask read as isovdb reads it, then
          tools::topologyToLevelSet on the whole mask and tools::volumeToMesh (adaptivity 0
          and 0.5), written as PLY; its "field s" is topologyToLevelSet's seconds.
  peers   a child /usr/bin/python3 per run reads the file with numpy (zlib for the
          frog's .zraw), runs the filter, writes a binary PLY and reports its
          getrusage peak RSS; time = wall time around the child (interpreter start and
          imports included, as for isovdb's process). "work s" is the child's own
          read -> write time (isovdb: the sum of its stats timings).
  rounds  --repeat N runs every row N times, the rows interleaved round by round (A B C A
          B C ...); times are medians over the rounds; the last round's meshes are checked.
          When the object touches the volume border (the frog) the peers get one
          voxel of background padding (inside the timed child), as isovdb's narrow
          band closes the surface there; --no-pad leaves their meshes open.
  check   `isovdb -q check MESH --stats X.json`, with --no-self-intersections for
          meshes over --self-intersection-limit triangles ("skip" in the table).
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHON = "/usr/bin/python3"
MIB = 1 << 20

ISOVDB_METHODS = [
    ("isovdb vdb", ["--method", "vdb"]),
    ("isovdb vdb a=0.5", ["--method", "vdb", "--adaptivity", "0.5"]),
    ("isovdb regular", ["--method", "regular"]),
    ("isovdb adaptive", ["--method", "adaptive"]),
]
BASELINE = "isovdb regular"

# Child process for the peers. argv[1] is a JSON job; the last stdout line is a JSON report.
PEER_CHILD = r'''
import json, resource, sys, time, zlib
job = json.loads(sys.argv[1])
import numpy as np

def read_volume():
    nx, ny, nz = job["dims"]
    if job["compressed"]:
        with open(job["path"], "rb") as f:
            data = np.frombuffer(zlib.decompress(f.read()), dtype=np.uint8)
    else:
        data = np.fromfile(job["path"], dtype=np.uint8)
    return data.reshape(nz, ny, nx)  # x fastest

def inside(v):
    return v == job["label"] if job["label"] is not None else v > 0

def touches_border(v):
    faces = (v[0], v[-1], v[:, 0], v[:, -1], v[:, :, 0], v[:, :, -1])
    return any(bool(inside(f).any()) for f in faces)

def write_ply(path, verts, faces):
    verts = np.ascontiguousarray(verts, dtype="<f4")
    rec = np.empty(len(faces), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    rec["n"] = 3
    rec["i"] = faces
    header = ("ply\nformat binary_little_endian 1.0\ncomment written by bench/peers.py\n"
              f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(verts.tobytes())
        f.write(rec.tobytes())

method = job["method"]
if method.startswith("vtk"):
    from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, vtkVersion
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkIOPLY import vtkPLYWriter
    if method == "vtk-discrete":
        import vtkmodules.vtkFiltersGeneral as general
        cls = getattr(general, "vtkDiscreteFlyingEdges3D", None) or general.vtkDiscreteMarchingCubes
    else:
        from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D as cls
    version = "VTK " + vtkVersion.GetVTKVersion()
else:
    import skimage
    from skimage.measure import marching_cubes
    cls = None
    version = "skimage " + skimage.__version__

start = time.monotonic()
vol = read_volume()
spacing = job["spacing"]
origin = [0.0, 0.0, 0.0]
padded = False
if job["pad"] and touches_border(vol):
    vol = np.pad(vol, 1)
    origin = [-s for s in spacing]
    padded = True
if method != "vtk-discrete" and job["label"] is not None:
    vol = inside(vol).view(np.uint8)  # the 0/1 volume; samples of generated inputs already are 0/1
nz, ny, nx = vol.shape

if cls is not None:
    image = vtkImageData()
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*spacing)
    image.SetOrigin(*origin)
    scalars = numpy_to_vtk(vol.reshape(-1), deep=False, array_type=VTK_UNSIGNED_CHAR)
    image.GetPointData().SetScalars(scalars)
    filt = cls()
    filt.SetInputData(image)
    if method == "vtk-discrete":  # the label's boundary; generated inputs are labelled 1
        filt.SetValue(0, job["label"] if job["label"] is not None else 1)
    else:
        filt.SetValue(0, 0.5)
    for off in ("ComputeNormalsOff", "ComputeGradientsOff", "ComputeScalarsOff"):
        if hasattr(filt, off):
            getattr(filt, off)()
    writer = vtkPLYWriter()
    writer.SetFileTypeToBinary()
    writer.SetInputConnection(filt.GetOutputPort())
    writer.SetFileName(job["out"])
    if not writer.Write():
        sys.exit("vtkPLYWriter failed")
    triangles = filt.GetOutput().GetNumberOfCells()
    algorithm = cls.__name__
else:
    sz_, sy_, sx_ = spacing[2], spacing[1], spacing[0]
    verts, faces, _normals, _values = marching_cubes(vol, 0.5, spacing=(sz_, sy_, sx_))
    verts = verts[:, ::-1] + np.asarray(origin, dtype=np.float32)  # (z,y,x) -> (x,y,z) ...
    faces = faces[:, ::-1]                                          # ... a reflection: keep the winding outward
    write_ply(job["out"], verts, faces)
    triangles = len(faces)
    algorithm = "marching_cubes (lewiner)"
seconds = time.monotonic() - start
print(json.dumps({"seconds": seconds, "peak_rss_bytes": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024,
                  "triangles": triangles, "padded": padded, "algorithm": algorithm, "version": version}))
'''

# OpenVDB's own path (bench/openvdb_path.cc): topologyToLevelSet on the whole mask + volumeToMesh.
OPENVDB_ROWS = [
    ("openvdb path", ["--adaptivity", "0"]),
    ("openvdb path a=0.5", ["--adaptivity", "0.5"]),
]

PEERS = [
    ("vtk discrete", "vtk-discrete"),  # vtkDiscreteFlyingEdges3D (or vtkDiscreteMarchingCubes) on the labels
    ("vtk flying edges", "vtk-fe"),    # vtkFlyingEdges3D on the 0/1 volume at 0.5
    ("skimage mc", "skimage"),         # skimage.measure.marching_cubes on the 0/1 volume at 0.5
]

VERSIONS_CHILD = r'''
import json
out = {}
try:
    from vtkmodules.vtkCommonCore import vtkVersion
    import vtkmodules.vtkFiltersGeneral as general
    out["vtk"] = vtkVersion.GetVTKVersion()
    out["vtk_discrete"] = "vtkDiscreteFlyingEdges3D" if hasattr(general, "vtkDiscreteFlyingEdges3D") else "vtkDiscreteMarchingCubes"
except Exception as e:
    out["vtk"] = f"missing ({type(e).__name__}: {e})"
try:
    import skimage
    out["skimage"] = skimage.__version__
except Exception as e:
    out["skimage"] = f"missing ({type(e).__name__}: {e})"
try:
    import numpy
    out["numpy"] = numpy.__version__
except Exception as e:
    out["numpy"] = f"missing ({type(e).__name__}: {e})"
print(json.dumps(out))
'''


def last_line(text):
    lines = [l for l in (text or "").strip().splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


def machine():
    model = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            mem = f", {kb / (1 << 20):.0f} GiB RAM"
    except (OSError, ValueError, IndexError):
        pass
    return f"{os.cpu_count()} CPUs (nproc {len(os.sched_getaffinity(0))}), {model}{mem}"


def versions():
    try:
        out = subprocess.run([PYTHON, "-c", VERSIONS_CHILD], capture_output=True, text=True, timeout=120)
        return json.loads(last_line(out.stdout))
    except Exception as e:  # noqa: BLE001 - report, never stop
        return {"vtk": f"unknown ({e})", "skimage": f"unknown ({e})"}


def read_mhd(path):
    header = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                key, value = line.split("=", 1)
                header[key.strip()] = value.strip()
    if header.get("ElementType") != "MET_UCHAR":
        raise ValueError(f"{path}: ElementType {header.get('ElementType')} (only MET_UCHAR handled)")
    data = header["ElementDataFile"]
    return {
        "path": os.path.join(os.path.dirname(path), data),
        "dims": [int(v) for v in header["DimSize"].split()],
        "spacing": [float(v) for v in header.get("ElementSpacing", "1 1 1").split()],
        "compressed": header.get("CompressedData", "False").lower() == "true",
    }


def sample_input(sample, shape, size, work):
    """A generated uint8 0/1 raw volume: N x N x nz (gyroid-slab is flatter than a cube)."""
    raw = os.path.join(work, f"{shape}-{size}.raw")
    if not os.path.exists(raw):
        print(f"generating {raw} ...", file=sys.stderr)
        subprocess.run([sample, shape, "--size", str(size), "-o", raw], check=True, stdout=subprocess.DEVNULL)
    nbytes = os.path.getsize(raw)
    if nbytes % (size * size):
        raise ValueError(f"{raw}: {nbytes} bytes is not a multiple of {size}x{size}")
    dims = [size, size, nbytes // (size * size)]
    return {
        "name": f"{shape}-{size}",
        "isovdb_in": [raw, "--dims", ",".join(map(str, dims)), "--type", "uint8"],
        "openvdb_in": [raw, "--dims", ",".join(map(str, dims)), "--type", "uint8"],
        "peer": {"path": raw, "dims": dims, "spacing": [1.0, 1.0, 1.0], "compressed": False, "label": None},
        "desc": f"{'x'.join(map(str, dims))} uint8, inside = value > 0",
    }


def frog_input(path, labels):
    meta = read_mhd(path)
    label = int(labels)
    return {
        "name": f"frog-{label}",
        "isovdb_in": [path, "--labels", str(label)],
        "openvdb_in": [path, "--labels", str(label)],
        "peer": dict(meta, label=label),
        "desc": f"{'x'.join(map(str, meta['dims']))} uint8 MetaImage{' (zlib)' if meta['compressed'] else ''}, "
                f"spacing {'x'.join(f'{s:g}' for s in meta['spacing'])}, inside = label {label}",
    }


def face_count(ply):
    """Triangles from a PLY header (to decide whether the self-intersection test is affordable)."""
    with open(ply, "rb") as f:
        head = f.read(4096)
    m = re.search(rb"element face (\d+)", head)
    return int(m.group(1)) if m else 0


def check(isovdb, mesh, stats, limit, timeout):
    cmd = [isovdb, "-q", "check", mesh, "--stats", stats]
    skipped = face_count(mesh) > limit
    if skipped:
        cmd.append("--no-self-intersections")
    if os.path.exists(stats):
        os.remove(stats)
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if not os.path.exists(stats):
        raise RuntimeError(f"check failed (exit {proc.returncode}): {last_line(proc.stderr) or last_line(proc.stdout)}")
    mesh_stats = json.load(open(stats))["mesh"]
    mesh_stats["self_intersections_skipped"] = skipped
    return mesh_stats


def run_isovdb(isovdb, inp, label, flags, out, stats, timeout):
    cmd = [isovdb, "-q", "extract", *inp["isovdb_in"], "-o", out, *flags, "--stats", stats]
    if os.path.exists(stats):
        os.remove(stats)
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"exit {proc.returncode}: {last_line(proc.stderr) or last_line(proc.stdout)}")
    s = json.load(open(stats))
    t = s.get("timings_s", {})
    # The contouring stages alone (everything after the distance field but the write).
    contour = sum(v for k, v in t.items() if k not in ("read", "distance_field", "write"))
    return {"time": wall, "work": sum(t.values()), "peak": s["memory"]["peak_rss_bytes"], "contouring": contour,
            "field": t.get("distance_field")}


def run_openvdb(tool, inp, flags, out, timeout):
    cmd = [tool, *inp["openvdb_in"], *flags, "-o", out]
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"exit {proc.returncode}: {last_line(proc.stderr) or last_line(proc.stdout)}")
    rep = json.loads(last_line(proc.stdout))
    work = sum(rep[k] for k in ("read", "distance_field", "sweep", "contour", "write"))
    return {"time": wall, "work": work, "peak": rep["peak_rss_bytes"], "contouring": rep["contour"],
            "field": rep["distance_field"]}


def run_peer(method, inp, out, pad, timeout):
    job = dict(inp["peer"], method=method, out=out, pad=pad)
    start = time.monotonic()
    proc = subprocess.run([PYTHON, "-c", PEER_CHILD, json.dumps(job)], capture_output=True, text=True, timeout=timeout)
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"exit {proc.returncode}: {last_line(proc.stderr) or last_line(proc.stdout)}")
    rep = json.loads(last_line(proc.stdout))
    note = rep["algorithm"] + (", padded" if rep["padded"] else "")
    return {"time": wall, "work": rep["seconds"], "peak": rep["peak_rss_bytes"], "note": note}


def median_row(runs):
    """One row from the runs of one method: median times, the largest peak, the last run's note."""
    row = dict(runs[-1])
    row["times"] = [r["time"] for r in runs]
    for key in ("time", "work", "contouring", "field"):
        values = [r[key] for r in runs if r.get(key) is not None]
        if values:
            row[key] = statistics.median(values)
    row["peak"] = max(r["peak"] for r in runs)
    notes = [row["note"]] if row.get("note") else []
    if row.get("contouring") is not None:
        notes.append(f"contouring {row['contouring']:.2f} s")
    if len(runs) > 1:
        notes.append(f"median of {len(runs)} runs")
    row["note"] = "; ".join(notes)
    return row


def yes_no(value):
    return "yes" if value else "no"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="256,512", help="salt-dome edges, comma-separated (default 256,512; 1024 works)")
    parser.add_argument("--blob-sizes", default="512",
                        help="blobs edges, comma-separated ('' to skip; default 512; 1024 works)")
    parser.add_argument("--gyroid-size", type=int, default=256, help="gyroid-slab size (0: skip; default 256)")
    parser.add_argument("--frog", default=os.path.join(ROOT, "data", "frog", "frogtissue.mhd"),
                        help="frog MetaImage ('' to skip)")
    parser.add_argument("--labels", default="13", help="frog label to mesh (default 13, the skeleton)")
    parser.add_argument("--build", default="build", help="build folder, relative to the repository or absolute (default build)")
    parser.add_argument("--work", default=tempfile.gettempdir(), help="folder for generated volumes, meshes and stats")
    parser.add_argument("--no-pad", action="store_true", help="do not pad peers' volumes where the object touches the border")
    parser.add_argument("--self-intersection-limit", type=int, default=5_000_000,
                        help="check meshes above this many triangles with --no-self-intersections (default 5000000)")
    parser.add_argument("--timeout", type=float, default=3600, help="seconds allowed per run or check (default 3600)")
    parser.add_argument("--keep-meshes", action="store_true", help="keep the output meshes in --work")
    parser.add_argument("--json", help="also write the rows to this JSON file")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of every row per input, interleaved round by round; the row shows the median "
                             "times (default 1)")
    parser.add_argument("--rows", default="",
                        help="only these rows, comma-separated labels as the table prints them (e.g. "
                             "\"isovdb regular,isovdb adaptive,vtk flying edges\"; default: every row)")
    args = parser.parse_args()
    every_row = [label for label, _ in ISOVDB_METHODS + OPENVDB_ROWS + PEERS]
    only = [r.strip() for r in args.rows.split(",") if r.strip()]
    for r in only:
        if r not in every_row:
            sys.exit(f"--rows: unknown row '{r}'; the rows are: {', '.join(every_row)}")

    build = args.build if os.path.isabs(args.build) else os.path.join(ROOT, args.build)
    isovdb = os.path.join(build, "isovdb")
    sample = os.path.join(build, "data", "isovdb-sample")
    openvdb_path = os.path.join(build, "bench", "isovdb-openvdb-path")
    for tool in (isovdb, sample, openvdb_path):
        if not os.path.exists(tool):
            sys.exit(f"{tool} is missing: run scripts/build.sh first (or pass --build)")
    os.makedirs(args.work, exist_ok=True)

    session_start = time.monotonic()
    vers = versions()
    wanted = [(f"salt-dome-{s.strip()}", sample_input, (sample, "salt-dome", int(s), args.work))
              for s in args.sizes.split(",") if s.strip()]
    wanted += [(f"blobs-{s.strip()}", sample_input, (sample, "blobs", int(s), args.work))
               for s in args.blob_sizes.split(",") if s.strip()]
    if args.gyroid_size:
        wanted.append((f"gyroid-slab-{args.gyroid_size}", sample_input,
                       (sample, "gyroid-slab", args.gyroid_size, args.work)))
    if args.frog:
        wanted.append((f"frog-{args.labels}", frog_input, (args.frog, args.labels)))

    rows = []
    inputs = []
    for name, make, make_args in wanted:
        try:
            inputs.append(make(*make_args))
        except Exception as e:  # noqa: BLE001 - an input that cannot be prepared gets an error row
            rows.append({"input": name, "method": "(input)", "error": f"{type(e).__name__}: {e}"})
    for inp in inputs:
        runs = [(label, "isovdb", flags) for label, flags in ISOVDB_METHODS] + \
               [(label, "openvdb", flags) for label, flags in OPENVDB_ROWS] + \
               [(label, "peer", method) for label, method in PEERS]
        runs = [run for run in runs if not only or run[0] in only]
        results = {label: [] for label, _, _ in runs}
        errors = {}
        rounds = max(1, args.repeat)
        for round_index in range(rounds):
            checked = round_index == rounds - 1  # the last round's meshes are validated
            for label, kind, spec in runs:
                if label in errors:
                    continue
                tag = f"{inp['name']}-{label.replace(' ', '-').replace('=', '')}"
                out = os.path.join(args.work, f"peers-{tag}.ply")
                print(f"{inp['name']}: {label} (round {round_index + 1} of {rounds}) ...", file=sys.stderr, flush=True)
                try:
                    if kind == "isovdb":
                        run = run_isovdb(isovdb, inp, label, spec, out, os.path.join(args.work, f"peers-{tag}.json"),
                                         args.timeout)
                    elif kind == "openvdb":
                        run = run_openvdb(openvdb_path, inp, spec, out, args.timeout)
                    else:
                        run = run_peer(spec, inp, out, not args.no_pad, args.timeout)
                    if checked:
                        run["mesh"] = check(isovdb, out, os.path.join(args.work, f"peers-{tag}-check.json"),
                                            args.self_intersection_limit, args.timeout)
                    results[label].append(run)
                except Exception as e:  # noqa: BLE001 - one failing run must not stop the others
                    errors[label] = f"{type(e).__name__}: {e}"
                finally:
                    if not args.keep_meshes and os.path.exists(out):
                        os.remove(out)
        for label, _, _ in runs:
            row = {"input": inp["name"], "method": label}
            if results[label]:
                row.update(median_row(results[label]))
            if label in errors:
                row["error"] = errors[label]
            rows.append(row)

    total = time.monotonic() - session_start
    print()
    print(f"machine: {machine()}")
    print(f"packages: isovdb {os.path.relpath(isovdb, ROOT)}; VTK {vers.get('vtk')} "
          f"(discrete: {vers.get('vtk_discrete', 'n/a')}); scikit-image {vers.get('skimage')}; "
          f"numpy {vers.get('numpy')}; Python {sys.version.split()[0]}")
    for inp in inputs:
        print(f"input {inp['name']}: {inp['desc']}")
    print()
    head = (f"{'input':<16}{'method':<20}{'time s':>8}{'work s':>8}{'field s':>8}{'ratio':>7}{'RSS MiB':>9}{'triangles':>11}"
            f"{'closed':>12}{'nm e/v':>12}{'self-x':>8}{'comps':>7}{'chi':>7}")
    print(head)
    print("-" * len(head))
    base = {r["input"]: r["time"] for r in rows if r["method"] == BASELINE and "error" not in r}
    for r in rows:
        start = f"{r['input']:<16}{r['method']:<20}"
        if "time" not in r:
            print(f"{start}ERROR {r['error']}")
            continue
        ratio = f"{r['time'] / base[r['input']]:.2f}" if r["input"] in base else "n/a"
        field = f"{r['field']:.2f}" if r.get("field") is not None else "-"
        cells = f"{start}{r['time']:>8.2f}{r['work']:>8.2f}{field:>8}{ratio:>7}{r['peak'] / MIB:>9.0f}"
        m = r.get("mesh")
        if m is None:
            print(f"{cells}  ERROR {r['error']}")
            continue
        closed = "yes" if m["closed"] else (f"no:{m['boundary_edges']}" if m["boundary_edges"] else "no")
        nm = f"{m['non_manifold_edges']}/{m['non_manifold_vertices']}"
        selfx = "skip" if m["self_intersections_skipped"] else str(m["self_intersecting_pairs"])
        print(f"{cells}{m['triangles']:>11}{closed:>12}{nm:>12}{selfx:>8}{m['components']:>7}{m['euler_characteristic']:>7}"
              + (f"  ({r['note']})" if r.get("note") else ""))
    print()
    print("time s: wall time around the process (end to end: read -> mesh file; with --repeat, the median); "
          "work s: the process's own read -> write time (median too); field s: the distance field stage (isovdb: "
          "the interface band; openvdb path: topologyToLevelSet on the whole mask); contouring: the stages after "
          "the distance field (partition, meta-cells, stitching; or volumeToMesh); ratio: time / isovdb regular's time on the same input; RSS: peak RSS of the "
          "process; closed: no:N = N boundary edges; nm e/v: non-manifold edges/vertices; self-x: "
          "self-intersecting triangle pairs; chi: Euler characteristic.")
    print(f"whole run {total:.0f} s")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"machine": machine(), "versions": vers, "rows": rows, "seconds": total}, f, indent=2)


if __name__ == "__main__":
    main()
