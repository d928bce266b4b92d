# Type stubs of df_l1_skeleton (the package and its compiled part _df_l1_skeleton).
# python/tests/test_module.py checks that skeletonize() lists every library parameter.
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Literal, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, os.PathLike]
Size = Union[int, float, str]

class ReadError(ValueError): ...
class WriteError(OSError): ...

PARAMETERS: Dict[str, Dict[str, Any]]

def parameter_table() -> List[Dict[str, Any]]: ...
def keep_large_buffers_on_heap() -> None: ...

class PointCloud:
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @property
    def normals(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def path(self) -> str: ...
    def __len__(self) -> int: ...
    def __array__(self, dtype: Any = ...) -> np.ndarray: ...

class Skeleton:
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def radii(self) -> npt.NDArray[np.float64]: ...
    @property
    def point_labels(self) -> npt.NDArray[np.int64]: ...
    @property
    def point_branches(self) -> npt.NDArray[np.int64]: ...
    @property
    def branches(self) -> List[List[int]]: ...
    @property
    def statistics(self) -> Dict[str, int]: ...
    @property
    def report(self) -> Dict[str, Any]: ...
    def polylines(self) -> List[npt.NDArray[np.float64]]: ...
    def to_networkx(self, multigraph: bool = ...) -> Any: ...

def skeletonize(
    points: Union[npt.ArrayLike, PointCloud],
    *,
    stage: Literal["final", "initial"] = ...,
    threads: Optional[int] = ...,
    seed: int = ...,
    max_memory: Optional[Size] = ...,
    denoising: Optional[Literal["auto", "on", "off"]] = ...,
    denoising_neighbors: Optional[int] = ...,
    upsampling: Optional[bool] = ...,
    upsampling_neighbors: Optional[int] = ...,
    upsampling_radius: Optional[float] = ...,
    voxel_resolution: Optional[int] = ...,
    initial_voxel_size: Optional[float] = ...,
    exterior_propagation_steps: Optional[int] = ...,
    outlier_component_size: Optional[int] = ...,
    thinning_coefficient: Optional[float] = ...,
    spur_length_ratio: Optional[float] = ...,
    skeletonization_method: Optional[Literal["df_l1", "l1"]] = ...,
    number_of_samples: Optional[int] = ...,
    repulsion_coefficient: Optional[float] = ...,
    initial_support_radius: Optional[float] = ...,
    support_radius_growth: Optional[float] = ...,
    branch_directionality: Optional[float] = ...,
    number_of_iterations: Optional[int] = ...,
    contraction_stages: Optional[int] = ...,
) -> Skeleton: ...
def read_point_cloud(path: PathLike) -> PointCloud: ...
def write_skeleton(
    path: PathLike,
    skeleton: Skeleton,
    *,
    segmentation: Optional[PathLike] = ...,
    report: Optional[PathLike] = ...,
) -> None: ...

@dataclass(frozen=True)
class VoxelGrid:
    origin: npt.NDArray[np.float64]
    voxel_size: float
    labels: npt.NDArray[np.uint8]

@dataclass(frozen=True)
class DistanceField:
    origin: npt.NDArray[np.float64]
    voxel_size: float
    distances: npt.NDArray[np.float64]

@dataclass(frozen=True)
class InitialSkeleton:
    skeleton: Skeleton
    skeleton_voxels: npt.NDArray[np.float64]
    thinning_parameters: Tuple[float, float, float]

@dataclass(frozen=True)
class ContractedSamples:
    points: npt.NDArray[np.float64]
    roles: npt.NDArray[np.uint8]
    support_radii: npt.NDArray[np.float64]
    edges: npt.NDArray[np.int64]
    initial_support_radius: float
    stages: List[Dict[str, Any]]

class Skeletonization:
    denoising: str
    denoising_neighbors: int
    upsampling: bool
    upsampling_neighbors: int
    upsampling_radius: float
    voxel_resolution: int
    initial_voxel_size: float
    exterior_propagation_steps: int
    outlier_component_size: int
    thinning_coefficient: float
    spur_length_ratio: float
    skeletonization_method: str
    number_of_samples: int
    repulsion_coefficient: float
    initial_support_radius: float
    support_radius_growth: float
    branch_directionality: float
    number_of_iterations: int
    contraction_stages: int
    def __init__(
        self,
        points: Union[npt.ArrayLike, PointCloud],
        *,
        threads: Optional[int] = ...,
        max_memory: Optional[Size] = ...,
        **parameters: Any,
    ) -> None: ...
    def flag_outliers(self) -> None: ...
    def denoise(self) -> None: ...
    def upsample(self) -> None: ...
    def voxelize(self) -> None: ...
    def remove_outlier_voxels(self) -> None: ...
    def compute_distance_field(self) -> None: ...
    def extract_initial_skeleton(self) -> None: ...
    def contract(self) -> bool: ...
    def contract_until_convergence(self) -> None: ...
    def convert_to_skeleton(self) -> None: ...
    @property
    def number_of_input_points(self) -> int: ...
    @property
    def bbox_diagonal(self) -> float: ...
    @property
    def estimated_peak_memory(self) -> float: ...
    @property
    def surface_noise(self) -> float: ...
    @property
    def residual_growth(self) -> float: ...
    @property
    def denoised(self) -> bool: ...
    @property
    def number_of_outliers(self) -> int: ...
    @property
    def number_of_sparse_outliers(self) -> int: ...
    @property
    def number_of_analysed_points(self) -> int: ...
    def outlier_flags(self) -> npt.NDArray[np.bool_]: ...
    def kept_points(self) -> npt.NDArray[np.float64]: ...
    def added_points(self) -> npt.NDArray[np.float64]: ...
    def voxel_grid(self) -> VoxelGrid: ...
    def distance_field(self) -> DistanceField: ...
    def initial_skeleton(self) -> InitialSkeleton: ...
    def contracted_samples(self) -> ContractedSamples: ...
    def skeleton(self) -> Skeleton: ...
    def get_parameter(self, name: str) -> Any: ...
    def set_parameter(self, name: str, value: Any) -> None: ...
