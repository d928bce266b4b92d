# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Fixtures of the Python tests: the tool and the generator (DF_L1_TOOL, DF_L1_GENERATE,
set by ctest), generated clouds, and helpers to compare outputs with the tool's."""

import json
import os
import subprocess

import pytest

TOOL = os.environ.get("DF_L1_TOOL")
GENERATE = os.environ.get("DF_L1_GENERATE")
SHARED_DATA = os.environ.get("DF_L1_SHARED_DATA_DIR",
                             os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data"))

needs_tool = pytest.mark.skipif(not (TOOL and GENERATE and os.path.exists(TOOL) and os.path.exists(GENERATE)),
                                reason="DF_L1_TOOL and DF_L1_GENERATE (the built tool and generator) are not set")


def generate(shape, variant, n, seed, path):
    """Writes a generated cloud with df_l1_generate."""
    subprocess.run([GENERATE, shape, variant, str(n), str(seed), str(path)], check=True, stdout=subprocess.DEVNULL)
    return str(path)


def run_tool(*args, cwd=None):
    """Runs the tool quietly; returns the completed process (not checked)."""
    return subprocess.run([TOOL, *map(str, args), "--quiet"], cwd=cwd, capture_output=True, text=True)


# The report's values that vary from run to run: the timings and the process's memory.
def comparable_report(path_or_dict):
    """A report without its timings and measured memory, for comparison."""
    report = path_or_dict if isinstance(path_or_dict, dict) else json.load(open(path_or_dict, encoding="utf-8"))
    report = json.loads(json.dumps(report))
    report["seconds"] = sorted(report["seconds"])  # the stages that ran, not their times
    report.pop("peak_memory_mib")
    for stage in report["counts"].get("contraction_stages", []):
        stage.pop("projection_seconds")
    return report


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


@pytest.fixture(scope="session")
def work_dir(tmp_path_factory):
    """A folder for the session's files (DF_L1_TEST_TMP when ctest sets it, emptied first)."""
    root = os.environ.get("DF_L1_TEST_TMP")
    if root:
        import shutil
        shutil.rmtree(root, ignore_errors=True)
        os.makedirs(root)
        return root
    return str(tmp_path_factory.mktemp("df_l1"))
