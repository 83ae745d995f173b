#include "scbt/tracker/motion_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scbt {

Point area_centroid(const Polygon& polygon) {
  double a2 = 0.0;
  Point sum(0.0, 0.0);
  Point mean(0.0, 0.0);
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& p = polygon[i];
    const Point& q = polygon[(i + 1) % n];
    const double cross = p.x * q.y - q.x * p.y;
    a2 += cross;
    sum += (p + q) * cross;
    mean += p;
  }
  if (n == 0) return mean;
  if (std::abs(a2) < 1e-9) return mean * (1.0 / static_cast<double>(n));
  return sum * (1.0 / (3.0 * a2));
}

void MotionModel::reset() {
  has_last_ = false;
  velocity_ = Point(0.0, 0.0);
  log_area_rate_ = 0.0;
  frames_since_last_ = 1;
  num_rates_ = 0;
}

void MotionModel::update(const Polygon& tracked) {
  const Point centroid = area_centroid(tracked);
  const double log_area = std::log(std::max(area(tracked), 1e-9));
  if (has_last_) {
    velocity_ = (centroid - last_centroid_) * (1.0 / frames_since_last_);
    log_area_rate_ = (log_area - last_log_area_) / frames_since_last_;
    recent_rates_[num_rates_ % kSustainedSteps] = log_area_rate_;
    ++num_rates_;
  }
  last_centroid_ = centroid;
  last_log_area_ = log_area;
  has_last_ = true;
  frames_since_last_ = 1;
}

void MotionModel::update_held() { ++frames_since_last_; }

double MotionModel::predicted_area_ratio() const {
  return std::exp(log_area_rate_ * frames_since_last_);
}

double MotionModel::sustained_shrink_ratio() const {
  if (num_rates_ < kSustainedSteps) return 1.0;
  double slowest = -std::numeric_limits<double>::infinity();
  for (double rate : recent_rates_) {
    if (!(rate < 0.0)) return 1.0;
    slowest = std::max(slowest, rate);
  }
  return std::exp(slowest * frames_since_last_);
}

void MotionModel::predict(const Polygon& last, bool with_scale, Polygon* predicted) const {
  const Point centroid = area_centroid(last);
  const Point target = centroid + velocity_ * frames_since_last_;
  // Area scales with the square of the linear size.
  const double scale = with_scale ? std::sqrt(predicted_area_ratio()) : 1.0;
  predicted->resize(last.size());
  for (size_t i = 0; i < last.size(); ++i) {
    (*predicted)[i] = target + (last[i] - centroid) * scale;
  }
}

}  // namespace scbt
