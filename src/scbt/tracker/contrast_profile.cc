#include "scbt/tracker/contrast_profile.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scbt/geometry/pixel_round.h"

namespace scbt {
namespace {

// weighted[c][v]: the grey weight of channel c (B, G, R: ITU-R BT.601) times level v, the product
// the grey level sums, looked up rather than multiplied (a box is read on every tracked frame).
struct ChannelWeights {
  std::array<std::array<double, 256>, 3> weighted;
  ChannelWeights() {
    const double weight[3] = {0.114, 0.587, 0.299};
    for (int c = 0; c < 3; ++c) {
      for (int v = 0; v < 256; ++v) weighted[c][v] = weight[c] * v;
    }
  }
};

// The sum of the grey levels of the (2 r + 1)^2 box centred on pixel (x, y), inside an image of
// kChannels channels.
template <int kChannels>
double box_sum(const cv::Mat& image, int x, int y, int r, const ChannelWeights& weights) {
  const auto& [blue, green, red] = weights.weighted;
  double sum = 0.0;
  for (int yy = y - r; yy <= y + r; ++yy) {
    const std::uint8_t* p = image.ptr<std::uint8_t>(yy) + static_cast<size_t>(x - r) * kChannels;
    for (int xx = x - r; xx <= x + r; ++xx, p += kChannels) {
      if constexpr (kChannels == 1) {
        sum += p[0];
      } else {
        sum += blue[p[0]] + green[p[1]] + red[p[2]];
      }
    }
  }
  return sum;
}

// Mean grey level of the (2 r + 1)^2 box centred on pixel (x, y); false if it leaves the image.
// The box is read in a loop compiled for the image's channels (1, 3 or 4, as contrast_profile
// admits): two boxes per sample.
bool box_mean(const cv::Mat& image, int x, int y, int r, double* mean) {
  if (x - r < 0 || y - r < 0 || x + r >= image.cols || y + r >= image.rows) return false;
  static const ChannelWeights weights;
  const int channels = image.channels();
  const double sum = channels == 1   ? box_sum<1>(image, x, y, r, weights)
                     : channels == 3 ? box_sum<3>(image, x, y, r, weights)
                                     : box_sum<4>(image, x, y, r, weights);
  *mean = sum / ((2 * r + 1) * (2 * r + 1));
  return true;
}

}  // namespace

void ContrastProfileOptions::check() const {
  if (samples < 3 || samples > 10000) {
    throw std::invalid_argument("contrast profile samples must be in 3..10000, got " +
                                std::to_string(samples));
  }
  if (!(across > 0.0 && across <= 50.0)) {
    throw std::invalid_argument("contrast profile across must be in (0, 50] px");
  }
  if (smoothing < 0 || smoothing > 10) {
    throw std::invalid_argument("contrast profile smoothing must be in 0..10");
  }
}

void contrast_profile(const cv::Mat& image, const Polygon& boundary,
                      const ContrastProfileOptions& options, std::vector<float>* profile) {
  if (image.depth() != CV_8U || image.channels() == 2 || image.channels() > 4) {
    throw std::invalid_argument("contrast profile needs an 8-bit image of 1, 3 or 4 channels");
  }
  profile->assign(static_cast<size_t>(options.samples), 0.0f);
  const size_t n = boundary.size();
  const double length = perimeter(boundary);
  if (n < 3 || !(length > 0.0)) return;
  const double step = length / options.samples;
  double along = 0.5 * step;  // arc length of the next sample
  double edge_start = 0.0;
  int k = 0;
  for (size_t i = 0; i < n && k < options.samples; ++i) {
    const Point& a = boundary[i];
    const Point& b = boundary[(i + 1) % n];
    const double edge = cv::norm(b - a);
    if (edge <= 0.0) continue;
    const Point t = (b - a) * (1.0 / edge);
    const Point normal(t.y, -t.x);  // one side of the boundary, fixed by its orientation
    for (; along < edge_start + edge && k < options.samples; along += step, ++k) {
      const Point p = a + t * (along - edge_start);
      const Point out = p + normal * options.across, in = p - normal * options.across;
      double outside = 0.0, inside = 0.0;
      if (box_mean(image, round_to_pixel(out.x), round_to_pixel(out.y), options.smoothing,
                   &outside) &&
          box_mean(image, round_to_pixel(in.x), round_to_pixel(in.y), options.smoothing, &inside)) {
        (*profile)[k] = static_cast<float>(outside - inside);
      }
    }
    edge_start += edge;
  }
}

double profile_agreement(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return 0.0;
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += static_cast<double>(a[i]) * b[i];
    aa += static_cast<double>(a[i]) * a[i];
    bb += static_cast<double>(b[i]) * b[i];
  }
  return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : 0.0;
}

void BoundaryAppearance::remember(const cv::Mat& image, const Polygon& boundary) {
  contrast_profile(image, boundary, options_, &reference_);
}

double BoundaryAppearance::agreement(const cv::Mat& image, const Polygon& placement) {
  if (reference_.empty()) return 0.0;
  contrast_profile(image, placement, options_, &buffer_);
  return profile_agreement(reference_, buffer_);
}

}  // namespace scbt
