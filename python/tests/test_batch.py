"""tailor.batch on a two-worker LocalCluster: rows equal `tailor check` run one sequence at
a time, bad input gives an error row while the batch goes on, a worker killed in the middle
of a task is replaced and the rows come out complete and identical, and the command line
resumes from its results file."""

import json
import os
import signal
import subprocess
import sys

from dask import distributed
import pandas as pd
import pytest

from conftest import CLI
import tailor
from tailor import batch


@pytest.fixture(scope="module")
def sequences(tmp_path_factory):
    """Short simulated runs (no contact) and procedural steps with contacts and
    intersections: each a folder, as `tailor check` takes it."""
    root = tmp_path_factory.mktemp("sequences")
    folders = []
    for i, gesture in enumerate(["elbow", "raise", "twist", "elbow"]):
        folder = root / f"sim{i}"
        subprocess.run([CLI, "simulate", "--frames", str(3 + i), "--gesture", gesture,
                        "--out", str(folder)], check=True, capture_output=True)
        folders.append(str(folder))
    for i, scene in enumerate(["folded-cloth", "pleated-cloth"]):
        folder = root / f"gen{i}"
        subprocess.run([CLI, "generate", scene, "--triangles", "1500", "--seed", str(i + 1),
                        "--out", str(folder)], check=True, capture_output=True)
        folders.append(str(folder))
    return folders


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def cli_check(folder, tmp_path):
    """What `tailor check --json-lines` reports for one sequence, in the batch's terms."""
    lines = tmp_path / (os.path.basename(folder) + ".jsonl")
    code = subprocess.run([CLI, "check", folder, "--json-lines", str(lines)],
                          capture_output=True, text=True).returncode
    steps = [json.loads(line) for line in lines.read_text().splitlines()]
    frames = [steps[0]["start"]] + [s["end"] for s in steps]
    intersecting = [f["frame"] for f in frames if not f["intersection_free"]]
    tois = [s["earliest_toi"] for s in steps if s["earliest_toi"] is not None]
    return code, {
        "frames": len(frames),
        "steps": len(steps),
        "vf_collisions": sum(s["vf_collisions"] for s in steps),
        "ee_collisions": sum(s["ee_collisions"] for s in steps),
        "earliest_toi": min(tois) if tois else None,
        "frames_with_intersections": len(intersecting),
        "first_intersecting_frame": intersecting[0] if intersecting else -1,
    }, [(s["step"], s["vf_collisions"], s["ee_collisions"]) for s in steps]


def without_timings(table):
    return table.drop(columns=batch.TIMING_COLUMNS)


def test_rows_equal_the_cli_one_by_one(sequences, client, tmp_path):
    table, steps = batch.check(sequences, client=client, per_step=True)
    assert list(table["sequence"]) == sequences
    assert (table["error"] == "").all(), table["error"]
    assert table["collisions"].sum() > 0  # the comparison covers contacts
    assert table["frames_with_intersections"].sum() > 0
    for row in table.to_dict("records"):
        code, expected, expected_steps = cli_check(row["sequence"], tmp_path)
        assert code == (0 if expected["frames_with_intersections"] == 0 else 1)
        for name, value in expected.items():
            if value is None:
                assert pd.isna(row[name]), name
            else:
                assert row[name] == value, (row["sequence"], name)
        mine = steps[steps["sequence"] == row["sequence"]]
        assert list(zip(mine["step"], mine["vf_collisions"], mine["ee_collisions"])) == \
            expected_steps


def test_bad_sequences_get_their_error_and_the_batch_goes_on(sequences, client, tmp_path):
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "cloth_0000.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    (bad / "cloth_0001.obj").write_text("v 0 0 0\nv 1 0 nonsense\n")
    missing = str(tmp_path / "missing")
    table, steps = batch.check([sequences[0], str(bad), missing, sequences[4]], client=client,
                               per_step=True)
    assert list(steps.columns) == batch.STEP_COLUMNS
    assert set(steps["sequence"]) == {sequences[0], sequences[4]}
    assert table.loc[0, "error"] == "" and table.loc[3, "error"] == ""
    assert table.loc[3, "collisions"] > 0
    assert "cloth_0001.obj" in table.loc[1, "error"]
    assert table.loc[1, "frames"] is None or pd.isna(table.loc[1, "frames"])
    assert "missing" in table.loc[2, "error"]


