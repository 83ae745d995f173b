#include "scbt/depth/depth_window.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace scbt {
namespace {

template <typename T>
void collect_valid_depths(const cv::Mat& depth, const BoundarySample& sample,
                          const DepthOptions& options, double scale, std::vector<DepthPixel>* out) {
  const Point tangent(-sample.inward.y, sample.inward.x);
  for (int k = 0; k < options.window_length; ++k) {
    const Point centre = sample.pixel + sample.inward * (options.window_offset + k);
    for (int j = -options.window_half_width; j <= options.window_half_width; ++j) {
      const Point p = centre + tangent * static_cast<double>(j);
      const int x = cvRound(p.x), y = cvRound(p.y);
      if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) continue;
      const double z = static_cast<double>(depth.ptr<T>(y)[x]) * scale;
      if (z >= options.min_depth && z <= options.max_depth)
        out->push_back({z, static_cast<float>(x), static_cast<float>(y), k});
    }
  }
}

// Median depth of the sorted range [first, last).
double median_of_sorted(const DepthPixel* first, const DepthPixel* last) {
  const std::ptrdiff_t n = last - first;
  return n % 2 ? first[n / 2].z : 0.5 * (first[n / 2 - 1].z + first[n / 2].z);
}

const DepthPixel* lower(const DepthPixel* first, const DepthPixel* last, double z) {
  return std::lower_bound(first, last, DepthPixel{z, 0.f, 0.f, 0});
}

const DepthPixel* upper(const DepthPixel* first, const DepthPixel* last, double z) {
  return std::upper_bound(first, last, DepthPixel{z, 0.f, 0.f, 0});
}

}  // namespace

double surface_tolerance(const DepthOptions& options, double z) {
  return std::max(options.tolerance_floor, options.outlier_sigmas * options.noise_at_1m * z * z);
}

SurfaceDepth nearest_surface_depth(const cv::Mat& depth, const BoundarySample& sample,
                                   const DepthOptions& options, std::vector<DepthPixel>* scratch) {
  scratch->clear();
  if (depth.type() == CV_16UC1)
    collect_valid_depths<std::uint16_t>(depth, sample, options, options.depth_scale, scratch);
  else
    collect_valid_depths<float>(depth, sample, options, 1.0, scratch);
  std::vector<DepthPixel>& z = *scratch;
  const std::size_t needed = static_cast<std::size_t>(options.min_surface_pixels);
  SurfaceDepth surface;
  if (z.size() < needed) return surface;
  std::sort(z.begin(), z.end());
  const DepthPixel* begin = z.data();
  const DepthPixel* end = z.data() + z.size();
  for (std::size_t i = 0; i + needed <= z.size(); ++i) {
    // The nearest run of `needed` depths within the tolerance is the nearest surface; the
    // depths within the tolerance of its median are its pixels.
    const double tolerance = surface_tolerance(options, z[i].z);
    if (z[i + needed - 1].z - z[i].z > tolerance) continue;
    const double centre = median_of_sorted(begin + i, upper(begin + i, end, z[i].z + tolerance));
    const DepthPixel* lo = lower(begin, end, centre - tolerance);
    const DepthPixel* hi = upper(begin, end, centre + tolerance);
    std::array<double, kMaxWindowRows> count{};
    for (const DepthPixel* p = lo; p != hi; ++p) {
      RowDepth& row = surface.rows[p->row];
      row.z += p->z, row.pixel.x += p->x, row.pixel.y += p->y, count[p->row] += 1.0;
    }
    surface.first_row = -1;
    for (int k = 0; k < options.window_length; ++k) {
      if (count[k] == 0.0) continue;
      RowDepth& row = surface.rows[k];
      row.z /= count[k], row.pixel.x /= count[k], row.pixel.y /= count[k];
      if (surface.first_row < 0) surface.first_row = k;
    }
    surface.z = surface.rows[surface.first_row].z;
    surface.pixel = surface.rows[surface.first_row].pixel;
    return surface;
  }
  return surface;
}

}  // namespace scbt
