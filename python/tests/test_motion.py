"""predict_motion: a boundary that moves fast is searched for where the image around it moved
(the behaviour itself is tested in C++, tracker_motion_test)."""

import scbt


def test_predict_motion_is_on_by_default_and_can_be_switched_off():
    assert scbt.Tracker().options["predict_motion"] is True
    assert scbt.Tracker(predict_motion=False).options["predict_motion"] is False
