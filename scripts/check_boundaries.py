#!/usr/bin/env python3
"""Checks tracked boundaries against the truth, one polygon per line in both files: the same
number of lines, and every boundary's centroid and area within a tolerance of the true one's.

    check_boundaries.py TRACKED TRUTH [--max-centroid-px 3] [--max-area-change 0.05]
"""
import argparse
import sys

import numpy as np


def polygons(path):
    result = []
    for line in open(path):
        values = line.split()
        n = int(values[0])
        result.append(np.array(values[1 : 1 + 2 * n], dtype=float).reshape(n, 2))
    return result


def centroid_and_area(p):
    x, y = p[:, 0], p[:, 1]
    cross = x * np.roll(y, -1) - np.roll(x, -1) * y
    area = cross.sum() / 2
    cx = ((x + np.roll(x, -1)) * cross).sum() / (6 * area)
    cy = ((y + np.roll(y, -1)) * cross).sum() / (6 * area)
    return np.array([cx, cy]), abs(area)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("tracked")
    parser.add_argument("truth")
    parser.add_argument("--max-centroid-px", type=float, default=3.0)
    parser.add_argument("--max-area-change", type=float, default=0.05)
    args = parser.parse_args()
    tracked, truth = polygons(args.tracked), polygons(args.truth)
    if len(tracked) != len(truth):
        sys.exit(f"{args.tracked}: {len(tracked)} boundaries for {len(truth)} frames")
    worst_shift, worst_area = 0.0, 0.0
    for frame, (a, b) in enumerate(zip(tracked, truth), start=1):
        (ca, aa), (cb, ab) = centroid_and_area(a), centroid_and_area(b)
        shift, area_change = np.linalg.norm(ca - cb), abs(aa / ab - 1)
        worst_shift, worst_area = max(worst_shift, shift), max(worst_area, area_change)
        if shift > args.max_centroid_px or area_change > args.max_area_change:
            sys.exit(f"{args.tracked}: frame {frame}: centroid {shift:.2f} px off, area {area_change:.1%} off")
    print(f"{args.tracked}: {len(tracked)} boundaries; worst centroid shift {worst_shift:.2f} px, "
          f"worst area change {worst_area:.1%}")


if __name__ == "__main__":
    main()
