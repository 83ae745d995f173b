#!/usr/bin/env python3
"""Renders a small test clip for the install checks (scripts/ci_install.sh): a textureless
hexagonal outline translating, rotating and growing over clutter strokes and noise, as numbered
frames (PNG, or the formats given, in turn), with its exact outline per frame in truth.txt and
the first one in init.txt.

    render_frames.py OUT_DIR [--frames N] [--formats png,jpg,...]
"""
import argparse
import pathlib

import cv2
import numpy as np


def outline(t):
    """The hexagon at time t in [0, 1]: centre, angle and radius move smoothly."""
    angles = np.linspace(0, 2 * np.pi, 6, endpoint=False) + 0.2 * t
    radius = 90 + 10 * t
    centre = np.array([280 + 60 * t, 230 + 15 * np.sin(np.pi * t)])
    return centre + radius * np.stack([np.cos(angles), np.sin(angles)], axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--formats", default="png",
                        help="file extensions to write the frames as, in turn (e.g. jpg,PNG,tif)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    formats = args.formats.split(",")
    rng = np.random.default_rng(7)
    clutter = [(rng.uniform(0, 640, 2), rng.uniform(0, 640, 2), int(rng.integers(60, 200)))
               for _ in range(25)]
    truth = []
    for i in range(args.frames):
        image = np.full((480, 640), 120, np.uint8)
        for (x1, y1), (x2, y2), grey in clutter:
            cv2.line(image, (int(x1), int(y1 * 0.75)), (int(x2), int(y2 * 0.75)), grey, 2)
        polygon = outline(i / max(args.frames - 1, 1))
        cv2.fillPoly(image, [np.round(polygon * 16).astype(np.int32)], 40, cv2.LINE_AA, shift=4)
        noise = rng.normal(0, 4, image.shape)
        image = np.clip(image + noise, 0, 255).astype(np.uint8)
        extension = formats[i % len(formats)]
        # A PGM holds grey only; every other format gets the BGR a camera gives.
        pixels = image if extension.lower() == "pgm" else cv2.cvtColor(image, cv2.COLOR_GRAY2BGR)
        if not cv2.imwrite(str(out / f"{i + 1:04d}.{extension}"), pixels):
            raise SystemExit(f"render_frames: cv2 cannot write .{extension}")
        truth.append(" ".join(["6"] + [f"{v:.2f}" for v in polygon.ravel()]))
    (out / "truth.txt").write_text("\n".join(truth) + "\n")
    (out / "init.txt").write_text(truth[0] + "\n")


if __name__ == "__main__":
    main()
