# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The module against the tool (byte for byte), its checks of the input, its API."""

import json
import os
import re
import threading
import time

import numpy as np
import pytest

import df_l1_skeleton as dfl1
from conftest import SHARED_DATA, comparable_report, generate, needs_tool, run_tool, same_bytes

# (shape, variant, points, seed, output, stage): a few shapes, variants and every format.
GENERATED = [
    ("y_junction", "noise", 4000, 1, "skeleton.obj", "final"),
    ("torus", "clean", 4000, 2, "skeleton.ply", "final"),
    ("stick_figure", "outliers", 6000, 3, "skeleton.polylines.txt", "final"),
    ("branching_tree", "uneven", 5000, 4, "skeleton.obj", "initial"),
]


def compare_with_tool(input_path, directory, output, stage="final", threads=1, **parameters):
    """Runs the tool and the module on the same file, in folders of the same relative
    layout (so the reports name the same files), and checks that every output agrees."""
    tool_dir, module_dir = os.path.join(directory, "tool"), os.path.join(directory, "module")
    os.makedirs(tool_dir, exist_ok=True)
    os.makedirs(module_dir, exist_ok=True)
    options = [f"--{k.replace('_', '-')}={v}" for k, v in parameters.items()]
    result = run_tool(input_path, output, "--stage", stage, "--threads", threads, "--report", "report.json",
                      "--segmentation", "segmentation.ply", *options, cwd=tool_dir)
    assert result.returncode == 0, result.stderr
    cwd = os.getcwd()
    os.chdir(module_dir)
    try:
        skeleton = dfl1.skeletonize(dfl1.read_point_cloud(input_path), stage=stage, threads=threads, **parameters)
        dfl1.write_skeleton(output, skeleton, segmentation="segmentation.ply", report="report.json")
    finally:
        os.chdir(cwd)
    for name in (output, "segmentation.ply"):
        assert same_bytes(os.path.join(tool_dir, name), os.path.join(module_dir, name)), name
    assert comparable_report(os.path.join(tool_dir, "report.json")) == comparable_report(
        os.path.join(module_dir, "report.json"))
    assert comparable_report(skeleton.report) == comparable_report(os.path.join(tool_dir, "report.json"))
    return skeleton


@needs_tool
@pytest.mark.parametrize("shape,variant,n,seed,output,stage", GENERATED)
def test_same_outputs_as_the_tool_on_generated_shapes(work_dir, shape, variant, n, seed, output, stage):
    directory = os.path.join(work_dir, f"generated_{shape}_{variant}")
    os.makedirs(directory, exist_ok=True)
    cloud = generate(shape, variant, n, seed, os.path.join(directory, "cloud.xyz"))
    skeleton = compare_with_tool(cloud, directory, output, stage)
    # the same points as an array (no PointCloud) give the same skeleton file
    again = dfl1.skeletonize(np.loadtxt(cloud)[:, :3], stage=stage, threads=1)
    path = os.path.join(directory, "from_array_" + output)
    dfl1.write_skeleton(path, again)
    assert same_bytes(path, os.path.join(directory, "tool", output))
    assert np.array_equal(again.point_labels, skeleton.point_labels)


@needs_tool
def test_same_outputs_as_the_tool_with_parameters(work_dir):
    directory = os.path.join(work_dir, "parameters")
    os.makedirs(directory, exist_ok=True)
    cloud = generate("many_armed", "sparse", 3000, 5, os.path.join(directory, "cloud.xyz"))
    compare_with_tool(cloud, directory, "skeleton.obj", threads=2, voxel_resolution=64, denoising="on",
                      upsampling="off", skeletonization_method="l1", repulsion_coefficient=0.3,
                      contraction_stages=8)


SCANS = sorted(f for f in os.listdir(SHARED_DATA) if f.endswith((".xyz", ".ply", ".off"))) \
    if os.path.isdir(SHARED_DATA) else []


@needs_tool
@pytest.mark.skipif(not SCANS, reason=f"the shared data folder {SHARED_DATA} is absent")
def test_same_outputs_as_the_tool_on_the_shared_scans(work_dir):
    for scan in SCANS:
        directory = os.path.join(work_dir, "scans", scan)
        os.makedirs(directory, exist_ok=True)
        path = os.path.abspath(os.path.join(SHARED_DATA, scan))
        try:
            compare_with_tool(path, directory, "skeleton.obj", threads=2)
        except ValueError as e:  # a scan the tool refuses too must fail alike
            result = run_tool(path, os.path.join(directory, "x.obj"))
            assert result.returncode == 1 and str(e) in result.stderr, (scan, str(e), result.stderr)


