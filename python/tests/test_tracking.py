"""Tracking a synthetic moving outline through the scbt module, and its stage functions."""

import threading
import time

import numpy as np
import pytest

import scbt
from conftest import pentagon, render

CANVAS = (320, 240)


def track_all(tracker, frames, truths):
    tracker.init(frames[0], truths[0])
    errors, stats = [], []
    for frame, truth in zip(frames[1:], truths[1:]):
        boundary, s = tracker.track(frame)
        assert isinstance(boundary, np.ndarray)
        assert boundary.dtype == np.float64 and boundary.ndim == 2 and boundary.shape[1] == 2
        assert boundary.shape[0] >= 3
        errors.append(scbt.alignment_error(boundary, truth, CANVAS))
        stats.append(s)
    return np.array(errors), stats


@pytest.mark.parametrize("colour", ["grey", "bgr", "bgra"])
def test_follows_moving_pentagon(moving_pentagon, colour):
    frames, truths = moving_pentagon
    if colour != "grey":
        frames = [np.repeat(f[:, :, None], 3 if colour == "bgr" else 4, axis=2) for f in frames]
    errors, stats = track_all(scbt.Tracker(), frames, truths)
    assert errors.max() < 3.0, errors
    assert not any(s.held for s in stats)
    # After 19 frames the boundary is 47.5 px away from where it started: it moved with the shape.
    assert scbt.alignment_error(truths[0], truths[-1], CANVAS) > 20


def test_stats_are_consistent(moving_pentagon):
    frames, truths = moving_pentagon
    tracker = scbt.Tracker()
    tracker.init(frames[0], truths[0])
    _, s = tracker.track(frames[1])
    d = s.as_dict()
    assert d["held"] is False
    assert s.num_detected >= s.num_kept >= 5
    assert s.num_vertices > 0 and s.num_edges >= s.num_kept and s.num_candidates > 0
    assert s.total_ms == pytest.approx(s.line_ms + s.grouping_ms)
    assert 0.9 < s.area_similarity <= 1.0 and s.cost >= 0
    assert set(d) >= {"held", "cost", "num_candidates", "line_ms", "grouping_ms", "total_ms"}
    # The property is the boundary the last track() returned.
    boundary, _ = tracker.track(frames[2])
    np.testing.assert_array_equal(tracker.boundary, boundary)


def test_blank_frame_holds_previous_boundary(moving_pentagon):
    frames, truths = moving_pentagon
    tracker = scbt.Tracker()
    tracker.init(frames[0], truths[0])
    before = tracker.boundary
    boundary, s = tracker.track(np.full_like(frames[0], 70))
    assert s.held
    np.testing.assert_array_equal(boundary, before)


def test_views_are_read_without_copy_and_match_copies(moving_pentagon):
    frames, truths = moving_pentagon
    # A region of a larger array (rows not adjacent in memory) and a Fortran-ordered copy
    # (read through a contiguous copy) must both track like the plain frame.
    big = [np.pad(f, ((7, 9), (11, 5)), constant_values=70) for f in frames[:4]]
    views = [b[7:-9, 11:-5] for b in big]
    assert not views[0].flags.c_contiguous
    fortran = [np.asfortranarray(f) for f in frames[:4]]
    results = []
    for variant in (frames[:4], views, fortran):
        tracker = scbt.Tracker()
        tracker.init(variant[0], truths[0])
        results.append([tracker.track(f)[0] for f in variant[1:]])
    for other in results[1:]:
        for a, b in zip(results[0], other):
            np.testing.assert_array_equal(a, b)


