"""tailor.batch: check or simulate many cloth sequences on a Dask cluster.

Each sequence (or scene) is one Dask task that runs the same code as the `tailor` CLI
through the compiled module (``tailor.check_sequence``, ``Simulation.run_to_folder``); the
results come back as pandas DataFrames, one row per sequence. With no client an embedded
``LocalCluster`` (one single-threaded worker process per core) runs the batch;
``scheduler="tcp://host:8786"`` connects to a running cluster instead. A task whose files
are bad returns its error in its row; a task whose worker dies is rerun by Dask on another
worker (the scheduler's ``allowed_failures``), so the rows are complete either way.

The command line (``python3 -m tailor.batch``) is in ``tailor/batch/__main__.py``;
docs/batch.md in the repository has the figures.
"""

import os
import time
from contextlib import contextmanager

import pandas as pd

__all__ = ["CHECK_COLUMNS", "STEP_COLUMNS", "SIMULATE_COLUMNS", "check", "simulate", "sequence_key", "scene_name"]

#: Columns of the DataFrame `check` returns, in order.
CHECK_COLUMNS = [
    "sequence", "obstacle", "frames", "steps", "vf_collisions", "ee_collisions", "collisions",
    "steps_with_contacts", "first_contact_step", "earliest_toi", "earliest_toi_step",
    "frames_with_intersections", "first_intersecting_frame", "vertices", "faces", "seconds",
    "error",
]

#: Columns of the per-step DataFrame of `check(per_step=True)`.
STEP_COLUMNS = [
    "sequence", "step", "vf_collisions", "ee_collisions", "earliest_toi", "end_frame",
    "end_file", "end_checked", "end_intersections", "detect_ms", "check_ms", "read_wait_ms",
    "total_ms",
]

#: Columns of the DataFrame `simulate` returns, in order.
SIMULATE_COLUMNS = [
    "scene", "folder", "frames", "steps", "self_collisions", "obstacle_collisions",
    "intersections", "unresolved", "max_strain", "seconds", "error",
]

#: Columns that differ between two runs of the same batch (wall times).
TIMING_COLUMNS = ["seconds"]


def sequence_key(sequence):
    """The name of a sequence in result rows (and in a resumed results.csv): its frames
    argument as given (a folder, glob or pattern; files joined by spaces)."""
    frames, _ = _split_sequence(sequence)
    return frames if isinstance(frames, str) else " ".join(frames)


def _split_sequence(sequence):
    """(frames, obstacle) of a sequence given as a path, (frames, obstacle) or a dict."""
    if isinstance(sequence, dict):
        frames, obstacle = sequence["frames"], sequence.get("obstacle")
    elif isinstance(sequence, tuple):
        frames, obstacle = sequence
    else:
        frames, obstacle = sequence, None
    if isinstance(frames, (str, os.PathLike)):
        frames = os.fspath(frames)
    else:
        frames = [os.fspath(f) for f in frames]
    return frames, (None if obstacle is None else os.fspath(obstacle))


def _check_task(sequence, options, per_step):
    """One sequence, on a worker: a row dict (and its step rows when `per_step`)."""
    from tailor import check_sequence  # imported on the worker

    frames, obstacle = _split_sequence(sequence)
    row = dict.fromkeys(CHECK_COLUMNS)
    row.update(sequence=sequence_key(sequence), obstacle=obstacle or "", error="")
    start = time.perf_counter()
    steps = []
    try:
        result = check_sequence(frames, obstacle, per_step=per_step, **options)
    except (ValueError, OSError) as e:  # InputError is a ValueError
        row["error"] = str(e)
    else:
        for name in CHECK_COLUMNS:
            if name in result:
                row[name] = result[name]
        row["collisions"] = result["vf_collisions"] + result["ee_collisions"]
        steps = [dict(sequence=row["sequence"], **s) for s in result.get("step_rows", [])]
    row["seconds"] = time.perf_counter() - start
    return row, steps


def scene_name(scene, index):
    """The folder name of a scene's run: a scene file's name without .json, a dict's
    "name" entry, else run_NNNN (its position in the sweep)."""
    if isinstance(scene, (str, os.PathLike)):
        return os.path.splitext(os.path.basename(os.fspath(scene)))[0]
    if isinstance(scene, dict) and "name" in scene:
        return str(scene["name"])
    return f"run_{index:04d}"


