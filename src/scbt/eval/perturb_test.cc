#include "scbt/eval/perturb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

// A grey test card: flat mid-grey with a bright square, so blur and noise have something to act on.
cv::Mat card(int channels = 3) {
  cv::Mat m(120, 160, CV_8UC(channels), cv::Scalar::all(100));
  cv::rectangle(m, cv::Rect(40, 30, 60, 50), cv::Scalar::all(200), cv::FILLED);
  return m;
}

double mean_abs_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return cv::mean(d)[0];
}

TEST(Perturb, ParsesEverySpecAndNamesItBack) {
  for (const char* spec :
       {"none", "stride:3", "noise:15", "blur:2.5", "motion-blur:9,30", "brightness:0.3",
        "contrast:0.5", "gamma:2", "lowlight:0.3", "lowlight:0.3,5", "jpeg:15", "downscale:2"}) {
    EXPECT_EQ(parse_perturbation(spec).name(), spec);
  }
  const std::vector<Perturbation> list = parse_perturbation_list("none; stride:2 noise:5");
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[1].frame_stride(), 2);
  EXPECT_EQ(list[2].level, 5.0);
}

TEST(Perturb, RejectsBadSpecs) {
  for (const char* spec :
       {"", "fog:3", "noise", "noise:x", "stride:0", "stride:1.5", "jpeg:0", "jpeg:101", "blur:-1",
        "gamma:0", "noise:5,3", "none:1", "downscale:0.5", "noise:nan"}) {
    EXPECT_THROW(parse_perturbation(spec), std::invalid_argument) << spec;
  }
  EXPECT_THROW(parse_perturbation_list(" ; "), std::invalid_argument);
}

TEST(Perturb, NoiseHasTheRequestedSigmaAndIsSeededPerFrame) {
  const cv::Mat in = card();
  const Perturbation p = parse_perturbation("noise:10", 7);
  cv::Mat a, b, c;
  p.apply(in, 5, &a);
  p.apply(in, 5, &b);
  p.apply(in, 6, &c);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);  // same frame, same noise
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);  // another frame, other noise
  cv::Mat diff;
  cv::subtract(a, in, diff, cv::noArray(), CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(diff.reshape(1), mean, stddev);
  EXPECT_NEAR(stddev[0], 10.0, 0.5);
  EXPECT_NEAR(mean[0], 0.0, 0.3);
  const Perturbation other_seed = parse_perturbation("noise:10", 8);
  other_seed.apply(in, 5, &c);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
}

TEST(Perturb, BlursSpreadAnEdge) {
  const cv::Mat in = card(1);
  cv::Mat gaussian, motion;
  parse_perturbation("blur:2.5").apply(in, 1, &gaussian);
  parse_perturbation("motion-blur:10").apply(in, 1, &motion);
  // Flat areas stay, the square's edges are spread: left edge at x = 40.
  EXPECT_EQ(gaussian.at<uchar>(5, 5), 100);
  EXPECT_GT(gaussian.at<uchar>(55, 38), 110);
  EXPECT_LT(gaussian.at<uchar>(55, 41), 190);
  // Horizontal motion blur spreads the left edge but not the top edge (y = 30).
  EXPECT_GT(motion.at<uchar>(55, 37), 110);
  EXPECT_EQ(motion.at<uchar>(28, 70), 100);
  EXPECT_EQ(motion.at<uchar>(31, 70), 200);
  // Both keep the mean brightness.
  EXPECT_NEAR(cv::mean(gaussian)[0], cv::mean(in)[0], 0.5);
  EXPECT_NEAR(cv::mean(motion)[0], cv::mean(in)[0], 0.5);
}

TEST(Perturb, ExposureChanges) {
  const cv::Mat in = card(1);
  cv::Mat out;
  parse_perturbation("brightness:0.3").apply(in, 1, &out);
  EXPECT_EQ(out.at<uchar>(5, 5), 30);
  EXPECT_EQ(out.at<uchar>(55, 60), 60);
  parse_perturbation("contrast:0.5").apply(in, 1, &out);
  EXPECT_EQ(out.at<uchar>(5, 5), 114);
  EXPECT_EQ(out.at<uchar>(55, 60), 164);
  parse_perturbation("gamma:2").apply(in, 1, &out);
  EXPECT_EQ(out.at<uchar>(5, 5), 39);  // 255 * (100/255)^2
  parse_perturbation("lowlight:0.3,4").apply(in, 1, &out);
  EXPECT_NEAR(cv::mean(out(cv::Rect(0, 0, 30, 30)))[0], 30.0, 1.0);
  EXPECT_GT(mean_abs_difference(out(cv::Rect(0, 0, 30, 30)), cv::Mat(30, 30, CV_8U, 30)), 2.0);
}

TEST(Perturb, JpegDegradesButKeepsTheImage) {
  cv::Mat in = card();
  cv::Mat noisy;
  parse_perturbation("noise:20").apply(in, 1, &noisy);
  cv::Mat low, high;
  parse_perturbation("jpeg:10").apply(noisy, 1, &low);
  parse_perturbation("jpeg:95").apply(noisy, 1, &high);
  ASSERT_EQ(low.size(), in.size());
  ASSERT_EQ(low.type(), in.type());
  EXPECT_GT(mean_abs_difference(low, noisy), mean_abs_difference(high, noisy));
  EXPECT_LT(mean_abs_difference(low, in), 20.0);
}

TEST(Perturb, DownscaleAndPolygonScalingRoundTrip) {
  const Perturbation p = parse_perturbation("downscale:2");
  cv::Mat out;
  p.apply(card(), 1, &out);
  EXPECT_EQ(out.size(), cv::Size(80, 60));
  EXPECT_DOUBLE_EQ(p.scale(), 0.5);
  // The square's corner pixel (40, 30) covers small pixel (20, 15) exactly.
  EXPECT_EQ(out.at<cv::Vec3b>(15, 20)[0], 200);
  EXPECT_EQ(out.at<cv::Vec3b>(14, 19)[0], 100);
  const Polygon square = {{40, 30}, {99, 30}, {99, 79}, {40, 79}};
  const Polygon small = scale_polygon_to_frame(square, p.scale());
  EXPECT_NEAR(small[0].x, 19.75,
              1e-12);  // the centre of pixel 40 lies in small pixel 20's left half
  const Polygon back = scale_polygon_from_frame(small, p.scale());
  for (size_t i = 0; i < square.size(); ++i) {
    EXPECT_NEAR(back[i].x, square[i].x, 1e-12);
    EXPECT_NEAR(back[i].y, square[i].y, 1e-12);
  }
}

TEST(Perturb, StrideAndNoneCopy) {
  const cv::Mat in = card();
  cv::Mat out;
  parse_perturbation("stride:2").apply(in, 3, &out);
  EXPECT_EQ(cv::norm(in, out, cv::NORM_INF), 0.0);
  EXPECT_EQ(parse_perturbation("none").frame_stride(), 1);
  EXPECT_THROW(parse_perturbation("noise:5").apply(cv::Mat(), 1, &out), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
