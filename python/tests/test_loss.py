"""State, confidence and evidence on the Python result; re-acquisition after blank frames;
initialisation from a box; the shape distance."""

import numpy as np
import pytest

import scbt
from conftest import pentagon, render

CANVAS = (320, 240)


def test_confident_tracking_reports_state_and_evidence(moving_pentagon):
    frames, truths = moving_pentagon
    tracker = scbt.Tracker()
    tracker.init(frames[0], truths[0])
    for frame in frames[1:]:
        _, s = tracker.track(frame)
        assert s.state == "tracking"
        assert 0.5 <= s.confidence <= 1.0
        assert 0.0 <= s.evidence.gap_share < 0.45
        assert s.evidence.shape_change < 0.05
        assert s.evidence.inside_level > 150  # the pentagon is filled with 200 on 70
        assert not s.reacquired
    d = s.as_dict()
    assert d["state"] == "tracking" and d["confidence"] == s.confidence
    assert d["evidence"] == s.evidence.as_dict()
    assert set(d["evidence"]) == {"gap_share", "edge_support", "shape_change", "jump", "inside_level"}
    assert "state='tracking'" in repr(s)


def test_blank_frames_are_lost_then_reacquired_elsewhere():
    before = pentagon((110, 110), 50)
    after = pentagon((200, 130), 50)  # back 90 px away from where it was lost
    tracker = scbt.Tracker()
    tracker.init(render(before, seed=1), before)
    blank = np.full((CANVAS[1], CANVAS[0]), 70, np.uint8)
    states = []
    for _ in range(6):
        boundary, s = tracker.track(blank)
        states.append(s.state)
        assert s.state != "tracking" and s.confidence < 0.5
    assert states[-1] == "lost" and "lost" in states[:4]
    # While lost the output is the last confident boundary, repeated.
    assert scbt.alignment_error(boundary, before, CANVAS) < 2.0
    found_at = None
    for k in range(6):
        boundary, s = tracker.track(render(after, seed=10 + k))
        if s.state == "tracking":
            found_at = k
            break
    assert found_at is not None and found_at <= 5, states
    assert s.reacquired
    assert scbt.alignment_error(boundary, after, CANVAS) < 2.0


def test_loss_handling_off_never_reports_lost(moving_pentagon):
    frames, truths = moving_pentagon
    tracker = scbt.Tracker(loss_handling=False)
    assert tracker.options["loss_handling"] is False
    tracker.init(frames[0], truths[0])
    blank = np.full_like(frames[0], 70)
    for _ in range(5):
        _, s = tracker.track(blank)
        assert s.state == "uncertain" and s.held and s.confidence == 0.0


def test_init_from_box_finds_the_outline():
    truth = pentagon((150, 120), 50)
    frame = render(truth, seed=3)
    x0, y0 = truth.min(axis=0)
    x1, y1 = truth.max(axis=0)
    margin = 0.15 * max(x1 - x0, y1 - y0)
    tracker = scbt.Tracker()
    boundary = tracker.init_from_box(frame, (x0 - margin, y0 - margin, x1 - x0 + 2 * margin,
                                             y1 - y0 + 2 * margin))
    assert tracker.initialized
    assert scbt.alignment_error(boundary, truth, CANVAS) < 2.0
    np.testing.assert_array_equal(tracker.boundary, boundary)
    moved = pentagon((153, 122), 50)
    tracked, s = tracker.track(render(moved, seed=4))
    assert s.state == "tracking"
    assert scbt.alignment_error(tracked, moved, CANVAS) < 2.0


def test_init_from_box_errors():
    frame = render(pentagon((150, 120), 50), seed=3)
    tracker = scbt.Tracker()
    with pytest.raises(ValueError, match="4 values"):
        tracker.init_from_box(frame, (10, 10, 50))
    with pytest.raises(TypeError, match="box"):
        tracker.init_from_box(frame, "box")
    with pytest.raises(ValueError, match="not finite"):
        tracker.init_from_box(frame, (10, 10, float("nan"), 50))
    with pytest.raises(ValueError):
        tracker.init_from_box(frame, (300, 200, 100, 100))  # leaves the frame
    empty = np.full_like(frame, 70)
    with pytest.raises(RuntimeError):
        tracker.init_from_box(empty, (20, 20, 100, 100))
    assert not tracker.initialized


@pytest.mark.parametrize(
    "box, named",
    [
        ((4294967496, 60, 240, 130), "box x=4294967496 is out of range"),  # 200 + 2**32
        ((0, 0, 99999999999, 50), "box w=99999999999 is out of range"),
        ((0, 0, 1e30, 50), "box w=1e+30 is out of range"),
        ((10, -(2**31) - 1, 50, 50), "box y=-2147483649 is out of range"),
        ((10, 10, 50, 10**400), "box h=1000000000"),
        ((10, 10, float("inf"), 50), "box w=inf is not finite"),
    ],
)
def test_init_from_box_names_a_value_out_of_range_as_given(box, named):
    frame = render(pentagon((150, 120), 50), seed=3)
    tracker = scbt.Tracker()
    with pytest.raises(ValueError) as info:
        tracker.init_from_box(frame, box)
    assert named in str(info.value)
    assert not tracker.initialized


def test_init_from_box_needs_numbers():
    frame = render(pentagon((150, 120), 50), seed=3)
    with pytest.raises(TypeError, match="box x=ten"):
        scbt.Tracker().init_from_box(frame, ("ten", 10, 50, 50))


def test_shape_distance_is_invariant_to_pose():
    a = pentagon((100, 100), 40)
    angle = np.deg2rad(25)
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    b = 1.4 * (a - a.mean(0)) @ rotation.T + [300, 50]
    assert scbt.shape_distance(a, b[::-1]) < 0.02
    square = np.array([[0, 0], [60, 0], [60, 60], [0, 60]], float)
    thin = np.array([[0, 0], [120, 0], [120, 20], [0, 20]], float)
    assert scbt.shape_distance(square, thin) > 0.1
    assert scbt.shape_distance(a, np.zeros((3, 2))) == float("inf")
