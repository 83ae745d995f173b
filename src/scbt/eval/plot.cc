#include "scbt/eval/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/io/atomic_file.h"

namespace scbt {
namespace {

const cv::Scalar kBlack(0, 0, 0), kGrid(225, 225, 225), kWhite(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

void put_text(cv::Mat& image, const std::string& text, cv::Point origin, double scale,
              const cv::Scalar& colour = kBlack, int thickness = 1) {
  cv::putText(image, text, origin, kFont, scale, colour, thickness, cv::LINE_AA);
}

cv::Size text_size(const std::string& text, double scale, int thickness = 1) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, thickness, &baseline);
}

// Text centred horizontally on x with its baseline at y.
void put_centred(cv::Mat& image, const std::string& text, int x, int y, double scale,
                 int thickness = 1) {
  put_text(image, text, {x - text_size(text, scale, thickness).width / 2, y}, scale, kBlack,
           thickness);
}

// Text rotated a quarter turn counter-clockwise, centred on (x, y).
void put_vertical(cv::Mat& image, const std::string& text, int x, int y, double scale) {
  const cv::Size size = text_size(text, scale);
  cv::Mat label(size.height + 8, size.width + 4, image.type(), kWhite);
  put_text(label, text, {2, size.height + 2}, scale);
  cv::Mat rotated;
  cv::rotate(label, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect target(x - rotated.cols / 2, y - rotated.rows / 2, rotated.cols, rotated.rows);
  target &= cv::Rect(0, 0, image.cols, image.rows);
  if (target.area() > 0) {
    rotated(cv::Rect(0, 0, target.width, target.height)).copyTo(image(target));
  }
}

std::string tick_label(double value, int decimals) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

void draw_panel(cv::Mat& panel, const PlotPanel& data, const PlotOptions& options,
                const std::map<std::string, size_t>& colour_of) {
  // Plot area inside the panel, leaving room for the title, tick labels and axis labels.
  const int left = 62, right = 16, top = 34, bottom = 48;
  const cv::Rect area(left, top, panel.cols - left - right, panel.rows - top - bottom);
  auto to_x = [&](double threshold) {
    return area.x + static_cast<int>(std::lround(threshold / options.max_threshold * area.width));
  };
  auto to_y = [&](double rate) {
    return area.y + area.height - static_cast<int>(std::lround(rate * area.height));
  };
  put_centred(panel, data.title, area.x + area.width / 2, 24, 0.6, 2);

  // Grid and ticks: x every 10 px (or a fifth of the range), y every 0.2.
  const double x_step = options.max_threshold >= 10.0 ? 10.0 : options.max_threshold / 5.0;
  for (double t = 0.0; t <= options.max_threshold + 1e-9; t += x_step) {
    const int x = to_x(t);
    cv::line(panel, {x, area.y}, {x, area.y + area.height}, kGrid, 1);
    cv::line(panel, {x, area.y + area.height}, {x, area.y + area.height + 5}, kBlack, 1);
    put_centred(panel, tick_label(t, x_step < 1.0 ? 1 : 0), x, area.y + area.height + 20, 0.42);
  }
  for (int i = 0; i <= 5; ++i) {
    const double rate = 0.2 * i;
    const int y = to_y(rate);
    cv::line(panel, {area.x, y}, {area.x + area.width, y}, kGrid, 1);
    cv::line(panel, {area.x - 5, y}, {area.x, y}, kBlack, 1);
    const std::string label = tick_label(rate, 1);
    put_text(panel, label, {area.x - 9 - text_size(label, 0.42).width, y + 5}, 0.42);
  }
  cv::rectangle(panel, area, kBlack, 1);
  put_centred(panel, "E_AL threshold (px)", area.x + area.width / 2, panel.rows - 8, 0.48);
  put_vertical(panel, "success rate", 13, area.y + area.height / 2, 0.48);

  // Curves, clipped to the plot area; `ink` marks their pixels for placing the legend.
  cv::Mat plot = panel(area);
  cv::Mat ink(area.size(), CV_8U, cv::Scalar(0));
  for (const PlotLine& line : data.lines) {
    std::vector<cv::Point> points;
    for (size_t i = 0; i < line.curve.thresholds.size() && i < line.curve.rates.size(); ++i) {
      if (line.curve.thresholds[i] > options.max_threshold + 1e-9) break;
      points.emplace_back(to_x(line.curve.thresholds[i]) - area.x,
                          to_y(line.curve.rates[i]) - area.y);
    }
    if (points.size() >= 2) {
      cv::polylines(plot, points, false, plot_colour(colour_of.at(line.label)), 2, cv::LINE_AA);
      cv::polylines(ink, points, false, cv::Scalar(255), 3);
    }
  }

  // Legend: in the lower right corner of the plot area unless curves run there; then in the
  // candidate place that hides the fewest curve pixels.
  if (data.lines.empty()) {
    put_centred(panel, "no data", area.x + area.width / 2, area.y + area.height / 2, 0.6);
    return;
  }
  std::vector<std::string> labels;
  int width = 0;
  for (const PlotLine& line : data.lines) {
    std::string label = line.label;
    if (line.auc >= 0.0) label += " (AUC " + tick_label(line.auc, 3) + ")";
    width = std::max(width, text_size(label, 0.42).width);
    labels.push_back(label);
  }
  const int row = 18, sample = 26;
  const cv::Size size(width + sample + 16, row * static_cast<int>(labels.size()) + 8);
  // Nine places (corners, edge middles, centre), the lower right first: the first of those
  // hiding the fewest curve pixels wins.
  const int xs[] = {area.width - size.width - 6, (area.width - size.width) / 2, 6};
  const int ys[] = {area.height - size.height - 6, (area.height - size.height) / 2, 6};
  std::vector<cv::Point> candidates;
  for (int y : ys) {
    for (int x : xs) candidates.emplace_back(x, y);
  }
  cv::Rect box;
  int best = -1;
  for (const cv::Point& corner : candidates) {
    const cv::Rect place = cv::Rect(corner, size) & cv::Rect(0, 0, area.width, area.height);
    const int hidden = cv::countNonZero(ink(place));
    if (best < 0 || hidden < best) {
      best = hidden;
      box = cv::Rect(corner + area.tl(), size);
    }
  }
  cv::Mat background = panel(box & cv::Rect(0, 0, panel.cols, panel.rows));
  cv::addWeighted(background, 0.15, cv::Mat(background.size(), background.type(), kWhite), 0.85,
                  0.0, background);
  cv::rectangle(panel, box, cv::Scalar(160, 160, 160), 1);
  for (size_t i = 0; i < labels.size(); ++i) {
    const int y = box.y + 4 + row * static_cast<int>(i) + row / 2;
    const cv::Scalar colour = plot_colour(colour_of.at(data.lines[i].label));
    cv::line(panel, {box.x + 6, y}, {box.x + 6 + sample - 6, y}, colour, 2, cv::LINE_AA);
    put_text(panel, labels[i], {box.x + 6 + sample, y + 5}, 0.42);
  }
}

}  // namespace

void PlotOptions::check() const {
  if (panel_width < 200 || panel_width > 4000) {
    throw std::invalid_argument("plot panel width " + std::to_string(panel_width) +
                                " outside 200..4000");
  }
  if (panel_height < 150 || panel_height > 4000) {
    throw std::invalid_argument("plot panel height " + std::to_string(panel_height) +
                                " outside 150..4000");
  }
  if (columns < 0 || columns > 16) {
    throw std::invalid_argument("plot columns " + std::to_string(columns) + " outside 0..16");
  }
  if (!(max_threshold > 0.0) || !std::isfinite(max_threshold)) {
    throw std::invalid_argument("plot max threshold " + std::to_string(max_threshold) +
                                " must be positive");
  }
}

cv::Scalar plot_colour(size_t index) {
  // A qualitative palette (BGR), readable on white and distinct for the first ten labels.
  static const cv::Scalar kPalette[] = {
      {180, 119, 31}, {14, 127, 255},  {44, 160, 44},   {40, 39, 214},  {189, 103, 148},
      {75, 86, 140},  {194, 119, 227}, {127, 127, 127}, {34, 189, 188}, {207, 190, 23}};
  return kPalette[index % (sizeof(kPalette) / sizeof(kPalette[0]))];
}

cv::Mat render_success_curves(const std::vector<PlotPanel>& panels, const PlotOptions& options) {
  options.check();
  std::vector<PlotPanel> shown = panels;
  if (shown.empty()) shown.push_back({"", {}});
  std::map<std::string, size_t> colour_of;
  for (const PlotPanel& panel : shown) {
    for (const PlotLine& line : panel.lines) colour_of.emplace(line.label, colour_of.size());
  }
  const int count = static_cast<int>(shown.size());
  int columns = options.columns;
  if (columns == 0) {
    // 1-3 panels in a row, 4 as 2x2, 5-6 and 9 in rows of 3, anything else in rows of 4.
    columns = count <= 3 ? count : count == 4 ? 2 : (count <= 6 || count == 9) ? 3 : 4;
  }
  columns = std::min(columns, count);
  const int rows = (count + columns - 1) / columns;
  cv::Mat image(rows * options.panel_height, columns * options.panel_width, CV_8UC3, kWhite);
  for (int i = 0; i < count; ++i) {
    cv::Mat panel =
        image(cv::Rect((i % columns) * options.panel_width, (i / columns) * options.panel_height,
                       options.panel_width, options.panel_height));
    draw_panel(panel, shown[i], options, colour_of);
  }
  return image;
}

void write_png(const std::string& path, const cv::Mat& image) {
  std::vector<uchar> bytes;
  if (image.empty() || !cv::imencode(".png", image, bytes)) {
    throw std::runtime_error(path + ": cannot encode PNG");
  }
  AtomicFile file(path);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()),
                      static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

}  // namespace scbt
