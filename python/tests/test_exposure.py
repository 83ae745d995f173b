"""normalize_exposure: a dim frame's grey levels are stretched before detection."""

import numpy as np
import pytest

import scbt
from conftest import pentagon, render


def dim(frame, brightness):
    return np.round(frame.astype(np.float64) * brightness).astype(np.uint8)


def test_normalize_exposure_is_on_by_default_and_can_be_switched_off():
    assert scbt.Tracker().options["normalize_exposure"] is True
    assert scbt.Tracker(normalize_exposure=False).options["normalize_exposure"] is False


def test_box_in_a_dim_frame_finds_the_outline_only_when_stretched():
    truth = pentagon((160, 120), 60)
    # At 6 % of the light the outline's step (130 grey levels lit) is under 8 levels: below
    # EDLines' published gradient threshold.
    frame = dim(render(truth, seed=5, clutter=0), 0.06)
    box = (80, 40, 160, 160)
    found = scbt.Tracker().init_from_box(frame, box)
    assert np.abs(found.mean(axis=0) - truth.mean(axis=0)).max() < 2.0
    with pytest.raises(RuntimeError):
        scbt.Tracker(normalize_exposure=False).init_from_box(frame, box)


def test_adapt_to_blur_is_on_by_default_and_can_be_switched_off():
    assert scbt.Tracker().options["adapt_to_blur"] is True
    assert scbt.Tracker(adapt_to_blur=False).options["adapt_to_blur"] is False