def cloud_array(n=3000, seed=0):
    """A noisy capsule: a cylinder along x with round ends."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(-1.5, 1.5, n)
    a = rng.uniform(0, 2 * np.pi, n)
    r = 0.4 * np.sqrt(np.clip(1 - np.maximum(np.abs(t) - 1.1, 0) ** 2 / 0.16, 0, 1))
    return np.column_stack([t, r * np.cos(a), r * np.sin(a)])


@pytest.mark.parametrize("points,message", [
    (np.zeros((0, 3)), "skeletonization: the point set is empty"),
    (np.zeros((10, 2)), r"points must be an \(N, 3\) array, got shape \(10, 2\)"),
    (np.zeros(9), r"points must be an \(N, 3\) array, got shape \(9,\)"),
    (np.zeros((4, 3, 1)), r"points must be an \(N, 3\) array"),
    (np.array([[0, 0, 0], [1, np.nan, 0], [0, 1, 1]] * 5, dtype=float), "point 1 has a coordinate that is not finite"),
    (np.array([[0, 0, 0], [1, np.inf, 0], [0, 1, 1]] * 5, dtype=float), "point 1 has a coordinate that is not finite"),
    ([["a", "b", "c"]] * 5, "real numbers, got dtype <U1"),
    (np.array([[1 + 2j, 0, 0]] * 5), "real numbers, got dtype complex128"),
    ([[0, 0], [1, 2, 3]], "points must be an"),
    (np.ones((20, 3)), "all 20 points coincide"),
    (np.column_stack([np.arange(30.0), np.arange(30.0) % 7, np.zeros(30)]), "lie on a plane"),
])
def test_bad_arrays_raise_value_error(points, message):
    with pytest.raises(ValueError, match=message):
        dfl1.skeletonize(points)


def test_bad_parameters():
    points = cloud_array()
    with pytest.raises(ValueError, match=re.escape("voxel_resolution must be an integer in [3, 2048], got 1")):
        dfl1.skeletonize(points, voxel_resolution=1)
    with pytest.raises(ValueError, match="denoising must be one of auto, on, off, got 'sometimes'"):
        dfl1.skeletonize(points, denoising="sometimes")
    with pytest.raises(ValueError, match=re.escape("repulsion_coefficient must be a number in [0, 0.5), got 0.5")):
        dfl1.skeletonize(points, repulsion_coefficient=0.5)
    with pytest.raises(ValueError, match="threads must be"):
        dfl1.skeletonize(points, threads=0)
    with pytest.raises(ValueError, match="exceeds the limit"):
        dfl1.skeletonize(points, voxel_resolution=2048, max_memory="1M")
    with pytest.raises(TypeError, match="unexpected keyword argument 'resolution'"):
        dfl1.skeletonize(points, resolution=10)


def test_layouts_and_dtypes_give_the_same_skeleton():
    base = cloud_array().astype(np.float32).astype(np.float64)
    reference = dfl1.skeletonize(base, threads=1)
    wide = np.zeros((len(base), 6))
    wide[:, 1:4] = base
    for variant in (np.asfortranarray(base), base.astype(np.float32), wide[:, 1:4], base.tolist(),
                    base.astype(">f8")):
        s = dfl1.skeletonize(variant, threads=1)
        assert np.array_equal(s.vertices, reference.vertices) and np.array_equal(s.edges, reference.edges)
    assert reference.statistics == {"vertices": len(reference.vertices), "edges": len(reference.edges),
                                    "components": 1, "cycles": 0, "end_points": 2, "junctions": 0}


def test_skeleton_api():
    points = cloud_array()
    s = dfl1.skeletonize(points)
    v, e = len(s.vertices), len(s.edges)
    assert s.vertices.shape == (v, 3) and s.edges.shape == (e, 2) and s.radii.shape == (v,)
    assert s.edges.min() >= 0 and s.edges.max() < v and (s.radii > 0).all()
    labels = s.point_labels
    assert labels.shape == (len(points),) and labels.max() < v and labels.min() >= -1
    assert sorted(i for b in s.branches for i in b) == sorted(set(range(v))) or len(s.branches) > 1
    lines = s.polylines()
    assert len(lines) == len(s.branches) and all(line.shape[1] == 3 for line in lines)
    assert np.array_equal(lines[0], s.vertices[s.branches[0]])
    g = s.to_networkx()
    assert g.number_of_nodes() == v and g.number_of_edges() == e and g.nodes[0]["radius"] == s.radii[0]
    report = s.report
    assert report["input"] == "" and report["output"] == "" and report["counts"]["skeleton_vertices"] == v
    assert "read" not in report["seconds"] and "write" not in report["seconds"]
    with pytest.raises(ValueError):  # read-only results
        s.vertices[0, 0] = 1


def test_stage_by_stage_class_agrees_with_skeletonize():
    points = cloud_array(seed=3)
    whole = dfl1.skeletonize(points, voxel_resolution=60)
    report = whole.report
    s = dfl1.Skeletonization(points, voxel_resolution=60)
    grid = s.voxel_grid()
    counts = np.bincount(grid.labels.ravel(), minlength=4)
    assert list(counts) == [report["counts"][k] for k in ("exterior_voxels", "boundary_voxels", "interior_voxels",
                                                         "outlier_voxels")]
    assert list(grid.labels.shape) == report["counts"]["grid"]
    field = s.distance_field()
    assert field.distances.max() == pytest.approx(report["counts"]["max_distance"], rel=1e-12)
    initial = s.initial_skeleton()
    assert len(initial.skeleton.vertices) == report["counts"]["initial_skeleton_vertices"]
    assert s.initial_support_radius == pytest.approx(report["parameters"]["initial_support_radius"], rel=1e-15)
    final = s.skeleton()
    assert np.array_equal(final.vertices, whole.vertices) and np.array_equal(final.edges, whole.edges)
    assert np.array_equal(final.point_labels, whole.point_labels)
    samples = s.contracted_samples()
    assert len(samples.stages) == len(report["counts"]["contraction_stages"])
    # a parameter set discards what depends on it
    s.voxel_resolution = 40
    assert s.voxel_resolution == 40 and list(s.voxel_grid().labels.shape) != report["counts"]["grid"]
    with pytest.raises(ValueError, match="voxel_resolution must be"):
        s.voxel_resolution = 2
    assert s.get_parameter("denoising") == "auto" and s.upsampling is True


def test_gil_is_released():
    points = cloud_array(20000)
    ticks = 0
    done = threading.Event()

    def work():
        dfl1.skeletonize(points, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    start = time.perf_counter()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    # with the GIL held the whole time, this thread would tick only at the start
    assert ticks > 20, (ticks, time.perf_counter() - start)


@needs_tool
def test_read_errors_are_the_tools(work_dir):
    path = os.path.join(work_dir, "corrupt.xyz")
    with open(path, "w") as f:
        f.write("0 0 0\n1 abc 2\n")
    with pytest.raises(dfl1.ReadError) as error:
        dfl1.read_point_cloud(path)
    assert isinstance(error.value, ValueError)
    result = run_tool(path, os.path.join(work_dir, "x.obj"))
    assert result.returncode == 1 and str(error.value) in result.stderr
    assert str(error.value) == f"{path}: line 2: expected a number, got 'abc'"
    with pytest.raises(dfl1.ReadError, match="cannot open file: no such file"):
        dfl1.read_point_cloud(os.path.join(work_dir, "missing.ply"))


def test_write_errors(tmp_path):
    s = dfl1.skeletonize(cloud_array())
    with pytest.raises(dfl1.WriteError, match="does not exist"):
        dfl1.write_skeleton(tmp_path / "no" / "skeleton.obj", s)
    with pytest.raises(ValueError, match=r"must end in \.obj, \.ply or \.polylines\.txt"):
        dfl1.write_skeleton(tmp_path / "skeleton.txt", s)
    existing = tmp_path / "skeleton.obj"
    existing.write_text("old")
    with pytest.raises(dfl1.WriteError):  # the report cannot be written: nothing is replaced
        dfl1.write_skeleton(existing, s, report=tmp_path / "no" / "report.json")
    assert existing.read_text() == "old" and sorted(os.listdir(tmp_path)) == ["skeleton.obj"]


def test_stub_and_signature_list_every_parameter():
    import inspect
    stub = open(os.path.join(os.path.dirname(dfl1.__file__), "__init__.pyi"), encoding="utf-8").read()
    block = stub[stub.index("def skeletonize("):stub.index(") -> Skeleton: ...")]
    in_stub = re.findall(r"^\s+(\w+):", block, re.M)
    assert in_stub == ["points", "stage", "threads", "seed", "max_memory"] + list(dfl1.PARAMETERS)
    assert list(inspect.signature(dfl1.skeletonize).parameters) == in_stub
    for name in dfl1.PARAMETERS:
        assert name in dfl1.skeletonize.__doc__ and isinstance(getattr(dfl1.Skeletonization, name), property)
        assert re.search(rf"^    {name}: ", stub, re.M)  # the Skeletonization properties


def test_dense_cloud_is_analysed_through_representatives():
    # 200,000 points of the capsule at V = 30: some 20 points per cell of a third of a
    # voxel on its surface; every point still has a label
    points = cloud_array(200000, seed=5)
    s = dfl1.Skeletonization(points, voxel_resolution=30)
    assert 1000 < s.number_of_analysed_points < len(points) // 5
    final = s.skeleton()
    assert (final.point_labels >= 0).sum() == len(points) - s.number_of_outliers
    assert len(final.vertices) > 2 and len(final.edges) == len(final.vertices) - 1  # one curve, no cycle
    sparse = dfl1.Skeletonization(cloud_array(3000), voxel_resolution=30)
    assert sparse.number_of_analysed_points == 3000 - sparse.number_of_sparse_outliers
