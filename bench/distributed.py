#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""isovdb.distributed (Dask) against one `isovdb extract` process on the same input and
settings: wall time, peak RSS per worker process and of the client, bytes of seam records
moved (in all and per meta-cell), time in stitching, and whether the output file is the
CLI's bytes. Inputs: generated blobs (surface-heavy) and the salt dome at each --sizes.

Run on demand, never in CI:
    /usr/bin/python3 bench/distributed.py [--sizes 1024] [--workers 1,2] [--method adaptive]
        [--shapes blobs,salt-dome] [--repeat 3] [--work DIR] [--build build]
It builds nothing: run scripts/build.sh first (BUILD/isovdb, BUILD/python, BUILD/data/isovdb-sample).

Peak RSS: each task's worker process from the task's start (Linux clear_refs, VmHWM), the
client's (this process) from the run's start; both include the interpreter, Dask and the
module (about 100-150 MB before any work).

Protocol: each worker is a process with one thread (LocalCluster(processes=True)), each
task runs with threads=1; the single process runs with --threads W for W workers, so both
sides use the same cores. The cluster is started before the clock (a cluster is long-lived;
its start-up is reported apart). --repeat N runs the rows of an input N times interleaved
(CLI, W=1, W=2, CLI, ...) and reports medians; RSS figures are the maxima.
"""
import argparse
import filecmp
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MIB = 1 << 20
# This file's name is Dask's package's: its folder must not shadow `import distributed`
# (here, and in the worker processes, which start with this process's sys.path).
sys.path = [p for p in sys.path if os.path.abspath(p or os.curdir) != os.path.dirname(os.path.abspath(__file__))]


def generate(sample, shape, size, work):
    path = os.path.join(work, f"{shape}-{size}.nrrd")
    if not os.path.exists(path):
        subprocess.run([sample, shape, "-n", str(size), "-o", path], check=True, capture_output=True)
    return path


def run_cli(cli, volume, out, method, meta_cell, threads, work):
    stats_path = os.path.join(work, "cli-stats.json")
    start = time.perf_counter()
    subprocess.run([cli, "-q", "extract", volume, "-o", out, "--method", method, "--meta-cell", str(meta_cell),
                    "--threads", str(threads), "--stats", stats_path], check=True, capture_output=True)
    wall = time.perf_counter() - start
    with open(stats_path) as f:
        stats = json.load(f)
    return {"wall": wall, "peak_rss": stats["memory"]["peak_rss_bytes"],
            "triangles": stats["contour"]["triangles"]}


def run_dask(client, volume, out, method, meta_cell, slab_layers):
    import isovdb.distributed
    isovdb.distributed._reset_peak_rss()
    start = time.perf_counter()
    stats = isovdb.distributed.extract(volume, out, client, method=method, meta_cell=meta_cell,
                                       slab_layers=slab_layers, threads=1)
    wall = time.perf_counter() - start
    slabs = stats["slabs"]
    per_worker = {}
    for s in slabs:
        per_worker[s["pid"]] = max(per_worker.get(s["pid"], 0), s["peak_rss_bytes"])
    meta_cells = sum(s["meta_cells"] for s in slabs)
    seam = sum(s["seam_bytes"] for s in slabs)
    return {"wall": wall, "worker_rss": max(per_worker.values()) if per_worker else 0,
            "client_rss": isovdb.distributed._peak_rss(),
            "seam_bytes": seam, "bytes": sum(s["bytes"] for s in slabs), "meta_cells": meta_cells,
            "slabs": len(slabs), "stitch": stats["timings_s"].get("stitch", 0.0),
            "task_seconds": sum(s["seconds"] for s in slabs), "triangles": stats["contour"]["triangles"],
            "per_slab": slabs, "client_timings": stats["timings_s"], "output_bytes": os.path.getsize(out)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1024")
    parser.add_argument("--shapes", default="blobs,salt-dome")
    parser.add_argument("--workers", default="1,2")
    parser.add_argument("--method", default="adaptive")
    parser.add_argument("--meta-cell", type=int, default=128)
    parser.add_argument("--slab-layers", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--build", default="build")
    parser.add_argument("--work", default=tempfile.gettempdir())
    parser.add_argument("--per-slab", action="store_true",
                        help="also print each task's figures (the inputs of a scaling model) for the last run")
    args = parser.parse_args()
    build = args.build if os.path.isabs(args.build) else os.path.join(ROOT, args.build)
    sys.path.insert(0, os.path.join(build, "python"))
    os.environ["PYTHONPATH"] = os.path.join(build, "python") + os.pathsep + os.environ.get("PYTHONPATH", "")
    from distributed import Client, LocalCluster

    cli = os.path.join(build, "isovdb")
    sample = os.path.join(build, "data", "isovdb-sample")
    workers = [int(w) for w in args.workers.split(",")]
    clusters = {}
    for w in workers:
        start = time.perf_counter()
        cluster = LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None)
        clusters[w] = (cluster, Client(cluster), time.perf_counter() - start)

    print(f"# {platform.node()}: {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"method {args.method}, meta-cell {args.meta_cell}, {args.slab_layers} layer(s) per task; "
          f"median of {args.repeat}; cluster start-up " +
          ", ".join(f"{w} worker(s) {c[2]:.1f} s" for w, c in clusters.items()))
    print("| input | run | wall s | ratio to CLI | peak RSS MiB (per worker / client) | slabs | meta-cells | "
          "seam bytes (total, per meta-cell) | stitch s | same bytes |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for size in [int(s) for s in args.sizes.split(",")]:
        for shape in args.shapes.split(","):
            volume = generate(sample, shape, size, args.work)
            rows = {}
            for _ in range(args.repeat):
                for w in workers:
                    out = os.path.join(args.work, f"cli-{w}.ply")
                    rows.setdefault(("cli", w), []).append(
                        run_cli(cli, volume, out, args.method, args.meta_cell, w, args.work))
                    dask_out = os.path.join(args.work, f"dask-{w}.ply")
                    result = run_dask(clusters[w][1], volume, dask_out, args.method, args.meta_cell,
                                      args.slab_layers)
                    result["same"] = filecmp.cmp(out, dask_out, shallow=False)
                    rows.setdefault(("dask", w), []).append(result)
            for w in workers:
                cli_runs, dask_runs = rows[("cli", w)], rows[("dask", w)]
                cli_wall = statistics.median(r["wall"] for r in cli_runs)
                dask_wall = statistics.median(r["wall"] for r in dask_runs)
                last = dask_runs[-1]
                print(f"| {shape} {size}³ | CLI --threads {w} | {cli_wall:.2f} | 1.00 | "
                      f"{max(r['peak_rss'] for r in cli_runs) / MIB:.0f} | | | | | |")
                print(f"| {shape} {size}³ | Dask {w} worker(s) | {dask_wall:.2f} | {dask_wall / cli_wall:.2f} | "
                      f"{max(r['worker_rss'] for r in dask_runs) / MIB:.0f} / "
                      f"{max(r['client_rss'] for r in dask_runs) / MIB:.0f} | {last['slabs']} | {last['meta_cells']} | "
                      f"{last['seam_bytes'] / MIB:.1f} MiB, {last['seam_bytes'] / max(1, last['meta_cells']) / 1024:.0f} KiB | "
                      f"{statistics.median(r['stitch'] for r in dask_runs):.2f} | "
                      f"{'yes' if all(r['same'] for r in dask_runs) else 'NO'} |")
                if args.per_slab:
                    print(f"<!-- {shape} {size}, {w} worker(s): output {last['output_bytes'] / MIB:.1f} MiB, "
                          f"task seconds {last['task_seconds']:.2f}, client timings {last['client_timings']} -->")
                    for slab in last["per_slab"]:
                        print(f"<!--   layers {slab['layers']}: {slab['meta_cells']} meta-cells, "
                              f"{slab['bytes'] / MIB:.2f} MiB ({slab['seam_bytes'] / MIB:.2f} seam), "
                              f"read {slab['read_s']:.2f} s of {slab['seconds']:.2f} s, "
                              f"peak {slab['peak_rss_bytes'] / MIB:.0f} MiB -->")
            sys.stdout.flush()
    for cluster, client, _ in clusters.values():
        client.close()
        cluster.close()


if __name__ == "__main__":
    main()
