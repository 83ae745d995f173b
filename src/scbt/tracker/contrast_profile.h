// The boundary's appearance as a signed contrast profile: at points spaced evenly along it, the
// mean intensity just outside minus just inside. Comparing the profile a placement of the last
// boundary has in the new frame with the one it had when it was tracked tells whether the
// boundary's edges are there (the same sign pattern of contrast), independently of the line
// detector; the tracker uses it to accept a motion prediction only when the image confirms it.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct ContrastProfileOptions {
  int samples = 64;     // points along the boundary
  double across = 2.0;  // px from the boundary at which either side is read
  // Each side's intensity is the mean of a (2 smoothing + 1)^2 box: damps sensor noise.
  int smoothing = 1;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// The profile of `boundary` (image coordinates) in `image` (8-bit, 1, 3 or 4 channels: colour is
// read as grey, ITU-R BT.601 weights), one value per sample; samples whose boxes leave the
// image are 0 (they then count for nothing in profile_agreement). The sign convention follows
// the polygon's orientation, so profiles compare only between placements of one polygon.
void contrast_profile(const cv::Mat& image, const Polygon& boundary,
                      const ContrastProfileOptions& options, std::vector<float>* profile);

// Normalised correlation (cosine) of two profiles of one length, in [-1, 1]; 0 when either is
// flat or the lengths differ.
double profile_agreement(const std::vector<float>& a, const std::vector<float>& b);

// The contrast profile of the last tracked boundary, and which of two placements of it in a new
// frame agrees with it better.
class BoundaryAppearance {
 public:
  explicit BoundaryAppearance(const ContrastProfileOptions& options = {}) : options_(options) {}
  // Records `boundary` as seen in `image` (the frame it was tracked in).
  void remember(const cv::Mat& image, const Polygon& boundary);
  // Agreement of `placement` (a moved copy of the remembered boundary, same vertices) in `image`
  // with the remembered profile; 0 before anything was remembered.
  double agreement(const cv::Mat& image, const Polygon& placement);

 private:
  ContrastProfileOptions options_;
  std::vector<float> reference_, buffer_;
};

}  // namespace scbt
