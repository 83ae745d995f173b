#include "scbt/tracker/view_cut.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace scbt {
namespace {

constexpr int kThumb = 32;
constexpr int kInner = 20;
constexpr int kMaxShift = (kThumb - kInner) / 2;
constexpr int kMinSurroundingCells = 200;
// Surroundings flatter than this (standard deviation of their cells, grey levels) say nothing of a
// cut: a plain table or wall correlates with anything by its noise and shading alone.
constexpr double kMinSurroundingSpread = 8.0;

// The best zero-mean normalised correlation of `a`'s cells where `use` is set against `b` moved by
// up to kMaxShift cells, over the cells of each shift that stay inside `b` (at least `min_cells`).
// Written out: OpenCV's masked template matching compares only shifts of a template inside the
// image, which leaves out the border cells the surroundings are made of.
double masked_correlation(const cv::Mat& a, const cv::Mat& b, const cv::Mat& use, int min_cells) {
  double best = 0.0;
  for (int dy = -kMaxShift; dy <= kMaxShift; ++dy) {
    for (int dx = -kMaxShift; dx <= kMaxShift; ++dx) {
      double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
      int n = 0;
      for (int y = std::max(0, -dy); y < std::min(kThumb, kThumb - dy); ++y) {
        const uchar* row_a = a.ptr<uchar>(y);
        const uchar* row_use = use.ptr<uchar>(y);
        const uchar* row_b = b.ptr<uchar>(y + dy);
        for (int x = std::max(0, -dx); x < std::min(kThumb, kThumb - dx); ++x) {
          if (row_use[x] == 0) continue;
          const double va = row_a[x], vb = row_b[x + dx];
          sa += va;
          sb += vb;
          saa += va * va;
          sbb += vb * vb;
          sab += va * vb;
          ++n;
        }
      }
      if (n < min_cells) continue;
      const double covariance = sab - sa * sb / n;
      const double variances = (saa - sa * sa / n) * (sbb - sb * sb / n);
      if (variances > 0.0) best = std::max(best, covariance / std::sqrt(variances));
    }
  }
  return best;
}

}  // namespace

ViewComparison::ViewComparison(const cv::Mat& reference, const cv::Mat& current)
    : reference_size_(reference.size()) {
  cv::resize(reference, reference_cells_, cv::Size(kThumb, kThumb), 0.0, 0.0, cv::INTER_AREA);
  cv::resize(current, current_cells_, cv::Size(kThumb, kThumb), 0.0, 0.0, cv::INTER_AREA);
}

double ViewComparison::whole() const {
  cv::Mat use(kThumb, kThumb, CV_8U, cv::Scalar(0));
  use(cv::Rect(kMaxShift, kMaxShift, kInner, kInner)).setTo(255);
  return masked_correlation(reference_cells_, current_cells_, use, kInner * kInner);
}

double ViewComparison::surroundings(const Polygon& object) const {
  const double sx = static_cast<double>(kThumb) / reference_size_.width;
  const double sy = static_cast<double>(kThumb) / reference_size_.height;
  std::vector<cv::Point> cells;
  for (const Point& p : object) cells.emplace_back(cvRound(p.x * sx), cvRound(p.y * sy));
  cv::Mat use(kThumb, kThumb, CV_8U, cv::Scalar(255));
  if (!cells.empty()) cv::fillPoly(use, std::vector<std::vector<cv::Point>>{cells}, cv::Scalar(0));
  cv::erode(use, use, cv::Mat());  // the object's edge blurs into the cells around it
  if (cv::countNonZero(use) < kMinSurroundingCells) return 1.0;
  cv::Scalar mean, spread;
  cv::meanStdDev(reference_cells_, mean, spread, use);
  if (spread[0] < kMinSurroundingSpread) return 1.0;
  return masked_correlation(reference_cells_, current_cells_, use, kMinSurroundingCells);
}

double coarse_view_correlation(const cv::Mat& reference, const cv::Mat& current) {
  return ViewComparison(reference, current).whole();
}

double surroundings_correlation(const cv::Mat& reference, const cv::Mat& current,
                                const Polygon& object) {
  return ViewComparison(reference, current).surroundings(object);
}

}  // namespace scbt
