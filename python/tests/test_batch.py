# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The Dask batch: the tool's outputs on 40 clouds with 2 workers, a rerun that skips
them, a worker killed in the middle, a corrupt file among good ones."""

import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from conftest import comparable_report, generate, needs_tool, run_tool, same_bytes

distributed = pytest.importorskip("distributed")
from df_l1_skeleton import batch  # noqa: E402

pytestmark = needs_tool

SHAPES = ["capsule", "y_junction", "star", "torus", "figure_eight", "theta", "stick_figure", "branching_tree",
          "helix", "many_armed", "dumbbell", "disjoint_pair"]
VARIANTS = ["clean", "noise", "outliers", "uneven"]


@pytest.fixture(scope="module")
def clouds(work_dir):
    """40 small generated clouds and the tool's outputs for them (--threads 1)."""
    cloud_dir = os.path.join(work_dir, "batch_clouds")
    tool_dir = os.path.join(work_dir, "batch_tool")
    os.makedirs(cloud_dir)
    os.makedirs(tool_dir)
    jobs = []
    for i in range(40):
        shape, variant = SHAPES[i % len(SHAPES)], VARIANTS[i // len(SHAPES) % len(VARIANTS)]
        jobs.append((shape, variant, 1500 + 50 * i, i, os.path.join(cloud_dir, f"c{i:02d}_{shape}_{variant}.xyz")))

    def make(job):
        path = generate(*job)
        name = os.path.splitext(os.path.basename(path))[0]
        result = run_tool(path, os.path.join(tool_dir, name + ".obj"), "--threads", "1",
                          "--report", os.path.join(tool_dir, name + ".json"))
        assert result.returncode == 0, result.stderr
        return path

    with ThreadPoolExecutor(2) as pool:
        paths = list(pool.map(make, jobs))
    return cloud_dir, tool_dir, paths


def check_against_tool(records, paths, output_dir, tool_dir):
    """Every file once in the summary, in input order, and the tool's outputs."""
    assert [r["input"] for r in records] == paths
    for record, path in zip(records, paths):
        name = os.path.splitext(os.path.basename(path))[0]
        assert record["output"] == os.path.join(output_dir, name + ".obj")
        assert same_bytes(record["output"], os.path.join(tool_dir, name + ".obj")), name
        ours, tools = comparable_report(record["report"]), comparable_report(os.path.join(tool_dir, name + ".json"))
        assert ours.pop("output") == record["output"] and tools.pop("output") == os.path.join(tool_dir, name + ".obj")
        assert ours == tools, name
        assert record["counts"]["vertices"] == tools["counts"]["skeleton_vertices"]
    with open(os.path.join(output_dir, "summary.jsonl"), encoding="utf-8") as f:
        assert [json.loads(line) for line in f] == records
    # no temporary file left
    assert not [n for n in os.listdir(output_dir) if ".tmp." in n]


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        with distributed.Client(cluster) as c:
            yield c


def test_batch_on_two_workers_equals_the_tool_and_resumes(clouds, client, work_dir):
    cloud_dir, tool_dir, paths = clouds
    output_dir = os.path.join(work_dir, "batch_out")
    records = batch.run_batch(batch.list_inputs([cloud_dir]), output_dir, client=client, threads=1, progress=False)
    assert [r["status"] for r in records] == ["ok"] * 40, [r["error"] for r in records if r["error"]]
    assert len({r["worker"] for r in records}) == 2  # both workers took files
    check_against_tool(records, paths, output_dir, tool_dir)
    # rerun: every file is skipped, nothing is rewritten
    before = {n: os.stat(os.path.join(output_dir, n)).st_ino for n in os.listdir(output_dir) if n != "summary.jsonl"}
    again = batch.run_batch(batch.list_inputs([cloud_dir]), output_dir, client=client, threads=1, progress=False)
    assert [r["status"] for r in again] == ["skipped"] * 40
    assert [r["counts"] for r in again] == [r["counts"] for r in records]
    after = {n: os.stat(os.path.join(output_dir, n)).st_ino for n in os.listdir(output_dir) if n != "summary.jsonl"}
    assert after == before
    # a changed input is redone
    os.utime(paths[7])
    third = batch.run_batch(batch.list_inputs([cloud_dir]), output_dir, client=client, threads=1, progress=False)
    assert [r["status"] for r in third] == ["skipped"] * 7 + ["ok"] + ["skipped"] * 32


def test_a_killed_worker_loses_no_file_and_does_none_twice(clouds, work_dir):
    """Kills (SIGKILL) a worker while it runs a task (again if the task had just
    finished, up to five kills); the nanny starts a new one, the
    scheduler gives the task to a worker again. Every file must end up written exactly
    once: each output path is watched during the batch, and a second write would show a
    new inode (the outputs are renamed into place)."""
    cloud_dir, tool_dir, paths = clouds
    output_dir = os.path.join(work_dir, "batch_killed")
    inodes = {}
    killed = []  # (task key, whether its output existed right after the kill)

    def watch():
        for name in os.listdir(output_dir) if os.path.isdir(output_dir) else []:
            if not name.startswith("."):
                try:
                    inodes.setdefault(name, set()).add(os.stat(os.path.join(output_dir, name)).st_ino)
                except FileNotFoundError:
                    pass

    def executing(dask_worker):
        return [str(ts.key) for ts in dask_worker.state.executing]

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        with distributed.Client(cluster) as client:
            result = {}
            runner = threading.Thread(target=lambda: result.update(records=batch.run_batch(
                paths, output_dir, client=client, threads=1, progress=False)))
            runner.start()
            deadline = time.monotonic() + 300
            while runner.is_alive() and time.monotonic() < deadline:
                watch()
                reports = [n for n in inodes if n.endswith(".json")]
                interrupted = [k for k, finished in killed if not finished]
                # a task can finish between the query and the kill: then kill again, later
                if not interrupted and len(killed) < 5 and len(reports) >= 8 + 4 * len(killed):
                    pids = client.run(os.getpid)
                    address = sorted(pids)[0]
                    keys = client.run(executing, workers=[address]).get(address, [])
                    if keys:  # kill it while it runs a task
                        os.kill(pids[address], signal.SIGKILL)
                        name = keys[0].split("-", 2)[2]
                        killed.append((keys[0], os.path.exists(os.path.join(output_dir, name + ".json"))))
                time.sleep(0.005)
            runner.join()
            watch()
    assert killed, "no worker was killed"
    assert any(not finished for _, finished in killed), f"every kill came after its task had finished: {killed}"
    records = result["records"]
    assert [r["status"] for r in records] == ["ok"] * 40, [r["error"] for r in records if r["error"]]
    written_twice = {name: ids for name, ids in inodes.items() if len(ids) > 1 and name != "summary.jsonl"}
    assert not written_twice
    assert len([n for n in inodes if n.endswith(".obj")]) == 40
    check_against_tool(records, paths, output_dir, tool_dir)


def test_a_corrupt_file_is_reported_and_the_others_finish(clouds, work_dir):
    cloud_dir, tool_dir, paths = clouds
    folder = os.path.join(work_dir, "batch_corrupt")
    os.makedirs(folder)
    for path in paths[:5]:
        shutil.copy(path, folder)
    corrupt = os.path.join(folder, "c99_corrupt.xyz")
    with open(corrupt, "w") as f:
        f.write("0 0 0\n1 abc 2\n")
    truncated = os.path.join(folder, "c98_truncated.ply")
    with open(truncated, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 10\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n0 0 0\n1 1 1\n")
    output_dir = os.path.join(work_dir, "batch_corrupt_out")
    command = [sys.executable, "-m", "df_l1_skeleton.batch", folder, output_dir, "--workers", "2", "--threads", "1"]
    first = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert first.returncode == 1, first.stderr
    with open(os.path.join(output_dir, "summary.jsonl"), encoding="utf-8") as f:
        records = {os.path.basename(r["input"]): r for r in map(json.loads, f)}
    assert len(records) == 7
    for bad in (corrupt, truncated):
        record = records[os.path.basename(bad)]
        assert record["status"] == "failed" and record["counts"] is None
        tool = run_tool(bad, os.path.join(work_dir, "x.obj"))  # the tool's message, word for word
        assert tool.returncode == 1 and tool.stderr.strip() == "df_l1_skeleton: " + record["error"]
        assert not os.path.exists(record["output"]) and not os.path.exists(record["report"])
    good = [r for name, r in records.items() if name.startswith("c0")]
    assert len(good) == 5 and all(r["status"] == "ok" for r in good)
    assert "failed" in first.stdout and "line 2: expected a number, got 'abc'" in first.stdout  # the table
    assert "7/7 files (5 ok, 0 skipped, 2 failed)" in first.stderr  # the progress line
    # rerun: the good files are skipped, the bad ones tried and reported again
    second = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert second.returncode == 1
    with open(os.path.join(output_dir, "summary.jsonl"), encoding="utf-8") as f:
        statuses = sorted(r["status"] for r in map(json.loads, f))
    assert statuses == ["failed"] * 2 + ["skipped"] * 5


def test_command_line_usage_errors(work_dir, clouds):
    cloud_dir = clouds[0]
    base = [sys.executable, "-m", "df_l1_skeleton.batch"]
    out = os.path.join(work_dir, "usage_out")
    bad_value = subprocess.run(base + [cloud_dir, out, "--voxel-resolution", "1"], capture_output=True, text=True)
    assert bad_value.returncode == 2
    assert "voxel_resolution must be an integer in [3, 2048], got 1" in bad_value.stderr
    assert subprocess.run(base + [cloud_dir], capture_output=True, text=True).returncode == 2
    assert not os.path.exists(out)
