// Camera-like degradations of a video, to measure how tracking holds up on worse cameras than the
// dataset's: lower frame rate, sensor noise, defocus and motion blur, exposure, low light, heavy
// JPEG compression and lower resolution. Every perturbation is seeded and deterministic per frame
// (the same frame gets the same noise whatever order or thread it is processed in).
//
// Spec strings (`parse_perturbation`), LEVEL a number, optional parameters after commas:
//   none               the frames as recorded
//   stride:K           keep every K-th frame (1, 1+K, 1+2K, ...): K times lower frame rate
//   noise:SIGMA        additive Gaussian noise of standard deviation SIGMA (grey levels, per
//   channel) blur:SIGMA         Gaussian blur of standard deviation SIGMA (px), defocus
//   motion-blur:L[,A]  linear motion blur over L px at A degrees (0 = horizontal; default 0)
//   brightness:B       every value times B (then clipped to 0..255)
//   contrast:C         values scaled by C about mid-grey 128
//   gamma:G            v -> 255 (v / 255)^G (G > 1 darkens the mid-tones)
//   lowlight:B[,SIGMA] brightness B plus Gaussian noise SIGMA (default 3): a dim scene, gain noise
//   jpeg:Q             re-encoded as JPEG of quality Q (1..100)
//   downscale:F        resolution divided by F (area averaging); the tracker sees the small frames
//                      and its results are scaled back by F to be scored at full size
//   occlude:COVER[,SECONDS[,SHAPE[,MOTION[,FILL]]]]
//                      occluders passing over the object at seeded positions (eval/occlusion.h);
//                      drawn by the evaluation, which knows where the object is
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/eval/occlusion.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

enum class PerturbationKind {
  kNone,
  kFrameStride,
  kNoise,
  kGaussianBlur,
  kMotionBlur,
  kBrightness,
  kContrast,
  kGamma,
  kLowLight,
  kJpeg,
  kDownscale,
  kOcclude,
};

struct Perturbation {
  PerturbationKind kind = PerturbationKind::kNone;
  // The main level: K, SIGMA, L, B, C, G, Q or F as in the spec grammar above.
  double level = 0.0;
  // Second parameter: motion-blur angle (degrees) or low-light noise sigma.
  double parameter = 0.0;
  std::uint64_t seed = 1;   // noise seed; the frame index is mixed in per frame
  OcclusionSpec occlusion;  // kOcclude: the occluders (placed per sequence by OcclusionPlan)

  // The spec string that parses back to this perturbation, e.g. "noise:15", "lowlight:0.3,3".
  std::string name() const;
  // Throws std::invalid_argument naming the bad value (e.g. stride < 1, JPEG quality > 100).
  void check() const;

  // Only frames 1, 1 + stride, ... are shown to the tracker (1 for everything but kFrameStride).
  int frame_stride() const;
  // Size factor of the frames the tracker sees (1 / F for kDownscale, else 1).
  double scale() const;

  // Writes the degraded version of `frame` (8-bit, 1, 3 or 4 channels) to `out`; frame_index
  // (1-based, in the original numbering) seeds the noise. For kDownscale `out` is smaller;
  // kNone, kFrameStride and kOcclude copy. `out` must not alias `frame`.
  void apply(const cv::Mat& frame, int frame_index, cv::Mat* out) const;
};

// Parses one spec ("noise:15"). Throws std::invalid_argument with the grammar on a bad spec.
Perturbation parse_perturbation(const std::string& spec, std::uint64_t seed = 1);
// A comma list is ambiguous with the parameters, so lists are separated by ';' or whitespace:
// "noise:5;noise:15 blur:2.5". Throws like parse_perturbation.
std::vector<Perturbation> parse_perturbation_list(const std::string& specs, std::uint64_t seed = 1);

// A polygon in full-size frame coordinates mapped into the tracker's (possibly scaled) frame, and
// back. Pixel centres map to pixel centres: x' = (x + 0.5) s - 0.5.
Polygon scale_polygon_to_frame(const Polygon& polygon, double scale);
Polygon scale_polygon_from_frame(const Polygon& polygon, double scale);

}  // namespace scbt
