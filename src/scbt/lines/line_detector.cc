#include "scbt/lines/line_detector.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>
#include <stdexcept>

#include "scbt/lines/band_mask.h"
#include "scbt/lines/edlines.h"

namespace scbt {
namespace {

std::vector<Segment> to_segments(const std::vector<cv::Vec4f>& lines) {
  std::vector<Segment> segments;
  segments.reserve(lines.size());
  for (const cv::Vec4f& l : lines) segments.push_back({{l[0], l[1]}, {l[2], l[3]}});
  return segments;
}

// Our EDLines; detect_near restricts the edges to the band around the boundary.
class OwnEdLinesDetector : public LineDetector {
 public:
  explicit OwnEdLinesDetector(const LineDetectorOptions& options) : edlines_(to_params(options)) {}

  std::vector<Segment> detect(const cv::Mat& gray) override {
    std::vector<Segment> segments;
    edlines_.detect(gray, cv::Point(0, 0), gray.size(), cv::Mat(), &segments);
    return segments;
  }

  std::vector<Segment> detect_in(const cv::Mat& crop, cv::Point offset,
                                 cv::Size full_size) override {
    std::vector<Segment> segments;
    edlines_.detect(crop, offset, full_size, cv::Mat(), &segments);
    return segments;
  }

  std::vector<Segment> detect_near(const cv::Mat& crop, cv::Point offset, cv::Size full_size,
                                   const Polygon& boundary, double radius) override {
    if (boundary.empty() || !(radius > 0.0) || !std::isfinite(radius)) {
      return detect_in(crop, offset, full_size);
    }
    band_spans(boundary, offset, radius, crop.size(), &band_);
    std::vector<Segment> segments;
    edlines_.detect(crop, offset, full_size, &band_, &segments);
    return segments;
  }

  bool adapts_thresholds() const override { return true; }
  void set_edge_thresholds(int gradient, int anchor) override {
    edlines_.set_thresholds(gradient, anchor);
  }

 private:
  static EdLinesParams to_params(const LineDetectorOptions& options) {
    EdLinesParams params;
    params.gradient_threshold = options.gradient_threshold;
    params.anchor_threshold = options.anchor_threshold;
    params.scan_interval = options.scan_interval;
    params.sigma = options.sigma;
    params.min_line_length =
        options.min_line_length > 0 ? static_cast<int>(std::ceil(options.min_line_length)) : -1;
    params.line_fit_error = options.line_fit_error;
    return params;
  }

  EdLines edlines_;
  RowSpans band_;
};

// OpenCV ximgproc's EdgeDrawing (EDLines), with a guard against its heap overflow.
class OpenCvEdLinesDetector : public LineDetector {
 public:
  explicit OpenCvEdLinesDetector(const LineDetectorOptions& options)
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
    params_ = params;
    detector_->setParams(params_);
  }

  std::vector<Segment> detect(const cv::Mat& gray) override {
    set_min_line_length(params_.MinLineLength <= 0 ? -1 : params_.MinLineLength);
    run(gray);
    return to_segments(lines_);
  }

  std::vector<Segment> detect_in(const cv::Mat& crop, cv::Point offset,
                                 cv::Size full_size) override {
    set_min_line_length(params_.MinLineLength <= 0 ? edlines_auto_min_line_length(full_size)
                                                   : params_.MinLineLength);
    run(crop);
    std::vector<Segment> segments;
    segments.reserve(lines_.size());
    const Point shift(offset.x, offset.y);
    for (const cv::Vec4f& l : lines_) {
      segments.push_back({Point(l[0], l[1]) + shift, Point(l[2], l[3]) + shift});
    }
    return segments;
  }

 private:
  void set_min_line_length(int length) {
    if (length == applied_min_length_) return;
    cv::ximgproc::EdgeDrawing::Params params = params_;
    params.MinLineLength = length;
    detector_->setParams(params);
    applied_min_length_ = length;
  }

  void run(const cv::Mat& gray) {
    // EdgeDrawing walks the pixels as one contiguous block.
    const cv::Mat* input = &gray;
    if (!gray.isContinuous()) {
      gray.copyTo(contiguous_);
      input = &contiguous_;
    }
    detector_->detectEdges(*input);
    // OpenCV 4.6's detectLines copies every edge segment into scratch arrays of (cols + rows) * 8
    // doubles without a bound check (opencv_contrib #3429, #4205): a longer, winding segment
    // overflows the heap (a serpentine stroke crashes it). Such an image gets LSD's lines.
    const size_t capacity = static_cast<size_t>(input->cols + input->rows) * 8;
    for (const std::vector<cv::Point>& segment : detector_->getSegments()) {
      if (segment.size() >= capacity) {
        if (!fallback_) fallback_ = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
        fallback_->detect(*input, lines_);
        const float min_length = static_cast<float>(std::max(applied_min_length_, 1));
        lines_.erase(std::remove_if(lines_.begin(), lines_.end(),
                                    [min_length](const cv::Vec4f& l) {
                                      return std::hypot(l[2] - l[0], l[3] - l[1]) < min_length;
                                    }),
                     lines_.end());
        return;
      }
    }
    detector_->detectLines(lines_);
  }

