#include "scbt/eval/perturb.h"

#include <cmath>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/eval/spec_text.h"

namespace scbt {
namespace {

struct KindName {
  PerturbationKind kind;
  const char* name;
};

constexpr KindName kKindNames[] = {
    {PerturbationKind::kNone, "none"},
    {PerturbationKind::kFrameStride, "stride"},
    {PerturbationKind::kNoise, "noise"},
    {PerturbationKind::kGaussianBlur, "blur"},
    {PerturbationKind::kMotionBlur, "motion-blur"},
    {PerturbationKind::kBrightness, "brightness"},
    {PerturbationKind::kContrast, "contrast"},
    {PerturbationKind::kGamma, "gamma"},
    {PerturbationKind::kLowLight, "lowlight"},
    {PerturbationKind::kJpeg, "jpeg"},
    {PerturbationKind::kDownscale, "downscale"},
    {PerturbationKind::kOcclude, "occlude"},
};

constexpr double kDefaultLowLightNoise = 3.0;

const char* kind_name(PerturbationKind kind) {
  for (const KindName& k : kKindNames) {
    if (k.kind == kind) return k.name;
  }
  return "?";
}

const char kGrammar[] =
    "expected none, stride:K, noise:SIGMA, blur:SIGMA, motion-blur:LENGTH[,DEGREES], "
    "brightness:B, contrast:C, gamma:G, lowlight:B[,SIGMA], jpeg:QUALITY, downscale:FACTOR or "
    "occlude:COVER[,SECONDS[,bar|disc|hand[,sweep|stay[,solid|textured]]]]";

void add_noise(const cv::Mat& frame, double sigma, std::uint64_t seed, int frame_index,
               cv::Mat* out) {
  cv::RNG rng(mix_seed(seed ^ mix_seed(static_cast<std::uint64_t>(frame_index))));
  cv::Mat noise(frame.size(), CV_32FC(frame.channels()));
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  cv::Mat sum;
  frame.convertTo(sum, CV_32F);
  sum += noise;
  sum.convertTo(*out, frame.type());  // rounds and saturates to 0..255
}

// A normalised line kernel of `length` px at `degrees` (anti-aliased by drawing it 8x larger).
cv::Mat motion_kernel(double length, double degrees) {
  const int size = 2 * static_cast<int>(std::ceil(length / 2.0)) + 1;
  constexpr int kSuper = 8;
  cv::Mat big = cv::Mat::zeros(size * kSuper, size * kSuper, CV_32F);
  const double c = (size * kSuper - 1) / 2.0;
  const double radians = degrees * CV_PI / 180.0;
  const double half = length * kSuper / 2.0;
  const cv::Point2d d(std::cos(radians) * half, -std::sin(radians) * half);
  constexpr int kShift = 4;
  const auto fixed = [](cv::Point2d p) {
    return cv::Point(static_cast<int>(std::lround(p.x * (1 << kShift))),
                     static_cast<int>(std::lround(p.y * (1 << kShift))));
  };
  cv::line(big, fixed(cv::Point2d(c, c) - d), fixed(cv::Point2d(c, c) + d), cv::Scalar(1.0), kSuper,
           cv::LINE_AA, kShift);
  cv::Mat kernel;
  cv::resize(big, kernel, cv::Size(size, size), 0, 0, cv::INTER_AREA);
  kernel /= cv::sum(kernel)[0];
  return kernel;
}

}  // namespace

std::string Perturbation::name() const {
  std::string n = kind_name(kind);
  if (kind == PerturbationKind::kNone) return n;
  if (kind == PerturbationKind::kOcclude) return n + ":" + occlusion.name();
  n += ":" + format_spec_number(level);
  if (kind == PerturbationKind::kMotionBlur && parameter != 0.0) {
    n += "," + format_spec_number(parameter);
  }
  if (kind == PerturbationKind::kLowLight && parameter != kDefaultLowLightNoise) {
    n += "," + format_spec_number(parameter);
  }
  return n;
}

void Perturbation::check() const {
  const auto fail = [this](const std::string& why) {
    throw std::invalid_argument("perturbation " + name() + ": " + why);
  };
  if (!std::isfinite(level) || !std::isfinite(parameter)) fail("levels must be finite");
  switch (kind) {
    case PerturbationKind::kNone:
      break;
    case PerturbationKind::kFrameStride:
      if (level < 1 || level != std::floor(level)) fail("the stride must be a whole number >= 1");
      break;
    case PerturbationKind::kNoise:
      if (level < 0) fail("the noise sigma must be >= 0");
      break;
    case PerturbationKind::kGaussianBlur:
      if (level < 0 || level > 50) fail("the blur sigma must be in 0..50");
      break;
    case PerturbationKind::kMotionBlur:
      if (level < 0 || level > 200) fail("the motion blur length must be in 0..200 px");
      break;
    case PerturbationKind::kBrightness:
    case PerturbationKind::kContrast:
      if (level < 0) fail("the factor must be >= 0");
      break;
    case PerturbationKind::kGamma:
      if (level <= 0) fail("gamma must be > 0");
      break;
    case PerturbationKind::kLowLight:
      if (level < 0) fail("the brightness factor must be >= 0");
      if (parameter < 0) fail("the noise sigma must be >= 0");
      break;
    case PerturbationKind::kJpeg:
      if (level < 1 || level > 100 || level != std::floor(level)) {
        fail("the JPEG quality must be a whole number in 1..100");
      }
      break;
    case PerturbationKind::kDownscale:
      if (level < 1 || level > 16) fail("the downscale factor must be in 1..16");
      break;
    case PerturbationKind::kOcclude:
      occlusion.check();
      break;
  }
}

int Perturbation::frame_stride() const {
  return kind == PerturbationKind::kFrameStride ? static_cast<int>(level) : 1;
}

double Perturbation::scale() const {
  return kind == PerturbationKind::kDownscale ? 1.0 / level : 1.0;
}

void Perturbation::apply(const cv::Mat& frame, int frame_index, cv::Mat* out) const {
  if (frame.empty() || frame.depth() != CV_8U) {
    throw std::invalid_argument("perturbation " + name() + ": the frame must be non-empty 8-bit");
  }
  switch (kind) {
    case PerturbationKind::kNone:
    case PerturbationKind::kFrameStride:
    case PerturbationKind::kOcclude:
      frame.copyTo(*out);
      return;
    case PerturbationKind::kNoise:
      add_noise(frame, level, seed, frame_index, out);
      return;
    case PerturbationKind::kGaussianBlur:
      if (level == 0) {
        frame.copyTo(*out);
      } else {
        cv::GaussianBlur(frame, *out, cv::Size(), level, level, cv::BORDER_REFLECT_101);
      }
      return;
    case PerturbationKind::kMotionBlur:
      if (level < 1) {
        frame.copyTo(*out);
      } else {
        cv::filter2D(frame, *out, -1, motion_kernel(level, parameter), cv::Point(-1, -1), 0,
                     cv::BORDER_REFLECT_101);
      }
      return;
    case PerturbationKind::kBrightness:
      frame.convertTo(*out, -1, level, 0.0);
      return;
    case PerturbationKind::kContrast:
      frame.convertTo(*out, -1, level, 128.0 * (1.0 - level));
      return;
    case PerturbationKind::kGamma: {
      cv::Mat table(1, 256, CV_8U);
      for (int v = 0; v < 256; ++v) {
        table.at<uchar>(v) = cv::saturate_cast<uchar>(255.0 * std::pow(v / 255.0, level));
      }
      cv::LUT(frame, table, *out);
      return;
    }
    case PerturbationKind::kLowLight: {
      cv::Mat dim;
      frame.convertTo(dim, -1, level, 0.0);
      add_noise(dim, parameter, seed, frame_index, out);
      return;
    }
    case PerturbationKind::kJpeg: {
      std::vector<uchar> bytes;
      cv::imencode(".jpg", frame, bytes, {cv::IMWRITE_JPEG_QUALITY, static_cast<int>(level)});
      *out = cv::imdecode(bytes, frame.channels() == 1 ? cv::IMREAD_GRAYSCALE : cv::IMREAD_COLOR);
      return;
    }
    case PerturbationKind::kDownscale: {
      const cv::Size size(std::max(1, static_cast<int>(std::lround(frame.cols / level))),
                          std::max(1, static_cast<int>(std::lround(frame.rows / level))));
      cv::resize(frame, *out, size, 0, 0, cv::INTER_AREA);
      return;
    }
  }
}

Perturbation parse_perturbation(const std::string& spec, std::uint64_t seed) {
  const size_t colon = spec.find(':');
  const std::string kind_text = spec.substr(0, colon);
  Perturbation p;
  p.seed = seed;
  bool known = false;
  for (const KindName& k : kKindNames) {
    if (kind_text == k.name) {
      p.kind = k.kind;
      known = true;
    }
  }
  if (!known) throw std::invalid_argument("unknown perturbation '" + spec + "'; " + kGrammar);
  if (p.kind == PerturbationKind::kNone) {
    if (colon != std::string::npos) {
      throw std::invalid_argument("perturbation 'none' takes no level; " + std::string(kGrammar));
    }
    return p;
  }
  if (colon == std::string::npos) {
    throw std::invalid_argument("perturbation '" + spec + "' needs a level; " + kGrammar);
  }
  const std::string args = spec.substr(colon + 1);
  if (p.kind == PerturbationKind::kOcclude) {
    p.occlusion = parse_occlusion_spec(args);
    p.level = p.occlusion.cover;
    return p;
  }
  const size_t comma = args.find(',');
  p.level = parse_spec_number(args.substr(0, comma), "perturbation '" + spec + "'", kGrammar);
  if (p.kind == PerturbationKind::kLowLight) p.parameter = kDefaultLowLightNoise;
  if (comma != std::string::npos) {
    if (p.kind != PerturbationKind::kMotionBlur && p.kind != PerturbationKind::kLowLight) {
      throw std::invalid_argument("perturbation '" + spec + "' takes one level; " + kGrammar);
    }
    p.parameter =
        parse_spec_number(args.substr(comma + 1), "perturbation '" + spec + "'", kGrammar);
  }
  p.check();
  return p;
}

std::vector<Perturbation> parse_perturbation_list(const std::string& specs, std::uint64_t seed) {
  std::vector<Perturbation> list;
  std::string item;
  for (size_t i = 0; i <= specs.size(); ++i) {
    const char c = i < specs.size() ? specs[i] : ';';
    if (c == ';' || c == ' ' || c == '\t' || c == '\n') {
      if (!item.empty()) list.push_back(parse_perturbation(item, seed));
      item.clear();
    } else {
      item += c;
    }
  }
  if (list.empty()) throw std::invalid_argument("no perturbation given; " + std::string(kGrammar));
  return list;
}

Polygon scale_polygon_to_frame(const Polygon& polygon, double scale) {
  Polygon scaled = polygon;
  for (Point& p : scaled) p = (p + Point(0.5, 0.5)) * scale - Point(0.5, 0.5);
  return scaled;
}

Polygon scale_polygon_from_frame(const Polygon& polygon, double scale) {
  Polygon scaled = polygon;
  for (Point& p : scaled) p = (p + Point(0.5, 0.5)) * (1.0 / scale) - Point(0.5, 0.5);
  return scaled;
}

}  // namespace scbt
