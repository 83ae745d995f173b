"""Type stubs of the scbt extension module (python/scbt_module.cc)."""

from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

# A frame: uint8, shape (H, W), (H, W, 1), (H, W, 3) BGR or (H, W, 4) BGRA.
Frame = npt.NDArray[np.uint8]
# (N, 2) x, y coordinates; anything numpy converts to float64 of that shape.
PolygonLike = Union[npt.NDArray[np.floating[Any]], npt.NDArray[np.integer[Any]], Sequence[Sequence[float]]]
# (M, 4) rows of x1, y1, x2, y2.
SegmentsLike = Union[npt.NDArray[np.floating[Any]], Sequence[Sequence[float]]]
FloatArray = npt.NDArray[np.float64]

class BoundaryEvidence:
    """What a frame's confidence was computed from (docs/loss-handling.md)."""

    @property
    def gap_share(self) -> float: ...
    @property
    def edge_support(self) -> float: ...
    @property
    def shape_change(self) -> float: ...
    @property
    def jump(self) -> float: ...
    @property
    def inside_level(self) -> float: ...
    def as_dict(self) -> dict[str, float]: ...

class FrameStats:
    """Statistics and timings of one tracked frame (see Tracker.track)."""

    @property
    def held(self) -> bool: ...
    @property
    def cost(self) -> float: ...
    @property
    def area_similarity(self) -> float: ...
    @property
    def num_detected(self) -> int: ...
    @property
    def num_kept(self) -> int: ...
    @property
    def num_dropped(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    @property
    def num_candidates(self) -> int: ...
    @property
    def recovered(self) -> bool: ...
    @property
    def state(self) -> str: ...  # 'tracking', 'uncertain' or 'lost'
    @property
    def confidence(self) -> float: ...
    @property
    def evidence(self) -> BoundaryEvidence: ...
    @property
    def reacquired(self) -> bool: ...
    @property
    def line_ms(self) -> float: ...
    @property
    def grouping_ms(self) -> float: ...
    @property
    def total_ms(self) -> float: ...
    def as_dict(self) -> dict[str, Union[bool, int, float, str, dict[str, float]]]: ...

class SegmentGraph:
    """The weighted graph of detected and generated (gap-filling) segments."""

    @property
    def vertices(self) -> FloatArray: ...
    @property
    def edges(self) -> npt.NDArray[np.int32]: ...
    @property
    def edge_detected(self) -> npt.NDArray[np.bool_]: ...
    @property
    def edge_weights(self) -> FloatArray: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    def segments(self, detected_only: bool = False) -> FloatArray: ...

class CycleCandidate:
    """A closed cycle found by the BDSP search."""

    @property
    def vertices(self) -> list[int]: ...
    @property
    def gap_length(self) -> float: ...
    @property
    def area(self) -> float: ...
    @property
    def seed_edge(self) -> int: ...

class BoundaryChoice:
    """The candidate chosen by choose_boundary."""

    @property
    def index(self) -> int: ...
    @property
    def cost(self) -> float: ...
    @property
    def similarity(self) -> float: ...
    @property
    def num_admissible(self) -> int: ...

class TrackerOptions:
    """The tracker options a user tunes (the CLI's flags with underscores, ROS's parameters,
    a config file's keys). help(scbt.TrackerOptions) lists them with defaults and ranges.
    Raises ValueError for a bad value, TypeError for a wrong type or an unknown name."""

    def __init__(
        self,
        *,
        detector: str = ...,
        gradient_threshold: int = ...,
        anchor_threshold: int = ...,
        min_line_length: float = ...,
        filter_distance: float = ...,
        max_segments: int = ...,
        seed_stride: int = ...,
        min_area_similarity: float = ...,
        shape_weight: float = ...,
        object_memory: bool = ...,
        predict_motion: bool = ...,
        recover_by_motion: bool = ...,
        normalize_exposure: bool = ...,
        adapt_to_blur: bool = ...,
        smooth_noisy_frames: bool = ...,
        loss_handling: bool = ...,
    ) -> None: ...
    detector: str  # 'edlines', 'opencv-edlines', 'lsd' or 'fld'
    gradient_threshold: int
    anchor_threshold: int
    min_line_length: float
    filter_distance: float
    max_segments: int
    seed_stride: int
    min_area_similarity: float
    shape_weight: float
    object_memory: bool
    predict_motion: bool
    recover_by_motion: bool
    normalize_exposure: bool
    adapt_to_blur: bool
    smooth_noisy_frames: bool
    loss_handling: bool
    @staticmethod
    def from_file(path: str) -> TrackerOptions: ...
    def to_text(self, *, json: bool = False) -> str: ...
    def as_dict(self) -> dict[str, Union[str, int, float, bool]]: ...
    def keys(self) -> list[str]: ...
    def __getitem__(self, name: str) -> Union[str, int, float, bool]: ...

def option_table() -> list[dict[str, Any]]: ...

class Tracker:
    """The salient closed boundary tracker.

    Tracker(options=None, *, keep_debug=False, **options): a TrackerOptions and/or the same
    options as keyword arguments (which override it).
    """

    def __init__(
        self,
        options: Optional[TrackerOptions] = None,
        *,
        keep_debug: bool = False,
        detector: str = ...,
        gradient_threshold: int = ...,
        anchor_threshold: int = ...,
        min_line_length: float = ...,
        filter_distance: float = ...,
        max_segments: int = ...,
        seed_stride: int = ...,
        min_area_similarity: float = ...,
        shape_weight: float = ...,
        object_memory: bool = ...,
        predict_motion: bool = ...,
        recover_by_motion: bool = ...,
        normalize_exposure: bool = ...,
        adapt_to_blur: bool = ...,
        smooth_noisy_frames: bool = ...,
        loss_handling: bool = ...,
    ) -> None: ...
    def init(
        self, frame: Frame, box_or_polygon: Union[Tuple[float, float, float, float], PolygonLike]
    ) -> FloatArray: ...
    def init_from_box(
        self, frame: Frame, box: Tuple[float, float, float, float]
    ) -> FloatArray: ...
    def update(self, frame: Frame) -> Tuple[bool, FloatArray]: ...
    def track(self, frame: Frame) -> Tuple[FloatArray, FrameStats]: ...
    @property
    def boundary(self) -> Optional[FloatArray]: ...
    @property
    def initialized(self) -> bool: ...
    @property
    def options(self) -> TrackerOptions: ...
    @property
    def keep_debug(self) -> bool: ...
    def detected_segments(self) -> FloatArray: ...
    def graph(self) -> SegmentGraph: ...
    def annotate(self, frame: Frame, status: Optional[str] = None) -> npt.NDArray[np.uint8]: ...

def read_polygons(path: str) -> list[FloatArray]: ...
def write_polygons(path: str, polygons: Sequence[PolygonLike]) -> None: ...
def detect_line_segments(
    image: Frame,
    *,
    detector: str = ...,
    gradient_threshold: int = ...,
    anchor_threshold: int = ...,
    scan_interval: int = ...,
    sigma: float = ...,
    min_line_length: float = ...,
    line_fit_error: float = ...,
    crop_to_boundary: bool = ...,
    roi_padding: float = ...,
) -> FloatArray: ...
def filter_segments_near_boundary(
    segments: SegmentsLike, boundary: PolygonLike, max_mean_distance: float = 20.0
) -> FloatArray: ...
def build_segment_graph(segments: SegmentsLike) -> SegmentGraph: ...
def search_cycle_candidates(graph: SegmentGraph, seed_stride: int = 2) -> list[CycleCandidate]: ...
def candidate_polygon(graph: SegmentGraph, candidate: CycleCandidate) -> FloatArray: ...
def grouping_cost(gap_length: float, area: float) -> float: ...
def area_similarity(previous_area: float, candidate_area: float) -> float: ...
def choose_boundary(
    candidates: Sequence[CycleCandidate], previous_area: float, min_similarity: float = 0.9
) -> Optional[BoundaryChoice]: ...
def alignment_error(tracked: PolygonLike, truth: PolygonLike, canvas_size: Tuple[int, int]) -> float: ...
def area(polygon: PolygonLike) -> float: ...
def check_boundary_polygon(polygon: PolygonLike) -> None: ...
def shape_distance(a: PolygonLike, b: PolygonLike) -> float: ...
