#!/usr/bin/env python3
"""Tracks a boundary through a folder of frames with the installed scbt module and prints the
boundary of every frame as one line `n x1 y1 ... xn yn` (scbt's polygon format).

    python3 track_folder.py FRAMES_DIR INIT_POLYGON_FILE

Frames are the folder's images in any format `scbt track` reads (jpg, jpeg, png, bmp, tif, tiff,
ppm, pgm, webp, in any case), in name order -- all-digit names by their number, so that 9.jpg
comes before 10.jpg; the first line of INIT_POLYGON_FILE is the boundary in the first frame.
"""
import pathlib
import sys

import cv2
import numpy as np
import scbt

FRAME_EXTENSIONS = {".jpg", ".jpeg", ".png", ".bmp", ".tif", ".tiff", ".ppm", ".pgm", ".webp"}


def frame_paths(folder):
    """The folder's frames: all-digit names first and by their number, then by name."""
    paths = [p for p in pathlib.Path(folder).iterdir()
             if p.suffix.lower() in FRAME_EXTENSIONS and p.is_file()]

    def order(path):
        numbered = path.stem.isascii() and path.stem.isdigit()
        return (0, int(path.stem), path.name) if numbered else (1, 0, path.name)

    return sorted(paths, key=order)


def read_frame(path):
    frame = cv2.imread(str(path))  # 8-bit BGR, whatever the file holds
    if frame is None:
        sys.exit(f"cannot read {path}")
    return frame


def format_polygon(polygon):
    return " ".join([str(len(polygon))] + [f"{v:.2f}" for v in np.asarray(polygon).ravel()])


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} FRAMES_DIR INIT_POLYGON_FILE  (scbt {scbt.__version__})")
    paths = frame_paths(argv[1])
    if not paths:
        sys.exit(f"no image frames in {argv[1]}")
    tracker = scbt.Tracker()  # default options (scbt.TrackerOptions lists them)
    print(format_polygon(tracker.init(read_frame(paths[0]), scbt.read_polygons(argv[2])[0])))
    for number, path in enumerate(paths[1:], start=2):
        boundary, stats = tracker.track(read_frame(path))
        print(format_polygon(boundary))
        print(f"frame {number}: {stats.state}, confidence {stats.confidence:.3f}, "
              f"{stats.total_ms:.2f} ms", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv)
