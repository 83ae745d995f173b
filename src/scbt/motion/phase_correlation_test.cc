#include "scbt/motion/phase_correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

// A smooth random texture as floats, multiplied by a Hann window (the correlator's caller
// windows its inputs), of `size`, sampled with its content moved by `shift` (bilinear).
cv::Mat windowed_texture(cv::Size size, cv::Point2d shift, unsigned seed) {
  cv::Mat noise(size.height + 80, size.width + 80, CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0.0, 255.0);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.0);
  cv::normalize(noise, noise, 0.0, 255.0, cv::NORM_MINMAX);
  // Content moved by `shift`: the output at p reads the texture at p - shift.
  const cv::Mat to_source = (cv::Mat_<double>(2, 3) << 1, 0, 40 - shift.x, 0, 1, 40 - shift.y);
  cv::Mat moved;
  cv::warpAffine(noise, moved, to_source, size, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP);
  cv::Mat window;
  cv::createHanningWindow(window, size, CV_32F);
  return moved.mul(window);
}

TEST(PhaseCorrelator, RecoversShiftsOfATexture) {
  PhaseCorrelator correlator;
  // DFT-friendly sizes; 153 and 101 are padded (to 160 and 108).
  const cv::Size sizes[] = {{128, 96}, {160, 120}, {153, 128}, {101, 100}};
  const cv::Point2d shifts[] = {{3.0, -2.0}, {-6.3, 4.6}, {0.4, 0.0}, {11.7, -9.2}};
  unsigned seed = 1;
  for (const cv::Size& size : sizes) {
    for (const cv::Point2d& shift : shifts) {
      const cv::Mat reference = windowed_texture(size, {0.0, 0.0}, seed);
      const cv::Mat current = windowed_texture(size, shift, seed);
      ++seed;
      const PhaseCorrelation result = correlator.correlate(reference, current);
      // The window stays where it is while the content moves, and the 5x5 centroid pulls toward
      // the integer peak: a few tenths of a pixel.
      EXPECT_NEAR(result.shift.x, shift.x, 0.5) << size << " " << shift;
      EXPECT_NEAR(result.shift.y, shift.y, 0.5) << size << " " << shift;
      EXPECT_GT(result.response, 0.1);
    }
  }
}

// It computes what cv::phaseCorrelate computes (given the windowed images and no window of its
// own), to the bit, on even, odd and padded sizes: the tracker's measured motion stays what it was
// measured with.
TEST(PhaseCorrelator, ComputesExactlyWhatOpenCVDoes) {
  PhaseCorrelator correlator;  // reused across sizes, as the tracker's estimator reuses it
  const cv::Size sizes[] = {{128, 96}, {75, 135}, {153, 128}, {101, 97}, {64, 64}, {45, 243}};
  const cv::Point2d shifts[] = {{3.0, -2.0}, {-6.3, 4.6}, {11.7, -9.2}};
  unsigned seed = 50;
  for (const cv::Size& size : sizes) {
    for (const cv::Point2d& shift : shifts) {
      const cv::Mat reference = windowed_texture(size, {0.0, 0.0}, seed);
      const cv::Mat current = windowed_texture(size, shift, seed);
      ++seed;
      double opencv_response = 0.0;
      const cv::Point2d opencv =
          cv::phaseCorrelate(reference, current, cv::noArray(), &opencv_response);
      const PhaseCorrelation ours = correlator.correlate(reference, current);
      EXPECT_EQ(ours.shift.x, opencv.x) << size << " " << shift;
      EXPECT_EQ(ours.shift.y, opencv.y) << size << " " << shift;
      EXPECT_EQ(ours.response, opencv_response) << size << " " << shift;
    }
  }
}

TEST(PhaseCorrelator, AnImageAgainstItselfPeaksAtZeroWithFullResponse) {
  PhaseCorrelator correlator;
  const cv::Mat image = windowed_texture({120, 90}, {0.0, 0.0}, 5);
  const PhaseCorrelation result = correlator.correlate(image, image);
  EXPECT_NEAR(result.shift.x, 0.0, 1e-3);
  EXPECT_NEAR(result.shift.y, 0.0, 1e-3);
  // All the correlation's energy in the 5x5 window at the peak: the response is about 1.
  EXPECT_GT(result.response, 0.95);
  EXPECT_LT(result.response, 1.05);
}

// A negative shift is a peak in the far half of the periodic correlation.
TEST(PhaseCorrelator, RecoversLargeNegativeShifts) {
  PhaseCorrelator correlator;
  const cv::Mat reference = windowed_texture({96, 96}, {0.0, 0.0}, 9);
  const cv::Mat current = windowed_texture({96, 96}, {-20.0, -15.0}, 9);
  const PhaseCorrelation result = correlator.correlate(reference, current);
  EXPECT_NEAR(result.shift.x, -20.0, 0.5);
  EXPECT_NEAR(result.shift.y, -15.0, 0.5);
}

TEST(PhaseCorrelator, RejectsImagesItCannotCorrelate) {
  PhaseCorrelator correlator;
  const cv::Mat a(32, 32, CV_32F, cv::Scalar(1.0f));
  EXPECT_THROW(correlator.correlate(a, cv::Mat(32, 31, CV_32F, cv::Scalar(1.0f))),
               std::invalid_argument);
  EXPECT_THROW(correlator.correlate(a, cv::Mat(32, 32, CV_8U, cv::Scalar(1))),
               std::invalid_argument);
  EXPECT_THROW(correlator.correlate(cv::Mat(), cv::Mat()), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
