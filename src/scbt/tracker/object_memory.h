// What the tracker remembers of the object beyond the last boundary: its outline as a fixed
// number of points, each with the polarity, contrast and side levels of the edge it had there.
// Confident frames whose boundary agrees with it move it by an affine map (place and view),
// refresh the edges and, when all of it is seen, move its shape a little towards theirs; a
// boundary that departs from it along the object's own edges restarts it (a new view). Each frame
// the remembered outline is fitted to the image (each point looks along its normal for an edge of
// its own polarity; an affine map is fitted to the points that found one, robustly),
// from its last place or, when that fails, from places around it (search()), which gives
//  - where the object is even when part of it is hidden: the fitted outline, hidden part
//    predicted from the visible one;
//  - how much of it is visible: the fraction of points whose edge was found where the fit puts
//    them;
//  - whether a cycle the grouping chose is the object: a cycle that swaps part of the outline
//    for edges the object never had (an occluder's side, a sheet behind it, a container's
//    inside) lies away from the fitted outline along that part.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct ObjectMemoryOptions {
  int points = 64;          // outline samples
  double search_px = 12.0;  // how far along its normal each point looks for its edge
  double min_step = 6.0;    // the smallest grey step counted as an edge (central difference)
  // A point is visible when its edge lies within this of where the fit puts it (px).
  double inlier_px = 2.5;
};

struct MemoryFit {
  bool valid = false;    // a fit was made (the memory holds an outline and enough points matched)
  Polygon outline;       // the remembered outline placed in this frame
  double visible = 0.0;  // fraction of the outline whose edge was found where the fit puts it
};

class ObjectMemory {
 public:
  explicit ObjectMemory(const ObjectMemoryOptions& options = {}) : options_(options) {}

  void clear();
  bool ready() const { return !anchor_model_.empty(); }
  // Forgets everything and remembers `boundary`: its outline becomes the anchor whose affine
  // images the memory holds from then on (remember()).
  void restart(const Polygon& boundary, const cv::Mat& gray, cv::Point tl);
  // Learns from `boundary`, tracked confidently in the grey window `gray` (whose top-left corner
  // is `tl` in the frame): the remembered outline is the anchor's mapped onto it by an affine map
  // (its place and view, not its shape), and each point whose edge is clear there takes that
  // edge's polarity, contrast and side levels. With `shape_rate` > 0 the outline's shape also
  // moves that fraction of the way onto the boundary (a slow change of view is followed; a few
  // frames of a boundary cut short by an occluder are not). The first call restarts.
  void remember(const Polygon& boundary, const cv::Mat& gray, cv::Point tl,
                double shape_rate = 0.0);
  // Moves the remembered outline onto `boundary`, found far from where it was last placed (the
  // object found again), by the robust affine map of mapped_onto(), keeping its shape, and reads
  // the edges there as remember() does.
  void place_onto(const Polygon& boundary, const cv::Mat& gray, cv::Point tl);
  // Fits the remembered outline from starting places on a grid up to `radius` px around where it
  // was last placed (the last place included) and returns the fit that sees most of it: the
  // object found again when the last place went wrong. It becomes the new place only when it sees
  // at least `accept_visible` of the outline (a poor fit elsewhere must not carry the memory off);
  // otherwise the place stays and the returned fit is not valid.
  MemoryFit search(const cv::Mat& gray, cv::Point tl, double radius, double accept_visible);
  // Fits the remembered outline to the grey window, starting from where it was last placed.
  MemoryFit fit(const cv::Mat& gray, cv::Point tl);
  // The remembered outline mapped onto `outline` (a boundary found elsewhere) and fitted there,
  // the memory itself unchanged: how much of the remembered object is seen where `outline` says
  // it is.
  MemoryFit fit_at(const Polygon& outline, const cv::Mat& gray, cv::Point tl) const;
  // The remembered outline mapped onto `outline` by an affine map (robustly: a part of `outline`
  // away from the rest of the map does not drag it), without looking at the image; empty when it
  // cannot be placed. `outline` runs along it when it is the object seen from another view.
  Polygon mapped_onto(const Polygon& outline) const;
  // Places the remembered outline at `fitted`, a fit of it made elsewhere (fit_at()), held to the
  // view found there.
  void place_at(const Polygon& fitted) { placed_ = learnt_ = fitted; }
  // Where the outline was last placed (the last fit, or the last remembered boundary).
  const Polygon& placed() const { return placed_; }

  // Of `cycle`'s points farther than `distance` from `fitted` (the last fit's outline), the
  // fraction with an edge across the cycle like the one the memory had nearest them: its
  // polarity, its contrast and the grey levels on either side (1 when none is that far). A cycle
  // departing along the object's own edge follows a change of the object's shape; one departing
  // along an occluder or the background does not.
  double departure_support(const Polygon& cycle, const Polygon& fitted, double distance,
                           const cv::Mat& gray, cv::Point tl) const;
  // The fraction of the memory's points (those with a clear edge) whose own edge (polarity,
  // contrast, side levels) `cycle` runs along within `distance` of where `fitted` (the last fit's
  // outline) puts them: near 1 when the cycle is the object seen from a view the remembered
  // outline cannot be moved onto; an occluder's side or a leak into the background leaves the
  // hidden or bypassed part unexplained.
  double explained_by(const Polygon& cycle, const Polygon& fitted, double distance,
                      const cv::Mat& gray, cv::Point tl) const;
  // The fraction of `outline`'s points (as resampled by the memory) farther than `distance`
  // from `other`, and the same the other way round: the larger of the two.
  double mismatch(const Polygon& outline, const Polygon& other, double distance) const;

 private:
  ObjectMemoryOptions options_;
  // Whether the grey levels either side of `p` (across `normal`) are those memory point `point`
  // had: the object inside, its surroundings outside (true when either is unknown).
  bool sides_match(const cv::Mat& gray, cv::Point tl, Point p, Point normal, size_t point) const;
  // The least step that counts as memory point `point`'s edge.
  double edge_need(size_t point) const;
  // Whether memory point `point`'s own edge crosses `normal` within a pixel of `p`: its polarity
  // (either, if it had no clear edge), at least edge_need(), the remembered levels either side.
  bool own_edge_near(size_t point, const cv::Mat& gray, cv::Point tl, Point p, Point normal) const;
  // Maps the anchor onto `boundary` by an affine map fitted to its closest points, starting from
  // *mapped and written there; false when the fit is singular.
  bool map_anchor_onto(const Polygon& boundary, Polygon* mapped) const;
  // Reads each point's edge at placed_ in the grey window (points without a clear one keep theirs).
  void read_edges(const cv::Mat& gray, cv::Point tl);
  std::vector<double> polarity_;  // +1: brighter outside, -1: darker outside, 0: no clear edge
  std::vector<double> contrast_;  // |step| at the point when remembered
  // Grey levels a few pixels inside and outside the outline at the point: what the object's own
  // edge has on either side (an occluder's side or a background sheet has other levels).
  std::vector<double> inside_;
  std::vector<double> outside_;
  Polygon anchor_model_;  // the outline restart() was given (resampled), or the shape learnt since
  Polygon placed_;        // the outline where it was last learnt or fitted
  Polygon learnt_;        // the outline where a boundary was last learnt (restart, remember)
};

// How near a boundary must run to an outline to agree with it there: a twentieth of the
// outline's size, at least 3 px.
double agreement_distance(const Polygon& outline);

// `polygon` resampled to `n` points evenly spaced along its length, from its first vertex.
Polygon resample_outline(const Polygon& polygon, int n);

}  // namespace scbt
