// Every tracker `--tracker` offers (scbt and its peers) leaves the caller's frames alone: none is
// written into, and none is still held once a call returns, with grey and colour frames mixed.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "scbt/peers/polygon_tracker.h"

namespace scbt {
namespace {

Polygon square(int shift) {
  return {
      {100.0 + shift, 60.0}, {200.0 + shift, 60.0}, {200.0 + shift, 160.0}, {100.0 + shift, 160.0}};
}

cv::Mat render(const Polygon& polygon, int type) {
  cv::Mat image(240, 320, type, cv::Scalar::all(40));
  std::vector<cv::Point> pts;
  for (const Point& v : polygon) pts.emplace_back(cvRound(v.x), cvRound(v.y));
  cv::fillPoly(image, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar::all(210));
  return image;
}

TEST(PeersFrameOwnership, NoFrameIsWrittenOrKept) {
  for (const std::string& name : polygon_tracker_names()) {
    SCOPED_TRACE(name);
    const std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker(name);
    std::vector<cv::Mat> frames, pristine;
    const int types[] = {CV_8UC1, CV_8UC3, CV_8UC1, CV_8UC4, CV_8UC3, CV_8UC1};
    for (int k = 0; k < 6; ++k) {
      frames.push_back(render(square(2 * k), types[k]));
      pristine.push_back(frames.back().clone());
      if (k == 0 || k == 3)
        tracker->init(frames.back(), square(2 * k));
      else
        tracker->track(frames.back());
      for (int i = 0; i <= k; ++i) {
        EXPECT_EQ(cv::norm(frames[i], pristine[i], cv::NORM_INF), 0.0)
            << "frame " << i + 1 << " written, after call " << k + 1;
        EXPECT_EQ(frames[i].u->refcount, 1) << "frame " << i + 1 << " held, after call " << k + 1;
      }
    }
  }
}

}  // namespace
}  // namespace scbt
