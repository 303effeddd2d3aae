# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""isovdb.distributed: one volume meshed by several processes or machines, with Dask.

The volume is cut into slabs of meta-cell layers along z. Each slab is one Dask task: it
reads only its slab of the file (or Zarr array) plus the halo its distance field needs,
computes the band, contours its meta-cells and returns them as bytes (each meta-cell's
mesh and the seam records the stitcher reads). The client takes the slabs' bytes in
order, appends each meta-cell's mesh to the output file as it arrives (it never holds the
whole mesh), keeps only the seam records, and stitches the seams between meta-cells with
the same edge-octree code as one process. The output is the same bytes as
`isovdb extract IN -o OUT.ply` with the same settings.

Dask does the scheduling, the data transfer and the retries: a task whose worker dies is
run again elsewhere (its output is the same bytes, so the file is too). A task that fails
on bad input fails the run with the reader's message, and no output file is left.

    import isovdb.distributed
    isovdb.distributed.extract("salt.nrrd", "salt.ply", method="adaptive")   # a LocalCluster
    isovdb.distributed.extract("salt.nrrd", "salt.ply", client=Client("tcp://host:8786"))

or from a shell, with a running scheduler and workers (`dask scheduler`, `dask worker ADDRESS`):

    python3 -m isovdb.distributed salt.nrrd -o salt.ply --scheduler tcp://host:8786

Masks and scalar fields; a scalar field's value range (its default iso is the middle, and
the caps beyond the data derive from it) is measured first by one task per slab.
"""
import argparse
import inspect
import math
import os
import sys
import time
import uuid

import isovdb

__all__ = ["extract"]


class _Source:
    """What a task needs to read its slab: a file and read_volume()'s keywords, or a Zarr
    array (its store's path and the array's path in it) indexed [z, y, x], read as
    from_numpy reads an array (`read`: threshold, kind, spacing, origin). Small and
    picklable: the tasks carry it, not the data."""

    def __init__(self, source, read):
        self.read = dict(read or {})
        self.zarr = None
        if _is_zarr(source):
            store = getattr(source, "store", None)
            root = getattr(store, "path", None)
            if root is None:
                raise ValueError("isovdb.distributed: a Zarr array must live in a directory store (zarr.open(PATH)) "
                                 "so that every worker can open it")
            self.zarr = (os.path.abspath(os.fspath(root)), source.path)
            self.path = self.zarr[0]
        else:
            # Absolute: the workers run elsewhere (another folder, another machine with the
            # same shared storage), and open the file at this path.
            self.path = os.path.abspath(os.fspath(source))
            if os.path.isdir(self.path):
                self.zarr = (self.path, "")
        if self.zarr:
            unknown = set(self.read) - {"threshold", "kind", "spacing", "origin", "voxel_size"}
            if unknown:
                raise ValueError(f"isovdb.distributed: read keywords for a Zarr array are threshold, kind, spacing "
                                 f"and origin; got {sorted(unknown)}")

    def _array(self):
        import zarr
        array = zarr.open(self.zarr[0], mode="r")
        if self.zarr[1]:
            array = array[self.zarr[1]]
        if not hasattr(array, "shape") or len(array.shape) != 3:
            raise ValueError(f"'{self.path}': expected a 3-D Zarr array indexed [z, y, x]")
        return array

    def volume(self, window):
        """The samples whose grid z lies in window = (begin, end); the others read as holes."""
        if not self.zarr:
            return isovdb.read_volume(self.path, window=window, **self.read)
        import numpy as np
        array = self._array()
        depth = array.shape[0]
        begin, end = max(0, window[0]), min(depth, window[1])
        if begin >= end:  # nothing of the array: no sample, the whole index space and box
            begin = end = 0
        block = np.asarray(array[begin:end])
        kind = self.read.get("kind")
        spacing = self.read.get("spacing", self.read.get("voxel_size", 1.0))
        origin = self.read.get("origin", (0.0, 0.0, 0.0))
        volume = isovdb._from_numpy(block.T, self.read.get("threshold"), spacing, origin, None, kind,
                                    placement=(begin, depth))
        return volume


def _is_zarr(source):
    return type(source).__module__.split(".")[0] == "zarr"


def _range_task(source, window):
    """A field's first pass: the samples of one slab (no halo: the slabs tile z once)."""
    return isovdb._sample_range(source.volume(window))


