// OpenCV 4.6's EdgeDrawing::detectLines overflows its scratch arrays on an edge segment longer
// than (cols + rows) * 8 pixels (opencv_contrib #3429, #4205). A serpentine stroke makes one:
// the EDLines detector must not pass it to detectLines, and must still return the stroke's lines.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>
#include <vector>

#include "scbt/lines/line_detector.h"

namespace scbt {
namespace {

// Horizontal runs `pitch` pixels apart, joined at alternating ends, in one polyline.
cv::Mat serpentine(int size, int pitch) {
  cv::Mat image(size, size, CV_8UC1, cv::Scalar(0));
  std::vector<cv::Point> points;
  for (int y = 10, k = 0; y < size - 10; y += pitch, ++k) {
    points.emplace_back(k % 2 ? size - 10 : 10, y);
    points.emplace_back(k % 2 ? 10 : size - 10, y);
  }
  cv::polylines(image, points, false, cv::Scalar(255), 2);
  return image;
}

size_t longest_edge_segment(const cv::Mat& gray) {
  cv::Ptr<cv::ximgproc::EdgeDrawing> ed = cv::ximgproc::createEdgeDrawing();
  cv::ximgproc::EdgeDrawing::Params params;
  params.EdgeDetectionOperator = cv::ximgproc::EdgeDrawing::SOBEL;
  params.GradientThresholdValue = 36;
  params.AnchorThresholdValue = 8;
  ed->setParams(params);
  ed->detectEdges(gray);
  size_t longest = 0;
  for (const std::vector<cv::Point>& s : ed->getSegments()) longest = std::max(longest, s.size());
  return longest;
}

TEST(EdLinesOverflowGuard, SerpentineStrokesAreDetectedWithoutOverflow) {
  for (int size : {120, 160, 240, 400}) {
    for (int pitch : {6, 8}) {
      SCOPED_TRACE(testing::Message() << size << " px, pitch " << pitch);
      const cv::Mat image = serpentine(size, pitch);
      // The input really is one that would overflow detectLines' (cols + rows) * 8 arrays.
      ASSERT_GT(longest_edge_segment(image), static_cast<size_t>(2 * size * 8));
      // OpenCV's (guarded) and ours (flat buffers, no such limit).
      for (LineDetectorKind kind : {LineDetectorKind::kOpenCvEdLines, LineDetectorKind::kEdLines}) {
        SCOPED_TRACE(to_string(kind));
        LineDetectorOptions options;
        options.kind = kind;
        std::unique_ptr<LineDetector> detector = make_line_detector(options);
        const std::vector<Segment> segments = detector->detect(image);
        // Each horizontal run has two long sides; most of them must be found.
        const int runs = (size - 20 + pitch - 1) / pitch;
        int long_horizontal = 0;
        for (const Segment& s : segments) {
          if (s.length() > 0.6 * (size - 20) && std::abs(s.a.y - s.b.y) < 3) ++long_horizontal;
        }
        EXPECT_GE(long_horizontal, runs);
        // The same through a crop (the tracker detects in a window around the boundary).
        const cv::Rect window(size / 4, size / 4, size / 2, size / 2);
        const std::vector<Segment> in_window =
            detector->detect_in(image(window).clone(), window.tl(), image.size());
        EXPECT_FALSE(in_window.empty());
      }
    }
  }
}

}  // namespace
}  // namespace scbt
