#include "scbt/eval/plot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <limits>
#include <opencv2/imgcodecs.hpp>

namespace scbt {
namespace {

// Pixels of `image` inside `roi` within a small distance of `colour`.
int count_colour(const cv::Mat& image, const cv::Rect& roi, const cv::Scalar& colour) {
  int count = 0;
  for (int y = roi.y; y < roi.y + roi.height; ++y) {
    for (int x = roi.x; x < roi.x + roi.width; ++x) {
      const cv::Vec3b p = image.at<cv::Vec3b>(y, x);
      if (std::abs(p[0] - colour[0]) + std::abs(p[1] - colour[1]) + std::abs(p[2] - colour[2]) <
          30) {
        ++count;
      }
    }
  }
  return count;
}

TEST(Plot, GridHasOnePanelPerSequence) {
  PlotOptions options;
  for (int panels = 1; panels <= 9; ++panels) {
    std::vector<PlotPanel> data(panels);
    const cv::Mat image = render_success_curves(data, options);
    ASSERT_EQ(image.type(), CV_8UC3);
    EXPECT_EQ(image.cols % options.panel_width, 0);
    EXPECT_EQ(image.rows % options.panel_height, 0);
    const int cells = (image.cols / options.panel_width) * (image.rows / options.panel_height);
    EXPECT_GE(cells, panels);
    EXPECT_LT(cells - panels, image.cols / options.panel_width) << "a whole empty row";
    EXPECT_LE(image.cols / options.panel_width, 4);
  }
  options.columns = 2;
  EXPECT_EQ(render_success_curves(std::vector<PlotPanel>(5), options).size(),
            cv::Size(2 * options.panel_width, 3 * options.panel_height));
}

TEST(Plot, CurvesAreDrawnWhereTheirRatesAre) {
  // A perfect tracker (rate 1 from 1 px on) and a failing one (rate 0) in one panel, and only
  // the failing one in the next: each colour shows up where its curve lies, and only there.
  const std::vector<double> perfect(10, 0.0);
  const std::vector<double> failing(10, std::numeric_limits<double>::infinity());
  PlotPanel both{"Both",
                 {{"good", success_curve(perfect), 1.0}, {"bad", success_curve(failing), 0.0}}};
  PlotPanel bad_only{"Bad only", {{"bad", success_curve(failing), 0.0}}};
  PlotOptions options;
  options.columns = 2;
  const cv::Mat image = render_success_curves({both, bad_only}, options);
  const cv::Scalar good_colour = plot_colour(0), bad_colour = plot_colour(1);
  const int w = options.panel_width, h = options.panel_height;
  // Top and bottom bands of the first panel's plot area (away from the legend at lower right).
  const cv::Rect top(w / 4, 30, w / 2, h / 6), bottom(70, h - 60, w / 4, 20);
  EXPECT_GT(count_colour(image, top, good_colour), 20);
  EXPECT_EQ(count_colour(image, top, bad_colour), 0);
  EXPECT_GT(count_colour(image, bottom, bad_colour), 20);
  const cv::Rect second(w, 0, w, h);
  EXPECT_EQ(count_colour(image, second, good_colour), 0);
  EXPECT_GT(count_colour(image, second, bad_colour), 20);
}

TEST(Plot, LegendAvoidsTheCurves) {
  // A curve flat at 0.1 runs through the lower right corner, where the legend goes by default;
  // a curve at 0.9 keeps the top busy. The legend must move and leave the low curve visible.
  SuccessCurve low, high;
  for (int t = 0; t <= 50; ++t) {
    low.thresholds.push_back(t);
    low.rates.push_back(0.1);
    high.thresholds.push_back(t);
    high.rates.push_back(0.9);
  }
  PlotOptions options;
  const cv::Mat image = render_success_curves({{"P", {{"low", low, 0.0}, {"high", high, 0.0}}}});
  const int w = options.panel_width, h = options.panel_height;
  // The right end of the plot area around rate 0.1 (the x axis is 48 px above the panel's bottom,
  // the plot area 278 px high, so rate 0.1 is about 76 px above the bottom).
  const cv::Rect corner(w - 140, h - 96, 110, 40);
  // No legend text (black) nor legend frame (grey 160) there; the grid (grey 225) may be.
  EXPECT_EQ(count_colour(image, corner, cv::Scalar(0, 0, 0)), 0) << "legend text in the corner";
  EXPECT_EQ(count_colour(image, corner, cv::Scalar(160, 160, 160)), 0) << "legend frame there";
  EXPECT_GT(count_colour(image, corner, plot_colour(0)), 100) << "the low curve is hidden";
}

TEST(Plot, RejectsBadOptions) {
  PlotOptions options;
  options.panel_width = 10;
  EXPECT_THROW(render_success_curves({}, options), std::invalid_argument);
  options = {};
  options.max_threshold = 0.0;
  EXPECT_THROW(render_success_curves({}, options), std::invalid_argument);
}

TEST(Plot, WritesAReadablePng) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("scbt-plot-test-" + std::to_string(::getpid()) + ".png");
  const cv::Mat image = render_success_curves({{"Seq", {{"t", success_curve({1.0, 2.0}), -1}}}});
  write_png(path.string(), image);
  const cv::Mat back = cv::imread(path.string(), cv::IMREAD_COLOR);
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), image.size());
  EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  EXPECT_THROW(write_png("/nonexistent-dir/x.png", image), std::runtime_error);
}

}  // namespace
}  // namespace scbt
