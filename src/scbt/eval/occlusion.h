// Seeded occluders drawn over a sequence, to measure tracking through partial occlusion: a bar (a
// bottle, a gripper's finger), a disc or a hand-like blob, one colour or textured, passing over the
// object at several positions of the sequence. Each event hides about `cover` of the object's
// outline at its worst (sized on the ground-truth outline of the event's middle frame; the
// occluder grows and shrinks with the object, so an approaching camera does not change how much
// it hides) and lasts `seconds`; between events the object is in plain view for 2-5 s, so that each
// event also measures how fast tracking comes back.
//
// Spec (the part after "occlude:" in a perturbation spec, eval/perturb.h):
//   COVER[,SECONDS[,SHAPE[,MOTION[,FILL]]]]
//   COVER    fraction of the outline hidden at the event's worst frame, 0.05..0.8
//   SECONDS  length of each event at 30 fps (default 2), 0.1..10
//   SHAPE    bar (default), disc or hand
//   MOTION   sweep (default: enters on one side, crosses the object, leaves on the other) or
//            stay (enters, stays still over the object for half the event, leaves the way it came)
//   FILL     solid (default: one colour) or textured
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

enum class OccluderShape { kBar, kDisc, kHand };
enum class OccluderMotion { kSweep, kStay };

struct OcclusionSpec {
  double cover = 0.3;
  double seconds = 2.0;
  OccluderShape shape = OccluderShape::kBar;
  OccluderMotion motion = OccluderMotion::kSweep;
  bool textured = false;

  // "0.3,2,bar,sweep,solid": parses back to this spec.
  std::string name() const;
  // Throws std::invalid_argument naming the bad value.
  void check() const;
};

// Parses the part after "occlude:". Throws std::invalid_argument with the grammar.
OcclusionSpec parse_occlusion_spec(const std::string& text);

// One pass of an occluder over the object.
struct OcclusionEvent {
  int start = 0;           // 0-based frame index of the first occluded frame
  int length = 0;          // frames
  double direction = 0.0;  // radians: the way the occluder moves (sweep) or comes in (stay)
  // Bar width, disc radius or hand scale and (stay) where it stops along `direction` from the
  // object's centre, in pixels of the frame whose truth has scale `scale` (the square root of its
  // area); other frames scale both with their truth.
  double size = 0.0;
  double stay_offset = 0.0;
  double scale = 0.0;
  cv::Scalar colour;
  std::uint64_t texture_seed = 0;
  int end() const { return start + length; }
};

class OcclusionPlan {
 public:
  OcclusionPlan() = default;
  // Events over a sequence whose ground truth is `truth` (one polygon per frame), placed by
  // `seed`. Frames with an unusable truth polygon are left unoccluded.
  OcclusionPlan(const OcclusionSpec& spec, const std::vector<Polygon>& truth, std::uint64_t seed);

  // Draws frame `index`'s occluder (if any) over `frame` (8-bit, 1, 3 or 4 channels), placed
  // relative to that frame's truth polygon.
  void draw(int index, cv::Mat* frame) const;
  // The event covering frame `index`, or nullptr.
  const OcclusionEvent* event_at(int index) const;
  const std::vector<OcclusionEvent>& events() const { return events_; }
  // The fraction of truth polygon `index`'s outline the occluder hides in that frame (0 outside
  // events).
  double hidden_fraction(int index) const;

 private:
  // The occluder's outline as polygons (their union is the occluder) in frame `index`.
  std::vector<Polygon> occluder_parts(const OcclusionEvent& event, int index) const;
  // The occluder's reference point in frame `index` (its leading end, or its centre).
  Point occluder_point(const OcclusionEvent& event, int index) const;
  // `event` with its size and stay offset scaled to frame `index`'s truth.
  OcclusionEvent scaled_to(const OcclusionEvent& event, int index) const;

  OcclusionSpec spec_;
  std::vector<Polygon> truth_;
  std::vector<OcclusionEvent> events_;
};

// The fraction of `outline`'s length inside the union of `parts` (sampled every ~2 px).
double hidden_outline_fraction(const Polygon& outline, const std::vector<Polygon>& parts);

}  // namespace scbt