def test_a_worker_killed_mid_task_is_replaced_and_rows_are_identical(sequences, client,
                                                                     tmp_path):
    reference = batch.check(sequences, client=client)
    marker = str(tmp_path / "killed")

    # Defined here so that it is pickled by value to the workers.
    class KillOnce(distributed.WorkerPlugin):
        """SIGKILLs the first worker that starts a check task, 5 ms into it (inside the
        C++ check), once over the cluster (the marker file says which pid)."""

        name = "tailor-test-kill-once"

        def transition(self, key, start, finish, **kwargs):
            if finish != "executing" or not str(key).startswith("tailor-check"):
                return
            try:
                fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            except FileExistsError:
                return
            os.write(fd, str(os.getpid()).encode())
            os.close(fd)
            import threading
            threading.Timer(0.005, os.kill, (os.getpid(), signal.SIGKILL)).start()

    pids_before = set(client.run(os.getpid).values())
    client.register_worker_plugin(KillOnce())
    try:
        table = batch.check(sequences, client=client)
    finally:
        client.unregister_worker_plugin(KillOnce.name)
    killed = int(open(marker).read())
    assert killed in pids_before
    client.wait_for_workers(2)
    assert killed not in set(client.run(os.getpid).values())
    pd.testing.assert_frame_equal(without_timings(table), without_timings(reference))


def run_batch(*arguments):
    env = dict(os.environ)
    return subprocess.run([sys.executable, "-m", "tailor.batch", *map(str, arguments)],
                          capture_output=True, text=True, env=env)


def test_the_command_line_appends_rows_and_resumes(sequences, tmp_path):
    out = tmp_path / "results.csv"
    first = run_batch("check", *sequences[:2], "--out", out, "--workers", "1")
    assert first.returncode == 0, first.stderr
    assert len(pd.read_csv(out)) == 2
    second = run_batch("check", *sequences[:3], str(tmp_path / "none"), "--out", out,
                       "--workers", "1")
    assert second.returncode == 1, second.stderr  # one row has an error
    assert "2 already in" in second.stderr
    table = pd.read_csv(out, keep_default_na=False)
    assert sorted(table["sequence"]) == sorted(sequences[:3] + [str(tmp_path / "none")])
    assert (table["error"] != "").sum() == 1
    for name, content in (("other.csv", "a,b\n1,2\n"), ("binary.csv", b"\xd1\xff\x00")):
        other = tmp_path / name
        (other.write_bytes if isinstance(content, bytes) else other.write_text)(content)
        bad = run_batch("check", sequences[0], "--out", other)
        assert bad.returncode == 2
        assert f"{other}: not a results file" in bad.stderr
        assert other.read_bytes() == (content if isinstance(content, bytes) else
                                      content.encode())  # left alone


def test_a_sweep_writes_each_run_to_its_folder(client, tmp_path):
    scenes = [{"name": "soft", "sleeve": {"material": {"stretch_stiffness": 5000.0}}},
              {"gesture": {"name": "raise"}},
              {"name": "broken", "no_such_setting": 1}]
    table = batch.simulate(scenes, client=client, out=tmp_path, frames=2)
    assert list(table["scene"]) == ["soft", "run_0001", "broken"]
    assert list(table["error"][:2]) == ["", ""]
    assert "no_such_setting" in table.loc[2, "error"]
    assert list(table["frames"][:2]) == [2, 2]
    for folder in table["folder"][:2]:
        assert sorted(os.listdir(folder))[:3] == ["arm_0000.obj", "arm_0001.obj", "arm_0002.obj"]
        summary = json.loads(open(os.path.join(folder, "summary.json")).read())
        assert summary["frames"] == 2
    checked = batch.check(list(table["folder"][:2]), client=client)
    assert list(checked["frames"]) == [3, 3] and (checked["error"] == "").all()
