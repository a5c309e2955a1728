#!/usr/bin/python3
# SPDX-License-Identifier: BSL-1.0
"""influence2d.dask on one worker against two (a benchmark, never a test):
LocalClusters of worker processes with one thread each, the same calls on
each, every result checked against the single-process call.

1. audit: a layer of --audit-size generated parcels (WKT text, as a layer
   exported from a GIS arrives), in chunks of --chunk-size.
2. study: the precision study's --quick run (the default families, every
   type), one scene per task.
3. pairs: the join of a layer of --pairs-size generated parcels (Polygons
   built once) in two partitions per worker thread, in each number type of
   --pairs-types (certified: little work per polygon against its transfer;
   exact: more). The client holds the layer and sends it.
4. pairs from files: the same parcels as --files WKT files (a layer
   exported from a GIS), read on the workers (dask.bag.read_text) and
   joined there in certified; the single process reads the same files.
5. The scheduler's overhead per task: --tiny-tasks tasks that do nothing,
   submitted at once and gathered, per task.

Each figure is the median of --repeats runs; the single-process calls (one
thread, no Dask) are timed beside them. Run it alone on the machine:

  PYTHONPATH=BUILD/python /usr/bin/python3 python/bench/dask_scaling.py
"""

import argparse
import glob
import os
import sys
import tempfile

import numpy as np
import pandas.testing

import influence2d
import influence2d.dask

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overhead import layer_from, median_seconds  # noqa: E402  (the generated parcels)


def timed(f, repeats):
    """The median time of ``repeats`` calls and the last call's result."""
    out = []
    seconds = median_seconds(lambda: out.append(f()), repeats)
    return seconds, out[-1]


def nothing(x):
    """A task that does nothing: what a task costs the scheduler."""
    return x


def per_task_seconds(client, count, repeats):
    """The time per task of ``count`` tasks that do nothing."""
    return median_seconds(lambda: client.gather(client.map(nothing, range(count), pure=False)), repeats) / count


def measure(workers, o, work):
    """Every measurement on a LocalCluster of ``workers`` one-thread worker
    processes: {name: seconds}; each result checked against the local one."""
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        client.gather(client.map(nothing, range(4 * workers), pure=False))  # workers up and warm
        out = {}
        out["audit"], got = timed(lambda: influence2d.dask.audit(work["audit_layer"], client, chunk_size=o.chunk_size),
                                  o.repeats)
        pandas.testing.assert_frame_equal(got, work["audit_want"])
        out["study"], got = timed(lambda: influence2d.dask.study(client=client), o.repeats)
        for name, table in work["study_want"].items():
            times = [c for c in ("ns_per_query", "ns_per_question") if c in table.columns]
            pandas.testing.assert_frame_equal(got[name].drop(columns=times), table.drop(columns=times))
        for t in o.pairs_types.split(","):
            out["pairs " + t], got = timed(lambda: influence2d.dask.pairs(work["pairs_layer"], client=client,
                                                                          number_type=t), o.repeats)
            np.testing.assert_array_equal(got, work["pairs_want"])
        out["files"], got = timed(lambda: influence2d.dask.pairs(lines_of(work["files"]), client=client), o.repeats)
        np.testing.assert_array_equal(got, work["files_want"])
        out["task"] = per_task_seconds(client, o.tiny_tasks, o.repeats)
        return out


def lines_of(pattern):
    """The WKT lines of the files matching ``pattern`` as a dask.bag, one
    partition per file, read where the tasks run."""
    import dask.bag
    return dask.bag.read_text(pattern).map(str.strip)


def read_files(pattern):
    """The WKT lines of the files matching ``pattern``, read here in order."""
    lines = []
    for path in sorted(glob.glob(pattern)):
        with open(path) as f:
            lines += [line.strip() for line in f]
    return lines


def local_work(o, folder):
    """The inputs and the single-process answers (and their times, one
    thread)."""
    rng = np.random.default_rng(20240601)
    work = {"audit_layer": [g.wkt for g in layer_from(None, o.audit_size, rng)]}
    work["pairs_layer"] = [influence2d.Polygon.from_shapely(g) for g in layer_from(None, o.pairs_size, rng)]
    local = {}
    local["audit"], work["audit_want"] = timed(lambda: influence2d.audit_layer(work["audit_layer"], threads=1),
                                               o.repeats)
    texts = [p.to_wkt() for p in work["pairs_layer"]]
    for k, cut in enumerate(np.array_split(np.arange(len(texts)), o.files)):
        with open(os.path.join(folder, f"part-{k:04d}.wkt"), "w") as f:
            f.write("".join(texts[i] + "\n" for i in cut))
    work["files"] = os.path.join(folder, "part-*.wkt")
    local["files"], work["files_want"] = timed(lambda: influence2d.pairs(read_files(work["files"]), threads=1),
                                               o.repeats)
    local["study"], work["study_want"] = timed(lambda: influence2d.study(), 1)
    for t in o.pairs_types.split(","):
        local["pairs " + t], work["pairs_want"] = timed(
            lambda: influence2d.pairs(work["pairs_layer"], threads=1, number_type=t), o.repeats)
    return work, local


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--audit-size", type=int, default=100_000)
    p.add_argument("--chunk-size", type=int, default=2_000)
    p.add_argument("--pairs-size", type=int, default=100_000)
    p.add_argument("--pairs-types", default="certified,exact")
    p.add_argument("--files", type=int, default=16)
    p.add_argument("--tiny-tasks", type=int, default=2_000)
    p.add_argument("--repeats", type=int, default=3)
    o = p.parse_args()
    import dask
    import distributed
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at the start; dask "
          f"{dask.__version__}, distributed {distributed.__version__}; worker processes of one thread; "
          f"medians of {o.repeats} runs")
    with tempfile.TemporaryDirectory() as folder:
        work, local = local_work(o, folder)
        one, two = measure(1, o, work), measure(2, o, work)
    rows = [("audit", f"audit of {o.audit_size} generated parcels (WKT), chunks of {o.chunk_size}",
             f"{len(work['audit_want'])} findings"),
            ("study", "precision study, the --quick run (every default family and type)",
             f"{int(work['study_want']['summaries']['questions'].sum())} questions")]
    rows += [("pairs " + t, f"pairs of {o.pairs_size} generated parcels, {t}", f"{len(work['pairs_want'])} pairs")
             for t in o.pairs_types.split(",")]
    rows += [("files", f"pairs of the same parcels read from {o.files} WKT files on the workers, certified",
              f"{len(work['files_want'])} pairs")]
    for key, what, size in rows:
        print(f"{what} ({size}): single process {local[key]:.2f} s; 1 worker {one[key]:.2f} s; "
              f"2 workers {two[key]:.2f} s; 2 workers / 1 worker {one[key] / two[key]:.2f}x; same result")
    print(f"scheduler overhead per task ({o.tiny_tasks} tasks that do nothing): "
          f"1 worker {one['task'] * 1e6:.0f} us, 2 workers {two['task'] * 1e6:.0f} us")
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
