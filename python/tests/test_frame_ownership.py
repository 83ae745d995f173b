"""The caller's frames stay the caller's: no call writes into an array it was given, and none
keeps using one once it returns (the array may be freed straight after)."""

import itertools
import os
import subprocess
import sys
import textwrap

import cv2
import numpy as np
import pytest

import scbt
from conftest import pentagon, render


def frame(step, colour):
    """The pentagon moved by `step` px, grey or BGR, in a buffer of its own."""
    image = render(pentagon((150 + step, 120 + step / 2), 50), seed=step)
    return cv2.cvtColor(image, cv2.COLOR_GRAY2BGR) if colour == "bgr" else image


def call(tracker, name, image, step):
    if name == "init":
        tracker.init(image, pentagon((150 + step, 120 + step / 2), 50))
    elif name == "init_from_box":
        tracker.init_from_box(image, (85 + step, 55 + step / 2, 130, 130))
    else:
        tracker.track(image)


CALLS = ["init", "init_from_box", "track"]
ORDERS = [
    list(zip(names, colours))
    for names in itertools.product(CALLS[:2], CALLS, CALLS)  # an init first
    for colours in itertools.product(["grey", "bgr"], repeat=3)
]


@pytest.mark.parametrize("order", ORDERS, ids=lambda o: "-".join(f"{n}({c})" for n, c in o))
def test_no_frame_is_written_in_any_order(order):
    tracker = scbt.Tracker()
    given = []
    for k, (name, colour) in enumerate(order):
        image = frame(2 * k, colour)
        given.append((image, image.copy()))
        call(tracker, name, image, 2 * k)
        for i, (array, pristine) in enumerate(given):
            assert np.array_equal(array, pristine), f"frame {i + 1} written after call {k + 1}"


# In a child interpreter: a crash there (the tracker writing into a freed array) is a failure
# here, not the end of the test run. The frames are large, so that numpy's buffers are mapped
# pages returned to the system when freed: a write into one then faults at once.
FREED_FRAMES = textwrap.dedent(
    """
    import gc, sys
    import cv2, numpy as np
    import scbt

    poly = np.array([[400, 300], [1500, 350], [1600, 1500], [500, 1600]], float)

    def grey():
        image = np.full((2000, 2000), 60, np.uint8)
        cv2.fillPoly(image, [poly.astype(np.int32)], 200)
        return image

    def bgr():
        return cv2.cvtColor(grey(), cv2.COLOR_GRAY2BGR)

    box = (300, 200, 1400, 1500)
    for order in sys.argv[1:]:
        t = scbt.Tracker()
        for step in order.split(","):
            name, colour = step.split(":")
            image = grey() if colour == "grey" else bgr()
            if name == "init":
                t.init(image, poly)
            elif name == "box":
                t.init_from_box(image, box)
            else:
                t.track(image)
            del image
            gc.collect()
    print("ok")
    """
)


def test_frames_freed_after_each_call():
    orders = [
        "init:grey,init:bgr",
        "init:grey,track:bgr",
        "box:grey,init:bgr",
        "init:bgr,track:grey,track:bgr",
        "init:grey,track:grey,box:bgr",
    ]
    child = subprocess.run(
        [sys.executable, "-c", FREED_FRAMES, *orders],
        env=dict(os.environ),
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert child.returncode == 0 and child.stdout.strip() == "ok", (
        f"exit {child.returncode}: {child.stderr[-2000:]}"
    )