def _slab_task(source, settings, layers, halo, value_range):
    """One Dask task: layers [begin, end) of meta-cells, as (bytes, figures)."""
    settings = dict(settings)
    if "threads" not in settings:
        try:
            from distributed import get_worker
            settings["threads"] = get_worker().nthreads
        except (ImportError, ValueError, AttributeError):
            pass
    meta_cell = settings["meta_cell"]
    _reset_peak_rss()
    start = time.perf_counter()
    volume = source.volume((layers[0] * meta_cell - halo, layers[1] * meta_cell + halo))
    read_s = time.perf_counter() - start
    data, figures = isovdb._extract_slab(volume, settings, layers, value_range)
    del volume
    figures["slab"]["read_s"] = read_s
    figures["slab"]["seconds"] = time.perf_counter() - start
    figures["slab"]["peak_rss_bytes"] = _peak_rss()
    figures["slab"]["pid"] = os.getpid()
    return data, figures


def _reset_peak_rss():
    """Starts the process's peak RSS over (Linux: clear_refs 5), so each task reports its own."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass


def _peak_rss():
    """The process's peak RSS since _reset_peak_rss (Linux's VmHWM), in bytes."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def _layers_of(header, meta_cell, slab_layers):
    """Slabs [begin, end) of meta-cell layers covering the sampled box along z (a .vdb
    grid's recorded active box when it has none), one layer beyond each face (caps made
    beyond the data lie there)."""
    info = header.info()
    if "sampled_min" in info:
        lo, hi = info["sampled_min"][2], info["sampled_max"][2]
    elif "file_bbox_min" in info["input"]:
        lo, hi = info["input"]["file_bbox_min"][2], info["input"]["file_bbox_max"][2]
    else:
        raise ValueError(f"'{info['name']}': the file records neither its sampled box nor its grid's active box, "
                         "so its slabs are unknown (write it again with OpenVDB or isovdb)")
    first = math.floor((lo - 1) / meta_cell)
    end = math.floor(hi / meta_cell) + 1
    return [(k, min(k + slab_layers, end)) for k in range(first, end, slab_layers)]


def extract(source, output, client=None, *, read=None, slab_layers=1, progress=None, **settings):
    """Meshes `source` into the .ply file `output` with Dask tasks, one per slab of
    meta-cell layers; the same bytes as isovdb.extract(..., output=output) in one process.

    source: a volume file (raw: give read=dict(dims=..., dtype=...); NRRD, MetaImage, SEG-Y)
      or a Zarr array indexed [z, y, x] (a zarr.Array in a directory store, or the store's
      path): a mask (a mask rule in read=, or integer/bool arrays) or a scalar field (SEG-Y
      amplitude, float arrays, read=dict(scalar=True)); a scalar field's value range is
      measured by a first pass of tasks (the default iso and the caps need it).
    output: the .ply path, written through a temporary file (nothing is left on failure).
    client: a dask.distributed Client; None starts a LocalCluster of worker processes (one
      per core, one thread each) for the run and closes it after.
    read: read_volume() keywords for a file (threshold, labels, mask, dims, dtype, ...); for
      a Zarr array: threshold, kind, spacing, origin (from_numpy's).
    slab_layers: meta-cell layers per task (default 1: S voxels of z per task).
    progress: callable(stage: str, percent: int): "slabs" as the slabs arrive at the client
      (in order), then the client's stages (stitching).
    settings: extract()'s keywords (method, meta_cell, max_error, iso, ...), in the regular or
      adaptive method. threads= sets each task's threads (default: the worker's).

    Returns the client's statistics dict plus "slabs": each task's figures (layers, meta-cells,
    bytes and seam bytes returned, seconds, peak RSS of its worker process).
    Raises ValueError for bad input (the reader's message, naming the file).
    """
    if slab_layers < 1:
        raise ValueError(f"slab_layers: expected 1 or more, got {slab_layers}")
    # None is extract()'s default for every keyword; the slabs need the meta-cell size itself.
    settings = {name: value for name, value in settings.items() if value is not None}
    settings.setdefault("meta_cell", inspect.signature(isovdb.extract).parameters["meta_cell"].default)
    meta_cell = settings["meta_cell"]
    if not meta_cell:
        raise ValueError("meta_cell: a distributed run needs meta-cells (16..512), not 0")
    source = _Source(source, read)
    header = source.volume((0, 0))
    slabs = _layers_of(header, meta_cell, slab_layers)
    halo = isovdb._slab_halo(settings)
    if client is None:
        from distributed import Client, LocalCluster
        with LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as own:
            return _run(own, source, header, settings, slabs, halo, output, progress)
    return _run(client, source, header, settings, slabs, halo, output, progress)


