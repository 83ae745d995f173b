#include "scbt/tracker/reacquire_appearance.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace scbt {

RegionHistogram region_histogram(const cv::Mat& image, const Polygon& boundary) {
  RegionHistogram histogram;
  if (image.empty() || image.depth() != CV_8U || boundary.size() < 3) return histogram;
  std::vector<cv::Point> points;
  for (const Point& p : boundary) points.emplace_back(cvRound(p.x), cvRound(p.y));
  const cv::Rect box = cv::boundingRect(points) & cv::Rect(0, 0, image.cols, image.rows);
  if (box.width < 5 || box.height < 5) return histogram;
  cv::Mat mask = cv::Mat::zeros(box.size(), CV_8U);
  for (cv::Point& p : points) p -= box.tl();
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{points}, 255);
  cv::erode(mask, mask, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  const Point middle = centroid(boundary);
  std::vector<cv::Point> inner;
  for (const Point& p : boundary) {
    const Point q = middle + (p - middle) * kAppearanceBandInnerScale;
    inner.emplace_back(cvRound(q.x) - box.x, cvRound(q.y) - box.y);
  }
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{inner}, 0);
  const cv::Mat window = image(box);
  const int channels = image.channels();
  const bool colour = channels >= 3;
  histogram.bins.assign(colour ? 64 : 16, 0.0f);
  double count = 0.0;
  for (int y = 0; y < box.height; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    const uchar* px = window.ptr<uchar>(y);
    for (int x = 0; x < box.width; ++x, px += channels) {
      if (!m[x]) continue;
      const int bin = colour ? (px[0] >> 6) * 16 + (px[1] >> 6) * 4 + (px[2] >> 6) : px[0] >> 4;
      histogram.bins[bin] += 1.0f;
      count += 1.0;
    }
  }
  if (count == 0.0) {
    histogram.bins.clear();
    return histogram;
  }
  for (float& b : histogram.bins) b = static_cast<float>(b / count);
  return histogram;
}

double histogram_similarity(const RegionHistogram& a, const RegionHistogram& b) {
  if (a.bins.empty() || a.bins.size() != b.bins.size()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < a.bins.size(); ++i) sum += std::sqrt(double(a.bins[i]) * b.bins[i]);
  return sum;
}

}  // namespace scbt
