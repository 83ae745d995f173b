#!/usr/bin/env python3
"""Tracks a boundary through a folder of frames with the installed scbt module and prints the
boundary of every frame as one line `n x1 y1 ... xn yn` (scbt's polygon format).

    python3 track_folder.py FRAMES_DIR INIT_POLYGON_FILE

Frames are the folder's .png and .jpg images in name order (the public dataset's sequences
are folders of .jpg); the first line of INIT_POLYGON_FILE is the
boundary in the first frame.
"""
import pathlib
import sys

import cv2
import numpy as np
import scbt


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} FRAMES_DIR INIT_POLYGON_FILE  (scbt {scbt.__version__})")
    paths = sorted(p for p in pathlib.Path(argv[1]).iterdir()
                   if p.suffix.lower() in (".png", ".jpg", ".jpeg"))
    if not paths:
        sys.exit(f"no .png or .jpg frames in {argv[1]}")
    tracker = scbt.Tracker()  # default options (scbt.TrackerOptions lists them)
    print(format_polygon(tracker.init(cv2.imread(str(paths[0])), scbt.read_polygons(argv[2])[0])))
    for number, path in enumerate(paths[1:], start=2):
        boundary, stats = tracker.track(cv2.imread(str(path)))
        print(format_polygon(boundary))
        print(f"frame {number}: {stats.state}, confidence {stats.confidence:.3f}, "
              f"{stats.total_ms:.2f} ms", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv)