  cv::Ptr<cv::ximgproc::EdgeDrawing> detector_;
  cv::ximgproc::EdgeDrawing::Params params_;
  int applied_min_length_ = 0;  // never a value set_min_line_length is called with
  cv::Mat contiguous_;
  std::vector<cv::Vec4f> lines_;
  cv::Ptr<cv::LineSegmentDetector> fallback_;  // for images detectLines cannot take
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

std::vector<Segment> LineDetector::detect_near(const cv::Mat& crop, cv::Point offset,
                                               cv::Size full_size, const Polygon& /*boundary*/,
                                               double /*radius*/) {
  return detect_in(crop, offset, full_size);
}

std::vector<Segment> LineDetector::detect_in(const cv::Mat& crop, cv::Point offset,
                                             cv::Size /*full_size*/) {
  std::vector<Segment> segments = detect(crop.isContinuous() ? crop : crop.clone());
  const Point shift(offset.x, offset.y);
  for (Segment& s : segments) {
    s.a += shift;
    s.b += shift;
  }
  return segments;
}

cv::Rect detection_roi(const Polygon& boundary, double margin, cv::Size frame_size) {
  const cv::Rect frame(cv::Point(0, 0), frame_size);
  if (boundary.empty()) return frame;
  double x0 = boundary[0].x, x1 = x0, y0 = boundary[0].y, y1 = y0;
  for (const Point& p : boundary) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  // Clamp in double first: a far-away polygon must not overflow int.
  auto clamp_x = [&](double x) {
    return static_cast<int>(std::clamp(x, 0.0, 1.0 * frame_size.width));
  };
  auto clamp_y = [&](double y) {
    return static_cast<int>(std::clamp(y, 0.0, 1.0 * frame_size.height));
  };
  const int left = clamp_x(std::floor(x0 - margin)), right = clamp_x(std::ceil(x1 + margin) + 1);
  const int top = clamp_y(std::floor(y0 - margin)), bottom = clamp_y(std::ceil(y1 + margin) + 1);
  return cv::Rect(left, top, std::max(0, right - left), std::max(0, bottom - top));
}

int edlines_auto_min_line_length(cv::Size size) {
  const double log_nt = 2.0 * (std::log10(static_cast<double>(size.width)) +
                               std::log10(static_cast<double>(size.height)));
  return static_cast<int>(std::round(-log_nt / std::log10(0.125) * 0.5));
}

LineDetectorKind parse_line_detector_kind(const std::string& name) {
  if (name == "edlines" || name == "scbt-edlines") return LineDetectorKind::kEdLines;
  if (name == "opencv-edlines") return LineDetectorKind::kOpenCvEdLines;
  if (name == "lsd") return LineDetectorKind::kLsd;
  if (name == "fld") return LineDetectorKind::kFastLineDetector;
  throw std::invalid_argument("unknown line detector '" + name +
                              "' (use edlines, opencv-edlines, lsd or fld)");
}

std::string to_string(LineDetectorKind kind) {
  switch (kind) {
    case LineDetectorKind::kEdLines:
      return "edlines";
    case LineDetectorKind::kOpenCvEdLines:
      return "opencv-edlines";
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
  if (!(roi_padding >= 0.0 && roi_padding <= 1000.0)) {
    throw std::invalid_argument("roi_padding must be in [0, 1000], got " +
                                std::to_string(roi_padding));
  }
  if (!(min_line_length <= 10000.0)) {
    throw std::invalid_argument("min_line_length must be <= 10000, got " +
                                std::to_string(min_line_length));
  }
}

std::unique_ptr<LineDetector> make_line_detector(const LineDetectorOptions& options) {
  options.check();
  switch (options.kind) {
    case LineDetectorKind::kOpenCvEdLines:
      return std::make_unique<OpenCvEdLinesDetector>(options);
    case LineDetectorKind::kEdLines:
      return std::make_unique<OwnEdLinesDetector>(options);
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