def test_gil_released_while_tracking():
    # Detection over the whole frame (the widest band) with OpenCV's EdgeDrawing, on a frame grown
    # until one call takes 20 ms on this machine: slow enough to see another thread run.
    for scale in (1, 2, 3):
        size = (1280 * scale, 960 * scale)
        truth = pentagon((size[0] / 2, size[1] / 2), 300 * scale)
        frame = render(truth, size=size, clutter=3000 * scale * scale)
        tracker = scbt.Tracker(filter_distance=1000, max_segments=100, detector="opencv-edlines")
        tracker.init(frame, truth)
        start = time.perf_counter()
        tracker.track(frame)
        one_call = time.perf_counter() - start
        if one_call > 0.02:
            break
    assert one_call > 0.02, "the frame is too easy to measure GIL release"

    done = threading.Event()

    def work():
        for _ in range(10):
            tracker.track(frame)
        done.set()

    thread = threading.Thread(target=work)
    stalled, last = 0.0, time.perf_counter()
    thread.start()
    begin = last
    while not done.is_set():
        now = time.perf_counter()
        if now - last > 0.5 * one_call:
            stalled += now - last
        last = now
    thread.join()
    elapsed = time.perf_counter() - begin
    # Holding the GIL would stall this loop for whole track() calls, i.e. most of the time; with
    # the GIL released only the OS scheduler (a loaded machine) can stall it.
    assert stalled < 0.5 * elapsed, (stalled, elapsed, one_call)


def test_stage_functions_recover_a_rectangle():
    truth = np.array([[80, 60], [240, 60], [240, 180], [80, 180]], float)
    image = render(truth, clutter=20, seed=3)
    segments = scbt.detect_line_segments(image)
    assert segments.ndim == 2 and segments.shape[1] == 4 and len(segments) >= 4
    previous = truth + [4, -3]
    kept = scbt.filter_segments_near_boundary(segments, previous, 20.0)
    assert 4 <= len(kept) <= len(segments)
    graph = scbt.build_segment_graph(kept)
    assert graph.num_vertices == len(graph.vertices)
    assert graph.edges.shape == (graph.num_edges, 2)
    assert graph.edge_detected.sum() == len(graph.segments(detected_only=True))
    np.testing.assert_array_equal(graph.edge_weights[graph.edge_detected], 0)
    candidates = scbt.search_cycle_candidates(graph)
    assert candidates
    choice = scbt.choose_boundary(candidates, scbt.area(previous), 0.9)
    assert choice is not None and choice.num_admissible >= 1
    chosen = candidates[choice.index]
    assert choice.cost == pytest.approx(scbt.grouping_cost(chosen.gap_length, chosen.area))
    polygon = scbt.candidate_polygon(graph, chosen)
    assert scbt.alignment_error(polygon, truth, CANVAS) < 2.0


def test_metric_functions():
    square = np.array([[50, 50], [150, 50], [150, 150], [50, 150]], float)
    assert scbt.alignment_error(square, square, CANVAS) == 0.0
    assert scbt.alignment_error(square + [6, 0], square, CANVAS) == pytest.approx(6 * 0.5, abs=1.5)
    assert scbt.alignment_error(square[:2], square, CANVAS) == float("inf")
    assert scbt.area(square) == pytest.approx(10000)
    assert scbt.area_similarity(100, 50) == pytest.approx(0.5)
    assert scbt.grouping_cost(10, 0) == float("inf")


def test_debug_segments_and_annotation(moving_pentagon):
    frames, truths = moving_pentagon
    tracker = scbt.Tracker(keep_debug=True)
    tracker.init(frames[0], truths[0])
    _, s = tracker.track(frames[1])
    assert len(tracker.detected_segments()) == s.num_detected
    assert tracker.graph().num_edges == s.num_edges
    drawn = tracker.annotate(frames[1], "frame 2")
    assert drawn.shape == frames[1].shape + (3,) and drawn.dtype == np.uint8
    assert (drawn != frames[1][:, :, None]).any()


def test_max_segments_caps_the_kept_segments(moving_pentagon):
    frames, truths = moving_pentagon
    free, capped = scbt.Tracker(), scbt.Tracker(max_segments=3)
    for tracker in (free, capped):
        tracker.init(frames[0], truths[0])
    _, s_free = free.track(frames[1])
    _, s_capped = capped.track(frames[1])
    assert s_free.num_dropped == 0 and s_free.num_kept > 3
    assert s_capped.num_kept == 3 and s_capped.num_dropped == s_free.num_kept - 3
