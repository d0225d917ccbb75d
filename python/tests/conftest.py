"""Shared helpers of the Python tests: where the data and the CLI are, a reader of the
reference CCD queries written in Python (independent of the C++ reader), and a check that a
call releases the GIL."""

from fractions import Fraction
import os
from pathlib import Path
import subprocess
import threading
import time

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
DATA_DIR = Path(os.environ.get("TAILOR_DATA_DIR", HERE.parents[2] / "shared" / "data"))
SOURCE_DIR = Path(os.environ.get("TAILOR_SOURCE_DIR", HERE.parents[1]))
CLI = os.environ.get("TAILOR_CLI", str(SOURCE_DIR / "build" / "release" / "tailor"))


def sanitized():
    return os.environ.get("TAILOR_SANITIZED") == "1"


@pytest.fixture
def data_dir():
    assert DATA_DIR.is_dir(), f"reference data not found at {DATA_DIR}"
    return DATA_DIR


def run_cli(*arguments):
    """Runs the `tailor` CLI; returns (exit code, stderr)."""
    process = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True)
    return process.returncode, process.stderr


def cli_error(*arguments):
    """The message the CLI prints for a usage error (exit code 2), without "error: "."""
    code, stderr = run_cli(*arguments)
    assert code == 2, stderr
    lines = [line for line in stderr.splitlines() if line.startswith("error: ")]
    assert len(lines) == 1, stderr
    return lines[0][len("error: "):]


def read_queries(path, truth_column=True):
    """Reads a reference CCD query CSV: 8 rows per query, `num,den` pairs per coordinate
    (exact doubles), optional 7th truth column. Returns (points, truth): points is a list
    of 8 C-contiguous (n, 3) float64 arrays in argument order, truth a bool array or None."""
    rows, truth = [], []
    for line in Path(path).read_text().splitlines():
        if not line.strip():
            continue
        fields = [field.strip() for field in line.split(",")]
        values = [Fraction(int(fields[2 * i]), int(fields[2 * i + 1])) for i in range(3)]
        point = [float(v) for v in values]
        assert all(Fraction(p) == v for p, v in zip(point, values)), "not exactly a double"
        rows.append(point)
        if truth_column and len(fields) > 6:
            truth.append(int(fields[6]) == 1)
    coordinates = np.array(rows, dtype=np.float64).reshape(-1, 8, 3)
    points = [np.ascontiguousarray(coordinates[:, k, :]) for k in range(8)]
    per_query = np.array(truth[::8], dtype=bool) if truth else None
    return points, per_query


def reference_query_files(data_dir):
    """(path, kind) of every Sample-Queries CSV; kind is 'vertex-face' or 'edge-edge'."""
    files = sorted((data_dir / "ccd-queries").glob("*/*/*.csv"))
    assert files, "no reference CCD queries found"
    return [(path, path.parent.name) for path in files]


def assert_releases_gil(make_call, target_seconds=0.4, max_scale=1 << 20):
    """`make_call(scale)` returns a function that runs one C++ call whose length grows with
    `scale`. Finds a scale where the call takes `target_seconds`, runs it in a thread and
    records when this (main) thread gets to run Python code meanwhile. While a call holds
    the GIL, this thread cannot run at all, so the longest gap would be the whole call;
    a call that releases it leaves only short scheduling gaps. Skipped under the sanitizers,
    where the point is memory errors and the timings mean little."""
    if sanitized():
        pytest.skip("a timing observation; not run under the sanitizers")
    scale = 1
    while True:
        call = make_call(scale)
        start = time.perf_counter()
        call()
        if time.perf_counter() - start >= target_seconds or scale >= max_scale:
            break
        scale *= 2
    timing = {}

    def worker():
        begin = time.perf_counter()
        call()
        timing["call"] = (begin, time.perf_counter())

    thread = threading.Thread(target=worker)
    stamps = [time.perf_counter()]
    thread.start()
    while thread.is_alive():
        time.sleep(0.001)
        stamps.append(time.perf_counter())
    thread.join()
    begin, end = timing["call"]
    inside = [begin] + [s for s in stamps if begin < s < end] + [end]
    longest_gap = max(b - a for a, b in zip(inside, inside[1:]))
    duration = end - begin
    assert duration >= 0.1, f"the call took only {duration:.3f} s: nothing to observe"
    assert longest_gap < duration / 2, (
        f"the main thread did not run for {longest_gap:.3f} s of a {duration:.3f} s call "
        "(GIL held?)")
