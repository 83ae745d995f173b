"""Bad options, frames and polygons raise Python exceptions with clear messages."""

import numpy as np
import pytest

import scbt
from conftest import pentagon, render

TRUTH = pentagon((160, 120), 50)


@pytest.fixture
def frame():
    return render(TRUTH)


@pytest.mark.parametrize(
    "options, words",
    [
        ({"filter_distance": 0}, ["filter_distance", "0"]),
        ({"min_area_similarity": 1.5}, ["min_area_similarity", "1.5"]),
        ({"seed_stride": 0}, ["seed_stride", "0"]),
        ({"gradient_threshold": -3}, ["gradient_threshold", "-3"]),
        ({"detector": "canny"}, ["canny"]),
        ({"max_segments": 1}, ["max_segments", "1"]),
        ({"shape_weight": -2.0}, ["shape_weight", "-2"]),
    ],
)
def test_bad_option_values_raise_value_error(options, words):
    with pytest.raises(ValueError) as info:
        scbt.Tracker(**options)
    for word in words:
        assert word in str(info.value)


def test_unknown_option_raises_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'filter_dist'"):
        scbt.Tracker(filter_dist=10)
    with pytest.raises(TypeError, match="detect_line_segments.*'mode'"):
        scbt.detect_line_segments(np.zeros((10, 10), np.uint8), mode=1)


def test_option_of_wrong_type_raises_type_error():
    with pytest.raises(TypeError, match="filter_distance must be a number, got 'far'"):
        scbt.Tracker(filter_distance="far")


def test_options_round_trip():
    options = scbt.Tracker(
        detector="lsd", filter_distance=12.5, seed_stride=3, max_segments=40, predict_motion=False
    ).options
    assert options["detector"] == "lsd" and options["max_segments"] == 40
    assert options["predict_motion"] is False
    assert options["filter_distance"] == 12.5 and options["seed_stride"] == 3


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.uint16, np.int8, np.int64, bool])
def test_wrong_dtype_rejected(frame, dtype):
    tracker = scbt.Tracker()
    tracker.init(frame, TRUTH)
    with pytest.raises(TypeError) as info:
        tracker.track(frame.astype(dtype))
    message = str(info.value)
    assert "uint8" in message and np.dtype(dtype).name in message
    with pytest.raises(TypeError, match="uint8"):
        scbt.Tracker().init(frame.astype(dtype), TRUTH)


@pytest.mark.parametrize(
    "shape", [(240, 320, 2), (240, 320, 5), (240, 320, 3, 1), (240,), (0, 320), (240, 0, 3)]
)
def test_wrong_shape_rejected(shape):
    tracker = scbt.Tracker()
    with pytest.raises(ValueError) as info:
        tracker.init(np.zeros(shape, np.uint8), TRUTH)
    assert str(shape).replace(" ", "") in str(info.value).replace(" ", "")


def test_non_array_frame_rejected():
    with pytest.raises(TypeError, match="numpy.ndarray.*list"):
        scbt.Tracker().init([[0, 1], [2, 3]], TRUTH)


def test_polygon_errors(frame):
    tracker = scbt.Tracker()
    with pytest.raises(ValueError, match=r"shape \(N, 2\), got \(5, 3\)"):
        tracker.init(frame, np.zeros((5, 3)))
    with pytest.raises(ValueError, match="outside"):
        tracker.init(frame, TRUTH + [300, 0])
    with pytest.raises(ValueError):
        tracker.init(frame, [[10, 10], [20, 20], [30, 30]])  # no area
    with pytest.raises(TypeError, match=r"\(N, 2\)"):
        tracker.init(frame, "not a polygon")
    assert not tracker.initialized and tracker.boundary is None


def test_track_before_init_and_size_change(frame):
    tracker = scbt.Tracker()
    with pytest.raises(RuntimeError, match="before Tracker.init"):
        tracker.track(frame)
    tracker.init(frame, TRUTH)
    with pytest.raises(ValueError, match="320x240 to 160x120"):
        tracker.track(frame[:120, :160].copy())


def test_debug_needs_keep_debug(frame):
    tracker = scbt.Tracker()
    tracker.init(frame, TRUTH)
    tracker.track(frame)
    with pytest.raises(RuntimeError, match="keep_debug=True"):
        tracker.detected_segments()


def test_stage_argument_errors():
    with pytest.raises(ValueError, match=r"\(M, 4\), got \(3, 2\)"):
        scbt.build_segment_graph(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="seed_stride"):
        scbt.search_cycle_candidates(scbt.build_segment_graph(np.zeros((0, 4))), seed_stride=0)
    with pytest.raises(ValueError, match="canvas_size"):
        scbt.alignment_error(TRUTH, TRUTH, (0, 10))


def _segments(bad=None):
    segments = np.array([[10, 10, 60, 10], [60, 10, 60, 60], [60, 60, 10, 60], [10, 60, 10, 10]],
                        float)
    if bad is not None:
        segments[1, 2] = bad
    return segments


def _polygon(bad):
    polygon = TRUTH.copy()
    polygon[2, 0] = bad
    return polygon


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize(
    "call",
    [
        lambda bad: scbt.build_segment_graph(_segments(bad)),
        lambda bad: scbt.filter_segments_near_boundary(_segments(bad), TRUTH),
        lambda bad: scbt.filter_segments_near_boundary(_segments(), _polygon(bad)),
        lambda bad: scbt.filter_segments_near_boundary(_segments(), TRUTH, bad),
        lambda bad: scbt.alignment_error(_polygon(bad), TRUTH, (320, 240)),
        lambda bad: scbt.alignment_error(TRUTH, _polygon(bad), (320, 240)),
        lambda bad: scbt.area(_polygon(bad)),
        lambda bad: scbt.check_boundary_polygon(_polygon(bad)),
        lambda bad: scbt.grouping_cost(bad, 10.0),
        lambda bad: scbt.grouping_cost(1.0, bad),
        lambda bad: scbt.area_similarity(bad, 10.0),
        lambda bad: scbt.area_similarity(10.0, bad),
        lambda bad: scbt.choose_boundary([], bad),
        lambda bad: scbt.choose_boundary([], 100.0, bad),
        lambda bad: scbt.Tracker().init(render(TRUTH), _polygon(bad)),
        lambda bad: scbt.Tracker(filter_distance=bad),
        lambda bad: scbt.Tracker(shape_weight=bad),
    ],
)
def test_non_finite_input_raises_value_error(call, bad):
    # scbt.build_segment_graph crashed inside CGAL on these before.
    with pytest.raises(ValueError):
        call(bad)
