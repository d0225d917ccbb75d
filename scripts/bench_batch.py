#!/usr/bin/env python3
"""Throughput of tailor.batch.check on LocalClusters of 1 and 2 workers (docs/batch.md):
simulates N short sequences with `tailor simulate`, checks them all on each cluster size
and prints sequences per minute, frames per second, the per-task overhead (wall time per
task and worker minus the check's own time) and the peak resident memory of each worker.

  PYTHONPATH=build/release/python python3 scripts/bench_batch.py \
      --cli build/release/tailor --sequences 40 --frames 30
"""

import argparse
import os
import resource
import subprocess
import tempfile
import time

from dask.distributed import Client, LocalCluster

from tailor import batch


def peak_rss_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def make_sequences(cli, root, count, frames):
    gestures = ["elbow", "raise", "twist"]
    folders = []
    for i in range(count):
        folder = os.path.join(root, f"seq{i:03d}")
        subprocess.run([cli, "simulate", "--frames", str(frames), "--gesture",
                        gestures[i % 3], "--threads", "1", "--out", folder],
                       check=True, capture_output=True)
        folders.append(folder)
    return folders


def measure(folders, workers, options):
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        batch.check(folders[:workers], client=client)  # workers warm (imports)
        warm = sorted(client.run(peak_rss_mib).values())
        start = time.perf_counter()
        table = batch.check(folders, client=client, **options)
        wall = time.perf_counter() - start
        peaks = sorted(client.run(peak_rss_mib).values())
    assert (table["error"] == "").all(), table["error"]
    n = len(table)
    check = table["seconds"].mean()
    return {
        "workers": workers, "wall_s": wall, "sequences_per_min": n / wall * 60,
        "frames_per_s": table["frames"].sum() / wall, "check_ms_per_task": check * 1e3,
        "overhead_ms_per_task": (wall * workers / n - check) * 1e3,
        "peak_rss_mib_per_worker": peaks, "warm_rss_mib_per_worker": warm,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default="build/release/tailor")
    parser.add_argument("--sequences", type=int, default=40)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--read-ahead", type=int, default=-1,
                        help="frames read ahead per task (-1: automatic, 0: no reader thread)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as root:
        folders = make_sequences(args.cli, root, args.sequences, args.frames)
        results = [measure(folders, w, {"read_ahead": args.read_ahead}) for w in args.workers]
    for r in results:
        print(f"{r['workers']} worker(s): {r['wall_s']:.2f} s, "
              f"{r['sequences_per_min']:.0f} sequences/min, {r['frames_per_s']:.0f} frames/s, "
              f"check {r['check_ms_per_task']:.1f} ms/task, overhead "
              f"{r['overhead_ms_per_task']:.1f} ms/task, peak RSS per worker "
              f"{', '.join(f'{p:.0f}' for p in r['peak_rss_mib_per_worker'])} MiB (after the "
              f"first task: {', '.join(f'{p:.0f}' for p in r['warm_rss_mib_per_worker'])} MiB)")
    if len(results) > 1:
        print(f"speed-up {results[0]['workers']} -> {results[-1]['workers']} workers: "
              f"{results[0]['wall_s'] / results[-1]['wall_s']:.2f}x")


if __name__ == "__main__":
    main()
