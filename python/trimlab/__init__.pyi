# Type stubs of the trimlab package (the compiled module trimlab._trimlab).
from typing import Any, Callable, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

Vertices = npt.NDArray[np.float64]  # (n, 3)
Triangles = npt.NDArray[np.int32]  # (m, 3)
Poses = npt.NDArray[np.float64]  # (k, n, 3)
Mesh = Tuple[Vertices, Triangles]
Progress = Optional[Callable[[str, int, int], Any]]
ArrayLike = npt.ArrayLike

class Error(Exception): ...

class MeshLoadError(Error):
    file: str
    line: Optional[int]
    element: str
    reason: str

class MeshSaveError(Error, OSError): ...
class InputError(Error, ValueError): ...
class ParameterError(InputError): ...
class NotTrimmableError(InputError): ...
class SkeletonInputError(InputError): ...
class SegmentationInputError(InputError): ...
class SkinningBonesError(InputError): ...
class Cancelled(Error): ...
class RenderError(Error): ...

def load(source: str) -> Mesh: ...
def load_scene(source: str) -> list[Mesh]: ...
def save(path: str, V: ArrayLike, F: ArrayLike, comment: str = "") -> None: ...
def close_holes(V: ArrayLike, F: ArrayLike) -> Mesh: ...
def info(V: ArrayLike, F: ArrayLike, name: str = "mesh") -> dict[str, Any]: ...
def winding_numbers(
    V: ArrayLike, F: ArrayLike, points: ArrayLike, *, threads: int = 0, progress: Progress = None
) -> npt.NDArray[np.float64]: ...
def demos() -> list[str]: ...
def parameters(operation: str) -> list[dict[str, Any]]: ...
def trim(
    meshes: Union[ArrayLike, Sequence[Tuple[ArrayLike, ArrayLike]]],
    F: Optional[ArrayLike] = None,
    *,
    rule: str = "alternating-border",
    csg: Optional[str] = None,
    rules: Union[None, Mapping[int, str], Sequence[Optional[str]]] = None,
    clip: Optional[Sequence[Sequence[float]]] = None,
    stats: bool = False,
    progress: Progress = None,
) -> Union[Mesh, Tuple[Vertices, Triangles, dict[str, Any]]]: ...
def trim_poses(
    poses: ArrayLike,
    F: ArrayLike,
    *,
    rule: str = "alternating-border",
    clip: Optional[Sequence[Sequence[float]]] = None,
    first: int = 0,
    last: Optional[int] = None,
    stats: bool = False,
    progress: Progress = None,
) -> list[Union[Mesh, Tuple[Vertices, Triangles, dict[str, Any]]]]: ...
def save_poses(
    path: str,
    poses: Sequence[Union[Mesh, Tuple[Vertices, Triangles, dict[str, Any]]]],
    *,
    fps: float = 24.0,
    first: int = 0,
    comment: str = "",
) -> None: ...
def render(
    meshes: Union[ArrayLike, Sequence[Tuple[ArrayLike, ArrayLike]]],
    F: Optional[ArrayLike] = None,
    *,
    width: int = 640,
    height: int = 480,
    rule: str = "alternating-border",
    csg: Optional[str] = None,
    rules: Union[None, Mapping[int, str], Sequence[Optional[str]]] = None,
    trim: bool = True,
    camera: Union[None, str, Sequence[float]] = None,
    backend: str = "reference",
    method: str = "kplus-array",
    threads: int = 0,
) -> dict[str, np.ndarray]: ...
def load_animation(
    source: str, *, rest_pose: int = 0, close_holes: bool = False, progress: Progress = None
) -> Tuple[Poses, Triangles]: ...
def segment(
    poses: ArrayLike,
    F: ArrayLike,
    *,
    clusters: int = ...,
    h: float = ...,
    feature: str = ...,
    reference: str = ...,
    method: str = ...,
    rest_pose: int = 0,
    threads: int = 0,
    name: str = "animation",
    progress: Progress = None,
) -> dict[str, Any]: ...

class SkinningFit:
    @property
    def bone_count(self) -> int: ...
    @property
    def labels(self) -> npt.NDArray[np.uint32]: ...
    @property
    def weights(self) -> npt.NDArray[np.float64]: ...
    @property
    def transforms(self) -> npt.NDArray[np.float64]: ...
    @property
    def rest_positions(self) -> Vertices: ...
    @property
    def approximation(self) -> Poses: ...
    @property
    def error(self) -> dict[str, Any]: ...
    def save_gltf(
        self, path: str, *, fps: float = 24.0, export: str = "rigid", interpolation: str = "linear"
    ) -> dict[str, Any]: ...

def skin(
    poses: ArrayLike,
    F: ArrayLike,
    *,
    bones: int = 8,
    method: str = "rigid",
    chain: Optional[str] = None,
    influences: Optional[int] = None,
    weight_corrections: Optional[bool] = None,
    vertex_corrections: Optional[bool] = None,
    rest_pose: int = 0,
    threads: int = 0,
    reconstruct: bool = False,
    name: str = "animation",
    progress: Progress = None,
) -> SkinningFit: ...
def skeleton(
    V: ArrayLike,
    F: ArrayLike,
    *,
    nodes: int = ...,
    root: int = -1,
    heat_constant: float = ...,
    refine: bool = True,
    max_iterations: int = ...,
    contraction_weight: float = ...,
    contraction_growth: float = ...,
    max_attraction_weight: float = ...,
    progress: Progress = None,
) -> dict[str, Any]: ...
def fit_rig(
    skeleton: Mapping[str, Any],
    poses: ArrayLike,
    *,
    rest_pose: int = 0,
    progress: Progress = None,
) -> dict[str, Any]: ...
