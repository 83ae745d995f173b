#include "scbt/lines/line_detector.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>
#include <stdexcept>

namespace scbt {
namespace {

std::vector<Segment> to_segments(const std::vector<cv::Vec4f>& lines) {
  std::vector<Segment> segments;
  segments.reserve(lines.size());
  for (const cv::Vec4f& l : lines) segments.push_back({{l[0], l[1]}, {l[2], l[3]}});
  return segments;
}

class EdLinesDetector : public LineDetector {
 public:
  explicit EdLinesDetector(const LineDetectorOptions& options)
      : detector_(cv::ximgproc::createEdgeDrawing()) {
    cv::ximgproc::EdgeDrawing::Params params;
    params.EdgeDetectionOperator = cv::ximgproc::EdgeDrawing::SOBEL;
    params.GradientThresholdValue = options.gradient_threshold;
    params.AnchorThresholdValue = options.anchor_threshold;
    params.ScanInterval = options.scan_interval;
    params.Sigma = static_cast<float>(options.sigma);
    params.MinLineLength = static_cast<int>(options.min_line_length);
    params.LineFitErrorThreshold = options.line_fit_error;
    params.PFmode = false;
    params.SumFlag = true;
    params.NFAValidation = true;
    detector_->setParams(params);
  }

  std::vector<Segment> detect(const cv::Mat& gray) override {
    detector_->detectEdges(gray);
    detector_->detectLines(lines_);
    return to_segments(lines_);
  }

 private:
  cv::Ptr<cv::ximgproc::EdgeDrawing> detector_;
  std::vector<cv::Vec4f> lines_;
};

class LsdDetector : public LineDetector {
 public:
  explicit LsdDetector(const LineDetectorOptions& options)
      : detector_(cv::createLineSegmentDetector(cv::LSD_REFINE_STD)),
        min_length_(options.min_line_length) {}

  std::vector<Segment> detect(const cv::Mat& gray) override {
    detector_->detect(gray, lines_);
    std::vector<Segment> segments = to_segments(lines_);
    if (min_length_ > 0) {
      segments.erase(std::remove_if(segments.begin(), segments.end(),
                                    [&](const Segment& s) { return s.length() < min_length_; }),
                     segments.end());
    }
    return segments;
  }

 private:
  cv::Ptr<cv::LineSegmentDetector> detector_;
  double min_length_;
  std::vector<cv::Vec4f> lines_;
};

class FastLineDetectorAdapter : public LineDetector {
 public:
  explicit FastLineDetectorAdapter(const LineDetectorOptions& options)
      : detector_(cv::ximgproc::createFastLineDetector(
            options.min_line_length > 0 ? static_cast<int>(options.min_line_length) : 10,
            static_cast<float>(std::sqrt(options.line_fit_error) * 1.414), 50.0, 50.0, 3, true)) {}

  std::vector<Segment> detect(const cv::Mat& gray) override {
    detector_->detect(gray, lines_);
    return to_segments(lines_);
  }

 private:
  cv::Ptr<cv::ximgproc::FastLineDetector> detector_;
  std::vector<cv::Vec4f> lines_;
};

}  // namespace

LineDetectorKind parse_line_detector_kind(const std::string& name) {
  if (name == "edlines") return LineDetectorKind::kEdLines;
  if (name == "lsd") return LineDetectorKind::kLsd;
  if (name == "fld") return LineDetectorKind::kFastLineDetector;
  throw std::invalid_argument("unknown line detector '" + name + "' (use edlines, lsd or fld)");
}

std::string to_string(LineDetectorKind kind) {
  switch (kind) {
    case LineDetectorKind::kEdLines:
      return "edlines";
    case LineDetectorKind::kLsd:
      return "lsd";
    case LineDetectorKind::kFastLineDetector:
      return "fld";
  }
  return "unknown";
}

void LineDetectorOptions::check() const {
  if (gradient_threshold < 1 || gradient_threshold > 255) {
    throw std::invalid_argument("gradient_threshold must be in 1..255, got " +
                                std::to_string(gradient_threshold));
  }
  if (anchor_threshold < 0 || anchor_threshold > 255) {
    throw std::invalid_argument("anchor_threshold must be in 0..255, got " +
                                std::to_string(anchor_threshold));
  }
  if (scan_interval < 1) {
    throw std::invalid_argument("scan_interval must be >= 1, got " + std::to_string(scan_interval));
  }
  if (!(sigma > 0.0 && sigma <= 10.0)) {
    throw std::invalid_argument("sigma must be in (0, 10], got " + std::to_string(sigma));
  }
  if (!(line_fit_error > 0.0 && line_fit_error <= 100.0)) {
    throw std::invalid_argument("line_fit_error must be in (0, 100], got " +
                                std::to_string(line_fit_error));
  }
  if (!(min_line_length <= 10000.0)) {
    throw std::invalid_argument("min_line_length must be <= 10000, got " +
                                std::to_string(min_line_length));
  }
}

std::unique_ptr<LineDetector> make_line_detector(const LineDetectorOptions& options) {
  options.check();
  switch (options.kind) {
    case LineDetectorKind::kEdLines:
      return std::make_unique<EdLinesDetector>(options);
    case LineDetectorKind::kLsd:
      return std::make_unique<LsdDetector>(options);
    case LineDetectorKind::kFastLineDetector:
      return std::make_unique<FastLineDetectorAdapter>(options);
  }
  throw std::invalid_argument("unknown line detector kind");
}

std::vector<Segment> detect_line_segments(const cv::Mat& image,
                                          const LineDetectorOptions& options) {
  cv::Mat gray;
  if (image.channels() == 1) {
    gray = image;
  } else {
    cv::cvtColor(image, gray, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  }
  return make_line_detector(options)->detect(gray);
}

}  // namespace scbt
