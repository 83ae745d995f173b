"""Synthetic scenes for the scbt module tests, rendered with numpy and cv2 (no fixtures)."""

import cv2
import numpy as np
import pytest


def pentagon(center, radius):
    """The corners of a regular pentagon as a (5, 2) float array."""
    angles = np.deg2rad(90 + 72 * np.arange(5))
    return np.stack([center[0] + radius * np.cos(angles), center[1] + radius * np.sin(angles)], 1)


def render(outline, size=(320, 240), seed=0, clutter=12, bgr=False):
    """A textureless bright outline over a mid-grey background with short clutter strokes
    (away from the outline) and pixel noise."""
    rng = np.random.default_rng(seed)
    width, height = size
    image = np.full((height, width), 70, np.uint8)
    for _ in range(clutter):
        p = rng.uniform([0, 0], [width, height])
        d = rng.normal(size=2)
        q = p + 18 * d / np.linalg.norm(d)
        cv2.line(image, tuple(int(v) for v in p), tuple(int(v) for v in q), 120, 1, cv2.LINE_AA)
    cv2.fillPoly(image, [np.round(outline * 16).astype(np.int32)], 200, cv2.LINE_AA, shift=4)
    noise = rng.normal(0, 4, image.shape)
    image = np.clip(image + noise, 0, 255).astype(np.uint8)
    return cv2.cvtColor(image, cv2.COLOR_GRAY2BGR) if bgr else image


@pytest.fixture
def moving_pentagon():
    """20 frames of a pentagon moving 2.5 px right and 1.5 px down per frame, with its truth."""
    frames, truths = [], []
    for k in range(20):
        truth = pentagon((120 + 2.5 * k, 110 + 1.5 * k), 55)
        frames.append(render(truth, seed=k))
        truths.append(truth)
    return frames, truths