def _simulate_task(scene, name, folder, frames, method, threads):
    """One scene, on a worker: runs it into `folder`, returns its summary row."""
    from tailor import SceneConfig, Simulation

    row = dict.fromkeys(SIMULATE_COLUMNS)
    row.update(scene=name, folder=folder, error="")
    start = time.perf_counter()
    try:
        if isinstance(scene, dict):
            config = SceneConfig.from_dict({k: v for k, v in scene.items() if k != "name"})
        else:
            config = SceneConfig.load(os.fspath(scene))
        simulation = Simulation(config, method=method, threads=threads)
        summary = simulation.run_to_folder(folder, frames)
    except (ValueError, OSError) as e:
        row["error"] = str(e)
    else:
        for name in ("frames", "steps", "self_collisions", "obstacle_collisions",
                     "intersections", "unresolved"):
            row[name] = summary[name]
        row["max_strain"] = summary["strain"]["max"]
    row["seconds"] = time.perf_counter() - start
    return row


@contextmanager
def _client(client=None, scheduler=None, workers=None):
    """The client to run on: `client`, one connected to `scheduler`, or an embedded
    LocalCluster of `workers` (default: one per core) single-threaded worker processes."""
    from dask.distributed import Client, LocalCluster

    if client is not None:
        yield client
        return
    if scheduler is not None:
        with Client(scheduler) as own:
            yield own
        return
    count = workers or os.cpu_count() or 1
    with LocalCluster(n_workers=count, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as own:
        yield own


def _run(client, function, items, keys, on_row):
    """Submits one task per item (key: a stable name, so a rerun batch maps to the same
    tasks) and returns the results in item order; `on_row(result)` is called as each
    finishes."""
    from dask.distributed import as_completed

    futures = [client.submit(function, *item, key=key, pure=False)
               for item, key in zip(items, keys)]
    position = {f.key: i for i, f in enumerate(futures)}
    results = [None] * len(futures)
    try:
        for future, result in as_completed(futures, with_results=True):
            results[position[future.key]] = result
            if on_row is not None:
                on_row(result)
    finally:
        client.cancel(futures)
    return results


def _task_keys(prefix, names):
    token = f"{os.getpid()}-{time.monotonic_ns()}"
    return [f"tailor-{prefix}-{token}-{i}-{name}" for i, name in enumerate(names)]


def check(sequences, client=None, scheduler=None, per_step=False, *, workers=None,
          on_row=None, method="paper", threads=1, **options):
    """Checks every sequence as `tailor check` does, one Dask task per sequence.

    `sequences`: folders, globs or printf patterns (a folder written by `tailor simulate`
    takes arm_*.obj as its obstacle), lists of frame files, or (frames, obstacle) pairs or
    {"frames", "obstacle"} dicts. `client`: a dask.distributed Client; else `scheduler`
    ("tcp://host:8786"); else an embedded LocalCluster of `workers` processes (default one
    per core). `method`, `threads` (per task; 1 suits one worker per core) and `options`
    (first_frame, last_frame, check_frames, read_ahead, max_pairs) are those of
    tailor.check_sequence. `on_row(row)` is called with each row (a dict) as it finishes.

    Returns a DataFrame with one row per sequence, in the given order (CHECK_COLUMNS; a bad
    sequence has its message in "error" and empty counts); with `per_step`, a pair
    (sequences, steps) whose second DataFrame has one row per step.
    """
    sequences = list(sequences)
    settings = dict(options, method=method, threads=threads)
    items = [(s, settings, per_step) for s in sequences]
    keys = _task_keys("check", range(len(sequences)))
    report = None if on_row is None else (lambda result: on_row(result[0]))
    with _client(client, scheduler, workers) as c:
        results = _run(c, _check_task, items, keys, report)
    table = pd.DataFrame([row for row, _ in results], columns=CHECK_COLUMNS)
    if not per_step:
        return table
    steps = pd.DataFrame([s for _, rows in results for s in rows], columns=STEP_COLUMNS)
    return table, steps


def simulate(scenes, client=None, scheduler=None, *, out="runs", frames=None, workers=None,
             on_row=None, method="paper", threads=1):
    """Runs a sweep of arm-sleeve scenes, one Dask task per scene, each written to its own
    folder `out`/NAME (scene_name) as `tailor simulate --out` writes it (no pictures).

    `scenes`: dicts shaped like the scene file (an optional "name" entry names the run) or
    scene file paths. `frames` overrides every scene's frame count. `client`, `scheduler`,
    `workers`, `on_row`, `method` and `threads` as in check(). Returns a DataFrame with one
    row per scene (SIMULATE_COLUMNS), in the given order.
    """
    scenes = list(scenes)
    names = [scene_name(s, i) for i, s in enumerate(scenes)]
    if len(set(names)) != len(names):
        raise ValueError("scene names must be unique (each run gets the folder out/NAME)")
    folders = [os.path.join(os.fspath(out), n) for n in names]
    items = [(s, n, f, frames, method, threads) for s, n, f in zip(scenes, names, folders)]
    with _client(client, scheduler, workers) as c:
        rows = _run(c, _simulate_task, items, _task_keys("simulate", range(len(scenes))),
                    on_row)
    return pd.DataFrame(rows, columns=SIMULATE_COLUMNS)
