// PNG figures of success-rate curves like the paper's Fig. 5: one panel per sequence, one line per
// tracker, with axes, ticks, labels and a legend, drawn with OpenCV.
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/eval/success_curve.h"

namespace scbt {

struct PlotLine {
  std::string label;  // tracker name; the same label gets the same colour in every panel
  SuccessCurve curve;
  double auc = -1.0;  // shown in the legend when >= 0
};

struct PlotPanel {
  std::string title;  // sequence name
  std::vector<PlotLine> lines;
};

struct PlotOptions {
  int panel_width = 480;  // pixels per panel
  int panel_height = 360;
  int columns = 0;              // panels per row; 0 picks a grid of at most 4 columns
  double max_threshold = 50.0;  // x axis range 0..max_threshold (px)

  // Throws std::invalid_argument naming the bad value.
  void check() const;
};

// The colour (BGR) of the i-th distinct label.
cv::Scalar plot_colour(size_t index);

// A 3-channel 8-bit image with the panels in a grid (row-major). An empty list gives a single
// panel saying "no data". Throws std::invalid_argument for bad options.
cv::Mat render_success_curves(const std::vector<PlotPanel>& panels,
                              const PlotOptions& options = {});

// Encodes `image` as PNG and writes it atomically. Throws std::runtime_error naming the path.
void write_png(const std::string& path, const cv::Mat& image);

}  // namespace scbt