def _run(client, source, header, settings, slabs, halo, output, progress):
    run = uuid.uuid4().hex[:12]
    meta_cell = settings["meta_cell"]
    value_range = None
    if header.kind != "mask":
        ranges = client.gather([client.submit(_range_task, source, (b * meta_cell, e * meta_cell), pure=False,
                                              key=f"isovdb-range-{run}-{b}") for b, e in slabs])
        value_range = isovdb._value_range(header, ranges)
    # Dask retries a task whose worker died (and recomputes results lost with one); these
    # retries are for the tasks' own failures that a rerun may cure (a file system hiccup).
    futures = [client.submit(_slab_task, source, settings, layers, halo, value_range, pure=False, retries=1,
                             key=f"isovdb-slab-{run}-{layers[0]}")
               for layers in slabs]
    figures = []

    def pieces():
        # In slab order, so the file's bytes are one process's; each slab's result is
        # released from the cluster as soon as the client has it.
        try:
            for i, future in enumerate(futures):
                data, slab = future.result()
                futures[i] = None
                figures.append(slab["slab"] | {"timings_s": slab.get("timings_s", {})})
                if progress is not None:
                    progress("slabs", int(100 * (i + 1) / len(slabs)))
                yield data
        finally:
            for future in futures:
                if future is not None:
                    future.cancel()

    stats = isovdb._extract_assembled(header, settings, output, pieces(), progress, value_range)
    stats["slabs"] = figures
    return stats


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m isovdb.distributed",
        description="Mesh a volume with Dask workers: the same .ply bytes as `isovdb extract`.")
    parser.add_argument("input", help="volume file (.raw with --dims/--type, .nrrd, .nhdr, .mhd, .mha, .nii, .nii.gz, .sgy) or a "
                                      "Zarr array's directory")
    parser.add_argument("-o", "--output", required=True, help="output mesh (.ply)")
    parser.add_argument("--scheduler", help="Dask scheduler address (tcp://HOST:8786); default: a local cluster")
    parser.add_argument("--method", default="adaptive", choices=["adaptive", "regular"])
    parser.add_argument("--meta-cell", type=int, default=128)
    parser.add_argument("--max-error", type=float, default=1.0)
    parser.add_argument("--slab-layers", type=int, default=1, help="meta-cell layers per task (default 1)")
    parser.add_argument("--threshold", type=float, help="mask: inside = value > THRESHOLD (default 0)")
    parser.add_argument("--labels", type=float, nargs="+", help="mask: inside = value is one of these")
    parser.add_argument("--mask", help='mask: inside = "above A" or "below A"')
    parser.add_argument("--scalar", action="store_true", help="contour the samples as a scalar field at --iso")
    parser.add_argument("--iso", type=float, help="isovalue (default: 0 on masks, the middle of a field's range)")
    parser.add_argument("--clip", type=float, default=0.0, help="scalars: |value| < CLIP stays inactive")
    parser.add_argument("--dims", type=int, nargs=3, help="raw volumes: samples along x y z")
    parser.add_argument("--type", help="raw volumes: sample type (uint8, uint16, float32, ...)")
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")
    args = parser.parse_args(argv)
    read = {}
    if args.threshold is not None:
        read["threshold"] = args.threshold
    if args.labels:
        read["labels"] = args.labels
    if args.mask:
        read["mask"] = args.mask
    if args.scalar:
        read["scalar"] = True
    if args.clip:
        read["clip"] = args.clip
    if args.dims or args.type:
        read["dims"], read["dtype"] = args.dims, args.type
    settings = dict(method=args.method, meta_cell=args.meta_cell, max_error=args.max_error)
    if args.iso is not None:
        settings["iso"] = args.iso

    shown = {}

    def report(stage, percent):
        # Each stage's start and every tenth percent after it, no more.
        last = shown.get(stage)
        if args.quiet or (last is not None and percent // 10 <= last // 10):
            return
        shown[stage] = percent
        print(f"{stage}: {percent}%", file=sys.stderr, flush=True)

    client = None
    if args.scheduler:
        from distributed import Client
        client = Client(args.scheduler)
    try:
        start = time.perf_counter()
        stats = extract(args.input, args.output, client, read=read, slab_layers=args.slab_layers, progress=report,
                        **settings)
    except (ValueError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    finally:
        if client is not None:
            client.close()
    if not args.quiet:
        contour = stats["contour"]
        print(f"mesh: {contour['triangles']:,} triangles, {contour['vertices']:,} vertices, method {contour['method']}, "
              f"{len(stats['slabs'])} slabs, {time.perf_counter() - start:.2f} s")
        print(f"output: {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
