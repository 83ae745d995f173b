// Whether the view around a tracked object was cut (a jump in the video, the camera turned away):
// the window around the boundary against the same window of the last tracked frame, both averaged
// down to 32 x 32 cells.
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

// How alike two views of the same window are, blur and a moderate shift aside: the best zero-mean
// normalised correlation of the middle 20 x 20 cells of `reference` in `current`, over shifts of
// up to 6 cells. Near 1 for the same view; low for a cut, 0 for a flat window.
double coarse_view_correlation(const cv::Mat& reference, const cv::Mat& current);

// The same, over the surroundings of `object` (the boundary tracked in `reference`, in its
// pixels): the whole window less the object's cells, grown by one, over the same shifts (the
// cells of each shift that stay inside `current`, at least 200 of them). A look-alike left where
// the object was keeps the whole window alike after a cut; the surroundings do not. 1 (alike)
// when the object leaves fewer cells, or when the reference's surroundings are flat (a standard
// deviation under 8 grey levels: a plain table correlates with anything by its noise alone).
double surroundings_correlation(const cv::Mat& reference, const cv::Mat& current,
                                const Polygon& object);

// Both correlations of one pair of windows, which are averaged down once.
class ViewComparison {
 public:
  ViewComparison(const cv::Mat& reference, const cv::Mat& current);
  double whole() const;                              // coarse_view_correlation
  double surroundings(const Polygon& object) const;  // surroundings_correlation

 private:
  cv::Mat reference_cells_, current_cells_;
  cv::Size reference_size_;
};

}  // namespace scbt
