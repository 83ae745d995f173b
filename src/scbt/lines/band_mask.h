// The band around a boundary that the tracker's line detection looks at: the pixels whose
// centres lie within a radius of the closed polyline, rasterised row by row as the union of one
// capsule (a segment grown by the radius) per edge. Written out rather than drawn with OpenCV's
// thick polylines, which fill a disc at both ends of every edge on top of its rectangle and
// cost as much per frame as the edge detector's gradients (callgrind, MarkCup: 384 k instructions
// per frame); this computes each row's interval of each capsule in closed form.
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"
#include "scbt/lines/row_spans.h"

namespace scbt {

// Fills `mask` (CV_8UC1 of `size`, reallocated only when its size or type differs) with 255 on
// the pixels whose centres lie within `radius` of the closed polyline `boundary` (a single point:
// a disc), given in the coordinates of a larger image where the mask's pixel (0, 0) is `offset`,
// and 0 elsewhere. Coordinates are clamped, so any input is safe; nothing is set for an empty
// boundary or a radius that is negative or not a number.
void draw_band_mask(const Polygon& boundary, cv::Point offset, double radius, cv::Size size,
                    cv::Mat* mask);

// The same pixels as spans per row (`band` reset to `size`): what the tracker's detector takes.
void band_spans(const Polygon& boundary, cv::Point offset, double radius, cv::Size size,
                RowSpans* band);

}  // namespace scbt
