# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Curve skeletons of 3D point clouds (distance-field guided L1-median).

The Python binding of the C++ library DF_L1_skeleton: the same computation as the
command-line tool ``df_l1_skeleton``, whose outputs (skeleton files, segmentation,
``--report`` JSON) it writes byte for byte.

    >>> import numpy as np, df_l1_skeleton as dfl1
    >>> points = np.loadtxt("cloud.xyz")[:, :3]          # any (N, 3) float array
    >>> s = dfl1.skeletonize(points, voxel_resolution=100)
    >>> s.vertices, s.edges, s.radii                     # (V, 3), (E, 2), (V,)
    >>> s.point_labels                                    # skeleton vertex of each point, -1: outlier
    >>> dfl1.write_skeleton("skeleton.obj", s, report="report.json")

Functions: ``skeletonize()`` (points in, ``Skeleton`` out), ``read_point_cloud()`` and
``write_skeleton()`` (the tool's readers and writers), ``parameter_table()``. The class
``Skeletonization`` runs the stages one by one (voxels, distance field, initial
skeleton, contraction) like the C++ class ``CGAL::DF_L1_skeletonization``. Batches of
files, on a local or distributed Dask cluster: ``python3 -m df_l1_skeleton.batch``
(``df_l1_skeleton.batch``).

The computation releases the GIL and runs on ``threads`` threads (default: all cores);
its results do not depend on the number. Bad input raises ``ValueError`` with the
library's message (``ReadError``, a ``ValueError``, for files; ``WriteError``, an
``OSError``, for outputs).
"""

import dataclasses
import inspect
import json
import numbers
import os
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from ._df_l1_skeleton import (
    PointCloud,
    ReadError,
    Skeleton,
    WriteError,
    __version__,
    keep_large_buffers_on_heap,
    parameter_table,
)
from . import _df_l1_skeleton as _core

__all__ = [
    "skeletonize",
    "read_point_cloud",
    "write_skeleton",
    "Skeleton",
    "Skeletonization",
    "PointCloud",
    "VoxelGrid",
    "DistanceField",
    "InitialSkeleton",
    "ContractedSamples",
    "ReadError",
    "WriteError",
    "parameter_table",
    "PARAMETERS",
    "keep_large_buffers_on_heap",
    "__version__",
]

for _class in (PointCloud, Skeleton, ReadError, WriteError):
    _class.__module__ = __name__  # as help() and tracebacks show them
del _class

#: The library's parameters by name: each a dict with ``name``, ``stage`` (the first
#: stage that reads it), ``kind`` (integer, real, boolean, choice), ``range``,
#: ``choices``, ``default`` (None when it derives from the input), ``default_text``
#: and ``help``. The same table makes the tool's options.
PARAMETERS: Dict[str, Dict[str, Any]] = {row["name"]: row for row in parameter_table()}

_PYTHON_TYPES = {"integer": "int", "real": "float", "boolean": "bool", "choice": "str"}


def _parameter_doc() -> str:
    lines = []
    for row in PARAMETERS.values():
        kind = _PYTHON_TYPES[row["kind"]]
        if row["kind"] == "choice":
            values = " | ".join(repr(c) for c in row["choices"])
            what = f"{values}, default {row['default']!r}"
        elif row["kind"] == "boolean":
            what = f"bool, default {row['default']}"
        else:
            default = row["default"] if row["default"] is not None else f"None ({row['default_text']})"
            what = f"{kind} in {row['range']}, default {default}"
        lines.append(f"    {row['name']} : {what}\n        {row['help']}")
    return "\n".join(lines)


def _points_array(points: Any) -> np.ndarray:
    """The points as an (N, 3) float32 or float64 array in native byte order, without a
    copy when they already are one (any strides: C, Fortran, a column slice)."""
    if isinstance(points, PointCloud):
        return points.points
    try:
        array = np.asarray(points)
    except Exception as e:  # ragged lists and the like
        raise ValueError(f"points must be an (N, 3) array of real numbers: {e}") from None
    if array.dtype.kind not in "fiu" or array.dtype.kind == "f" and array.dtype.itemsize > 8:
        raise ValueError(f"points must be an (N, 3) array of real numbers, got dtype {array.dtype}")
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"points must be an (N, 3) array, got shape {array.shape}")
    if array.dtype not in (np.float32, np.float64) or not array.dtype.isnative:
        array = array.astype(np.float64)
    return array


def _parameter_texts(function: str, parameters: Dict[str, Any]) -> List[Tuple[str, str]]:
    """The given parameters as (name, text) pairs for the library's parser, which checks
    them (ValueError with its message); None leaves a parameter at its default."""
    texts = []
    for name, value in parameters.items():
        if name not in PARAMETERS:
            raise TypeError(f"{function}() got an unexpected keyword argument '{name}'")
        if value is None:
            continue
        if isinstance(value, (bool, np.bool_)):
            text = "on" if value else "off"
        elif isinstance(value, numbers.Integral):
            text = str(int(value))
        elif isinstance(value, numbers.Real):
            text = repr(float(value))  # the shortest text that reads back as the same double
        else:
            text = str(value)
        texts.append((name, text))
    return texts


def _threads(threads: Optional[int]) -> int:
    if threads is None:
        return 0
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or not 1 <= threads <= 1024:
        raise ValueError(f"threads must be an integer in [1, 1024] or None (all cores), got {threads!r}")
    return int(threads)


def _max_memory(max_memory: Any) -> float:
    if max_memory is None:
        return 0.0
    if isinstance(max_memory, str):
        return _core._parse_bytes(max_memory)
    if isinstance(max_memory, numbers.Real) and not isinstance(max_memory, bool) and max_memory > 0:
        return float(max_memory)
    raise ValueError(f"max_memory must be a positive number of bytes or a size such as '4G', got {max_memory!r}")


def skeletonize(points, *, stage: str = "final", threads: Optional[int] = None, seed: int = 0,
                max_memory=None, **parameters) -> Skeleton:
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
        raise ValueError(f"seed must be an integer, got {seed!r}")
    texts = _parameter_texts("skeletonize", parameters)
    if isinstance(points, PointCloud):
        return _core._skeletonize_cloud(points, stage, _threads(threads), int(seed), _max_memory(max_memory), texts)
    return _core._skeletonize_array(_points_array(points), stage, _threads(threads), int(seed),
                                    _max_memory(max_memory), texts)


skeletonize.__doc__ = f"""Computes the curve skeleton of a point cloud.

    Runs the stages of the tool ``df_l1_skeleton`` in its order (scattered outliers,
    denoising, upsampling, voxelization, outlier voxels, distance field, initial
    skeleton, and with ``stage="final"`` the L1-median contraction and the skeleton
    graph), without the GIL.

    Parameters
    ----------
    points : array_like of shape (N, 3), or PointCloud
        float32 or float64 arrays in any memory order are read in place (no copy); other
        real dtypes are converted. A ``PointCloud`` of ``read_point_cloud()`` gives the
        report its ``input`` and ``read`` time, as the tool's.
    stage : 'final' | 'initial'
        ``final`` (default): the skeleton of the contracted samples; ``initial``: that
        of the voxel thinning. (The voxels and the distance field: ``Skeletonization``.)
    threads : int, optional
        the number of threads (exactly, as the tool's ``--threads``); default all cores.
        The skeleton does not depend on it.
    seed : int
        written to the report (the stages draw no random numbers).
    max_memory : int, float or str, optional
        refuse (ValueError) a run whose estimated peak memory exceeds this many bytes
        (or ``'512M'``, ``'4G'``); default the memory available.
    **parameters
        the library's parameters, by name (``PARAMETERS``); None or absent: the default.

{_parameter_doc()}

    Returns
    -------
    Skeleton
        ``vertices``, ``edges``, ``radii``, ``point_labels``, ``branches``,
        ``polylines()``, ``to_networkx()``, ``report``.

    Raises
    ------
    ValueError
        bad points (wrong shape or dtype, empty, NaN or infinite, flat, all equal), a
        parameter out of range, or no skeleton; the message is the library's.
    TypeError
        an unknown keyword argument.
    """
skeletonize.__signature__ = inspect.Signature(
    [inspect.Parameter("points", inspect.Parameter.POSITIONAL_OR_KEYWORD),
     inspect.Parameter("stage", inspect.Parameter.KEYWORD_ONLY, default="final", annotation=str),
     inspect.Parameter("threads", inspect.Parameter.KEYWORD_ONLY, default=None, annotation=Optional[int]),
     inspect.Parameter("seed", inspect.Parameter.KEYWORD_ONLY, default=0, annotation=int),
     inspect.Parameter("max_memory", inspect.Parameter.KEYWORD_ONLY, default=None)]
    + [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=row["default"])
       for name, row in PARAMETERS.items()],
    return_annotation=Skeleton)


def read_point_cloud(path) -> PointCloud:
    """Reads a point cloud file with the tool's readers.

    ``.xyz``/``.pts``/``.txt`` (x y z, optional normals, extra columns ignored), ``.ply``
    (ascii or binary), ``.off`` (also ``NOFF``, headerless vertex lists). Returns a
    ``PointCloud``: ``points`` (N, 3) float64, ``normals`` (N, 3) or None, ``path``;
    ``np.asarray(cloud)`` gives the points. The GIL is released while it reads.

    Raises ``ReadError`` (a ValueError) naming the file and the line or vertex, as the
    tool's messages (README, Errors).
    """
    return _core._read_point_cloud(os.fspath(path))


def write_skeleton(path, skeleton: Skeleton, *, segmentation=None, report=None) -> None:
    """Writes a skeleton in the tool's formats, by the extension of ``path``.

    ``.obj`` (``v x y z``, ``l a b``), ``.ply`` (vertex ``x y z radius``, edge
    ``vertex1 vertex2``) or ``.polylines.txt`` (CGAL polylines, one line per branch).
    ``segmentation`` (``.ply``): every input point with its skeleton vertex and branch,
    -1 for outliers (the tool's ``--segmentation``). ``report`` (``.json``): the tool's
    ``--report`` (this write's ``output`` and ``write`` time included; ``Skeleton.report``
    then shows it too).

    As the tool does, every file is written to a temporary file next to it and all are
    renamed together at the end: on an error none is left and existing ones are kept.
    Raises ``WriteError`` (an OSError) when a file cannot be written, ``ValueError`` for
    a bad extension.
    """
    _core._write_skeleton(os.fspath(path), skeleton, "" if segmentation is None else os.fspath(segmentation),
                          "" if report is None else os.fspath(report))


def _skeleton_report(self) -> Dict[str, Any]:
    return json.loads(self._report_json())


Skeleton.report = property(_skeleton_report, doc=(
    "The tool's ``--report`` of the run that made this skeleton, as a dict: ``input`` "
    "(the file of a PointCloud, else ''), ``output`` (the last write_skeleton(), else ''), "
    "``version``, ``parameters`` (the values used), ``seconds`` per stage, ``counts``, "
    "``peak_memory_mib`` (of this process), ``estimated_peak_memory_mib``."))


def _to_networkx(self, multigraph: bool = False):
    """The skeleton as a ``networkx.Graph`` (``networkx.MultiGraph`` with
    ``multigraph=True``, which keeps parallel edges): node ``i`` has attributes ``pos``
    (x, y, z) and ``radius``. Needs networkx (Debian: python3-networkx)."""
    import networkx as nx

    g = nx.MultiGraph() if multigraph else nx.Graph()
    for i, (p, r) in enumerate(zip(self.vertices.tolist(), self.radii.tolist())):
        g.add_node(i, pos=tuple(p), radius=r)
    g.add_edges_from(self.edges.tolist())
    return g


Skeleton.to_networkx = _to_networkx


@dataclasses.dataclass(frozen=True)
class VoxelGrid:
    """The labelled voxels (``Skeletonization.voxel_grid()``).

    ``labels[i, j, k]`` (uint8, shape (nx, ny, nz)): 0 exterior, 1 boundary, 2 interior,
    3 outlier; voxel (i, j, k) is the cube ``origin + [i, i+1] x [j, j+1] x [k, k+1] *
    voxel_size`` (input units)."""

    origin: np.ndarray
    voxel_size: float
    labels: np.ndarray


@dataclasses.dataclass(frozen=True)
class DistanceField:
    """The distance field (``Skeletonization.distance_field()``): ``distances[i, j, k]``
    (float64, input units), from each voxel centre to the nearest voxel that is not
    interior; grid as in ``VoxelGrid``."""

    origin: np.ndarray
    voxel_size: float
    distances: np.ndarray


@dataclasses.dataclass(frozen=True)
class InitialSkeleton:
    """The initial skeleton (``Skeletonization.initial_skeleton()``): ``skeleton`` (a
    ``Skeleton``), ``skeleton_voxels`` ((S, 3) centres of all skeleton voxels, the
    attractors of the contraction) and ``thinning_parameters`` (TP1..3, voxel units)."""

    skeleton: Skeleton
    skeleton_voxels: np.ndarray
    thinning_parameters: Tuple[float, float, float]


@dataclasses.dataclass(frozen=True)
class ContractedSamples:
    """The contracted samples (``Skeletonization.contracted_samples()``): ``points``
    (P, 3), ``roles`` (uint8: 0 free, 1 branch point, 2 removed), ``support_radii``
    (P,), ``edges`` (B, 2) of the branches, ``initial_support_radius`` and ``stages``
    (one dict per support-radius stage, as the report's ``contraction_stages``)."""

    points: np.ndarray
    roles: np.ndarray
    support_radii: np.ndarray
    edges: np.ndarray
    initial_support_radius: float
    stages: List[Dict[str, Any]]


class Skeletonization:
    """The stages one by one, like the C++ class ``CGAL::DF_L1_skeletonization``.

    Each stage method runs the stages before it when they have not run, and does nothing
    when it has; each result method runs the stages it needs. Every parameter is a
    property (``s.voxel_resolution = 64``): its getter returns the value used (derived
    defaults resolved, which runs the stages they derive from), its setter checks the
    value and discards only the results that depend on it. The computation releases the
    GIL and runs on ``threads`` threads.

        >>> s = Skeletonization(points, voxel_resolution=80)
        >>> grid = s.voxel_grid()                  # VoxelGrid
        >>> field = s.distance_field()             # DistanceField
        >>> initial = s.initial_skeleton()         # InitialSkeleton
        >>> final = s.skeleton()                   # Skeleton

    ``skeletonize()`` runs the same stages in one call and adds the tool's report.
    """

    def __init__(self, points, *, threads: Optional[int] = None, max_memory=None, **parameters):
        """Reads the points (an (N, 3) array, read in place, or a ``PointCloud``) and the
        parameters (as ``skeletonize()``). Raises ValueError as ``skeletonize()``."""
        texts = _parameter_texts("Skeletonization", parameters)
        self._impl = _core._Skeletonization(_points_array(points), _threads(threads), _max_memory(max_memory), texts)

    def flag_outliers(self) -> None:
        """Flags the scattered outliers."""
        self._impl.flag_outliers()

    def denoise(self) -> None:
        """Estimates the surface noise and, as ``denoising`` says, smooths the points."""
        self._impl.denoise()

    def upsample(self) -> None:
        """Adds points in the sparse regions, unless ``upsampling`` is off."""
        self._impl.upsample()

    def voxelize(self) -> None:
        """Voxelizes the kept and added points (multi-scale)."""
        self._impl.voxelize()

    def remove_outlier_voxels(self) -> None:
        """Removes the outlier voxels and flags their points."""
        self._impl.remove_outlier_voxels()

    def compute_distance_field(self) -> None:
        """Computes the exact Euclidean distance field of the voxels."""
        self._impl.compute_distance_field()

    def extract_initial_skeleton(self) -> None:
        """Extracts the initial skeleton by multi-scale thinning."""
        self._impl.extract_initial_skeleton()

    def contract(self) -> bool:
        """Runs one support-radius stage of the contraction; returns False, running
        nothing, once it has converged."""
        return self._impl.contract()

    def contract_until_convergence(self) -> None:
        """Runs the stages of the contraction until it converges."""
        self._impl.contract_until_convergence()

    def convert_to_skeleton(self) -> None:
        """Builds the final skeleton from the contracted samples."""
        self._impl.convert_to_skeleton()

    @property
    def number_of_input_points(self) -> int:
        """The number of input points."""
        return self._impl.number_of_input_points

    @property
    def bbox_diagonal(self) -> float:
        """d_bb, the diagonal of the points' bounding box."""
        return self._impl.bbox_diagonal

    @property
    def estimated_peak_memory(self) -> float:
        """The estimate of the peak memory of the whole skeletonization, in bytes."""
        return self._impl.estimated_peak_memory

    @property
    def surface_noise(self) -> float:
        """The estimated noise of the surface (input units)."""
        return self._impl.surface_noise

    @property
    def residual_growth(self) -> float:
        """How the noise estimate grows from 10 to 40 neighbours per fit (0 when not measured)."""
        return self._impl.residual_growth

    @property
    def denoised(self) -> bool:
        """Whether the points were smoothed before voxelization."""
        return self._impl.denoised

    @property
    def number_of_outliers(self) -> int:
        """The number of input points flagged as outliers (scattered, or in outlier voxels)."""
        return self._impl.number_of_outliers

    @property
    def number_of_sparse_outliers(self) -> int:
        """The number of input points flagged as scattered outliers."""
        return self._impl.number_of_sparse_outliers

    @property
    def number_of_analysed_points(self) -> int:
        """The number of points the stages from the smoothing to the contraction analyse:
        those not flagged as scattered outliers, or one of them per cell of a third of a
        voxel in a cloud denser than its voxels (every point is still flagged and
        assigned, a point left out as the representative of its cell)."""
        return self._impl.number_of_analysed_points

    def outlier_flags(self) -> np.ndarray:
        """(N,) bool array: the outlier flag of every input point."""
        return self._impl.outlier_flags()

    def kept_points(self) -> np.ndarray:
        """(K, 3) array: the points that are not scattered outliers, as the later stages
        use them (smoothed when ``denoised``)."""
        return self._impl.kept_points()

    def added_points(self) -> np.ndarray:
        """(A, 3) array: the points added in sparse regions."""
        return self._impl.added_points()

    def voxel_grid(self) -> VoxelGrid:
        """The voxels after outlier removal."""
        return VoxelGrid(**self._impl.voxel_grid())

    def distance_field(self) -> DistanceField:
        """The distance field."""
        return DistanceField(**self._impl.distance_field())

    def initial_skeleton(self) -> InitialSkeleton:
        """The initial skeleton."""
        d = self._impl.initial_skeleton()
        return InitialSkeleton(d["skeleton"], d["skeleton_voxels"], tuple(d["thinning_parameters"]))

    def contracted_samples(self) -> ContractedSamples:
        """The contracted samples, as the stages run by ``contract()`` left them (all
        stages when the contraction has not started)."""
        return ContractedSamples(**self._impl.contracted_samples())

    def skeleton(self) -> Skeleton:
        """The final skeleton (no report: ``skeletonize()`` makes one)."""
        return self._impl.skeleton()

    def get_parameter(self, name: str):
        """The value of parameter ``name`` used by the stages (a derived default is
        resolved, which runs the stages it derives from)."""
        if name not in PARAMETERS:
            raise KeyError(f"unknown parameter '{name}'")
        return self._impl.get_parameter(name)

    def set_parameter(self, name: str, value) -> None:
        """Sets parameter ``name`` (ValueError out of range), discarding the results of
        the stages that depend on it."""
        for n, text in _parameter_texts("set_parameter", {name: value}):
            self._impl.set_parameter(n, text)


def _parameter_property(name: str, row: Dict[str, Any]) -> property:
    return property(lambda self: self.get_parameter(name),
                    lambda self, value: self.set_parameter(name, value),
                    doc=f"{row['help']} ({_PYTHON_TYPES[row['kind']]}, default {row['default_text']})")


for _name, _row in PARAMETERS.items():
    setattr(Skeletonization, _name, _parameter_property(_name, _row))
del _name, _row
