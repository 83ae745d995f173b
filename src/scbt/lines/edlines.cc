#include "scbt/lines/edlines.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

namespace scbt {

int edlines_min_line_length(const EdLinesParams& params, cv::Size full_size) {
  if (params.min_line_length > 0) return params.min_line_length;
  const double log_nt =
      2.0 * (std::log10(std::max(1, full_size.width)) + std::log10(std::max(1, full_size.height)));
  const int automatic = static_cast<int>(std::round(-log_nt / std::log10(0.125) * 0.5));
  return std::max(automatic, 9);
}

EdLines::EdLines(const EdLinesParams& params) : params_(params) {}

void EdLines::detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size, const cv::Mat& band,
                     std::vector<Segment>* out) {
  const RowSpans* spans = nullptr;
  if (!gray.empty() && !band.empty()) {
    if (band.type() != CV_8UC1 || band.size() != gray.size()) {
      throw std::invalid_argument("EdLines band mask must be CV_8UC1 of the image's size");
    }
    band_from_mask_.assign_from_mask(band);
    spans = &band_from_mask_;
  }
  detect(gray, offset, full_size, spans, out);
}

void EdLines::detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size,
                     const RowSpans* band, std::vector<Segment>* out) {
  out->clear();
  if (gray.empty()) return;
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("EdLines needs an 8-bit single-channel image, got type " +
                                std::to_string(gray.type()));
  }
  if (band != nullptr && band->size() != gray.size()) {
    throw std::invalid_argument("EdLines band spans must be on the image's window");
  }
  width_ = gray.cols;
  height_ = gray.rows;
  seg_pixels_.clear();
  seg_start_.clear();
  seg_end_.clear();
  open_begin_ = 0;
  lines_.clear();
  if (width_ < 5 || height_ < 5) return;  // no interior pixel can be an anchor

  // OpenCV's GaussianBlur of a view into a larger image reads the pixels around it (and rounds
  // differently): for other sigmas than EDLines' 1 (gaussian_blur_5x5, which reads the view's
  // pixels only), work on a copy, so that the result depends on the window's pixels only.
  const cv::Mat* input = &gray;
  if (!gray.isContinuous() && params_.sigma != 1.0) {
    gray.copyTo(contiguous_);
    input = &contiguous_;
  }
  if (band != nullptr && params_.compute_near_band_only && params_.sigma == 1.0 &&
      std::max(params_.scan_interval, 1) == 1) {
    smooth_and_gradient(*input, cv::Mat(), band);
    find_anchors(true);
  } else {
    if (band != nullptr) band->draw(&band_mask_);
    smooth_and_gradient(*input, band != nullptr ? band_mask_ : cv::Mat(), nullptr);
    find_anchors(false);
  }
  sort_anchors();
  draw_edges();
  fit_lines(edlines_min_line_length(params_, full_size));
  join_collinear_lines();

  const double log_nt = 2.0 * (std::log10(std::max(1, width_)) + std::log10(std::max(1, height_)));
  log_nt_ = log_nt;
  out->reserve(lines_.size());
  for (const Line& line : lines_) {
    if (params_.nfa_validation && !validate(line, *input)) continue;
    out->push_back({Point(line.sx + offset.x, line.sy + offset.y),
                    Point(line.ex + offset.x, line.ey + offset.y)});
  }
}

std::vector<std::vector<cv::Point>> EdLines::edge_segments() const {
  std::vector<std::vector<cv::Point>> segments;
  for (size_t s = 0; s < seg_start_.size(); ++s) {
    std::vector<cv::Point>& points = segments.emplace_back();
    for (int i = seg_start_[s]; i < seg_end_[s]; ++i) {
      points.emplace_back(seg_pixels_[i] % width_, seg_pixels_[i] / width_);
    }
  }
  return segments;
}

}  // namespace scbt
