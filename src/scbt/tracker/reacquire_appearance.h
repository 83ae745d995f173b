// What a lost object looks like inside its boundary, wherever it is, however large and however
// turned: a colour histogram of the band just inside its boundary (a container's wall, a face's
// border), not of its whole inside, since contents change while the object is away (a cup
// filled or emptied) and its middle is more often the same colour as the background. The search
// while lost asks for it when a cycle matches only once its view change is allowed (another
// distance, another angle: view_change.h), since a shape alone then admits much more of the clutter
// (every ellipse is a circle seen obliquely).
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Normalised to sum 1: 4 x 4 x 4 bins of B, G, R for a colour image, 16 grey bins for a grey one
// (coarse: a little change of light moves few pixels across a bin). Empty when nothing is inside.
struct RegionHistogram {
  std::vector<float> bins;
};

// Share of the boundary's size (from its area centroid) the band reaches in to: its outer 36 %
// of the area.
constexpr double kAppearanceBandInnerScale = 0.8;

// The pixels inside `boundary` (image coordinates) at least 2 px from it (the blurred edge
// belongs to both sides) and outside it shrunk by kAppearanceBandInnerScale about its centroid;
// `image` 8-bit with 1, 3 or 4 channels.
RegionHistogram region_histogram(const cv::Mat& image, const Polygon& boundary);

// The Bhattacharyya coefficient sum_i sqrt(a_i b_i): 1 for equal histograms, 0 for disjoint ones
// or when either is empty or they were taken from images of different channel counts.
double histogram_similarity(const RegionHistogram& a, const RegionHistogram& b);

}  // namespace scbt
