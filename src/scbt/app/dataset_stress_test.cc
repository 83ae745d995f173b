// Camera stress and loss on real video, fast: a window of kFrames frames of each dataset sequence
// (the one holding most of its frames that fail under these conditions over the whole sequence),
// tracked by the default tracker from the true outline of its first frame, under the camera
// conditions of eval/perturb.h (frame stride, noise, blur, low light, JPEG, downscale) and with an
// object gap (eval/sequence_gap.h: 30 grey frames, or 60 frames dropped) at two positions. Every
// condition's tracker is fed from the same decoded frame. Each condition has its own limits per
// sequence: success at 10 px and at 5 px over the frames it shows the tracker (a perturbation;
// noise seeded as `scbt eval --perturb` seeds it, by the frame's number in the sequence), or the
// re-acquisition delay and the success at 10 px from then on (a gap). The limits are the figures
// measured on this code, printed by every run, with the margins stated at the table; a crossed
// limit prints the frames over it. One ctest entry per sequence. Missing dataset: skipped, failed
// under CI=true (ci_requirement.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "scbt/app/ci_requirement.h"
#include "scbt/app/eval_jobs.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/perturb.h"
#include "scbt/eval/sequence_gap.h"
#include "scbt/io/frame_source.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr int kFrames = 300;

// The window of each sequence: its first frame (1-based). Over whole sequences these conditions
// fail mostly near BookStand's end, Bowl's frames 90-135, MarkCup's last 110 frames,
// MarkCupContour's frames 180-200, ToolBox's frames 850-970 and TransparentCup's end.
const std::map<std::string, int>& windows() {
  static const std::map<std::string, int> first = {{"BookStand", 600}, {"Bowl", 1},
                                                   {"MarkCup", 560},   {"MarkCupContour", 1},
                                                   {"ToolBox", 750},   {"TransparentCup", 752}};
  return first;
}

// One tracker's input: the frames degraded by `perturbation`, or with `gap` taken out (its
// indices 0-based in the window).
struct Condition {
  std::string name;
  Perturbation perturbation;
  SequenceGap gap;
};

std::vector<Condition> conditions() {
  std::vector<Condition> list;
  for (const char* spec : {"none", "stride:2", "stride:3", "noise:15", "blur:2.5", "lowlight:0.3",
                           "jpeg:15", "downscale:2"}) {
    list.push_back({spec, parse_perturbation(spec), SequenceGap()});
  }
  for (int start : {120, 180}) {
    list.push_back({"grey30@" + std::to_string(start), Perturbation(),
                    SequenceGap{GapVariantKind::kGrey, start, 30}});
    list.push_back({"jump60@" + std::to_string(start), Perturbation(),
                    SequenceGap{GapVariantKind::kDrop, start, 60}});
  }
  return list;
}

// The tracker's first outline: the ground truth (whose lines repeat vertices, each one twice on
// some sequences) with every vertex once, in the tracker's frame.
Polygon initial_outline(const Polygon& truth, double scale, cv::Size size) {
  Polygon outline;
  for (Point p : scale_polygon_to_frame(truth, scale)) {
    p.x = std::clamp(p.x, 0.0, static_cast<double>(size.width));
    p.y = std::clamp(p.y, 0.0, static_cast<double>(size.height));
    if (std::none_of(outline.begin(), outline.end(),
                     [&](const Point& q) { return q.x == p.x && q.y == p.y; })) {
      outline.push_back(p);
    }
  }
  return outline;
}

// Tracks the window of `sequence` that starts at frame `first` (1-based) under every condition,
// in one decoding pass. Result c: condition c's tracked frames, LossFrame::index 0-based in the
// window (a grey gap frame has e_al -1).
std::vector<std::vector<LossFrame>> run_conditions(const DatasetSequence& sequence, int first,
                                                   const std::vector<Condition>& list) {
  const std::vector<Polygon> truth = load_truth(sequence, 0);  // as `scbt eval` reads it
  const std::vector<std::string> files = list_numbered_images(sequence.frames);
  const int frames = std::min<int>({kFrames, static_cast<int>(truth.size()) - (first - 1),
                                    static_cast<int>(files.size()) - (first - 1)});
  std::unique_ptr<FrameSource> source = open_image_list_source(
      std::vector<std::string>(files.begin() + (first - 1), files.begin() + (first - 1) + frames));
  std::vector<Tracker> trackers;
  for (size_t c = 0; c < list.size(); ++c) trackers.emplace_back(TrackerOptions{});
  std::vector<std::vector<LossFrame>> runs(list.size());
  cv::Mat frame, degraded;
  for (int k = 0; k < frames; ++k) {
    const int number = first + k;  // 1-based in the sequence
    if (!source->read(&frame)) {
      ADD_FAILURE() << sequence.name << ": frame " << number << " unreadable";
      break;
    }
    for (size_t c = 0; c < list.size(); ++c) {
      const Perturbation& p = list[c].perturbation;
      const SequenceGap& gap = list[c].gap;
      if (k % p.frame_stride() != 0 || gap.dropped(k)) continue;
      if (gap.in_gap(k)) {
        degraded = frame.clone();
        gap.apply(k, &degraded);
      } else {
        p.apply(frame, number, &degraded);
      }
      if (k == 0) {
        trackers[c].init(degraded, initial_outline(truth[number - 1], p.scale(), degraded.size()));
        continue;
      }
      const TrackResult r = trackers[c].track(degraded);
      const double e_al = gap.in_gap(k)
                              ? -1.0
                              : alignment_error(scale_polygon_from_frame(r.boundary, p.scale()),
                                                truth[number - 1], frame.size());
      runs[c].push_back({k, e_al, r.confidence, r.state == TrackState::kTracking});
    }
  }
  return runs;
}

// A perturbation's limits: success at 10 px and at 5 px over the frames it shows the tracker.
// A gap's: re-acquisition within `delay` frames of the gap's end, then success at 10 px from the
// re-acquired frame on of at least `success_10` (success_5 unused).
struct Limits {
  double success_10 = 0.0;
  double success_5 = 0.0;
  int delay = 0;
};

// Measured (comments: S@10 S@5, seeds 1/2/3 for the noisy conditions; a gap's delay and S@10
// after, of how many frames) and the limits: a perturbation's floors let 3 more frames reach
// 10 px and 6 more reach 5 px than the worst measured seed; a gap's delay may double plus 5
// frames, and 3 more frames after re-acquisition may reach 10 px. A build repeats its figures
// exactly; the margin is for another machine's floating point (a frame or two at a threshold).
// Bistable entries, which flip between the low and the high figure with the noise seed, have
// their floor below the low one: ToolBox lowlight:0.3 (seed 1 loses the box near frame 900 for
// the rest of the window) and MarkCup noise:15. ToolBox's window is the hardest: its stride,
// low-light and JPEG conditions lose the box near frame 900 (the low figures), the gaps there are
// slow to re-acquire (17 and 11 frames); a gap at 150 instead of 120 turns BookStand's jump into
// a loss, at 60 Bowl's, so the gap positions 120 and 180 are where all six re-acquire.
const std::map<std::string, std::map<std::string, Limits>>& limits() {
  static const std::map<std::string, std::map<std::string, Limits>> table = {
      {"BookStand",
       {
           {"none", {0.986, 0.959}},          // 0.997 0.980
           {"stride:2", {0.959, 0.932}},      // 0.980 0.973
           {"stride:3", {0.969, 0.929}},      // 1.000 0.990
           {"noise:15", {0.979, 0.949}},      // 0.990/0.990/0.990 0.990/0.980/0.970
           {"blur:2.5", {0.986, 0.973}},      // 0.997 0.993
           {"lowlight:0.3", {0.966, 0.923}},  // 0.983/0.977/0.987 0.943/0.947/0.963
           {"jpeg:15", {0.983, 0.936}},       // 0.993 0.957
           {"downscale:2", {0.976, 0.963}},   // 0.987 0.983
           {"grey30@120", {0.973, 0.0, 7}},   // delay 1, 0.993 of 149
           {"jump60@120", {0.965, 0.0, 13}},  // delay 4, 0.991 of 116
           {"grey30@180", {0.955, 0.0, 7}},   // delay 1, 0.989 of 89
           {"jump60@180", {0.925, 0.0, 17}},  // delay 6, 0.982 of 54
       }},
      {"Bowl",
       {
           {"none", {0.989, 0.979}},          // 1.000 1.000
           {"stride:2", {0.979, 0.959}},      // 1.000 1.000
           {"stride:3", {0.818, 0.787}},      // 0.849 0.849
           {"noise:15", {0.989, 0.979}},      // 1.000/1.000/1.000 1.000/1.000/1.000
           {"blur:2.5", {0.989, 0.979}},      // 1.000 1.000
           {"lowlight:0.3", {0.989, 0.979}},  // 1.000/1.000/1.000 1.000/1.000/1.000
           {"jpeg:15", {0.989, 0.979}},       // 1.000 1.000
           {"downscale:2", {0.989, 0.979}},   // 1.000 1.000
           {"grey30@120", {0.979, 0.0, 7}},   // delay 1, 1.000 of 149
           {"jump60@120", {0.974, 0.0, 13}},  // delay 4, 1.000 of 116
           {"grey30@180", {0.966, 0.0, 7}},   // delay 1, 1.000 of 89
           {"jump60@180", {0.95, 0.0, 5}},    // delay 0, 1.000 of 60
       }},
      {"MarkCup",
       {
           {"none", {0.986, 0.926}},          // 0.997 0.947
           {"stride:2", {0.973, 0.865}},      // 0.993 0.906
           {"stride:3", {0.626, 0.575}},      // 0.657 0.636
           {"noise:15", {0.919, 0.909}},      // 0.930/0.973/1.000 0.930/0.970/0.997
           {"blur:2.5", {0.919, 0.909}},      // 0.930 0.930
           {"lowlight:0.3", {0.969, 0.949}},  // 0.993/0.980/0.983 0.970/0.980/0.977
           {"jpeg:15", {0.983, 0.953}},       // 0.993 0.973
           {"downscale:2", {0.986, 0.939}},   // 0.997 0.960
           {"grey30@120", {0.973, 0.0, 7}},   // delay 1, 0.993 of 149
           {"jump60@120", {0.965, 0.0, 13}},  // delay 4, 0.991 of 116
           {"grey30@180", {0.955, 0.0, 7}},   // delay 1, 0.989 of 89
           {"jump60@180", {0.921, 0.0, 23}},  // delay 9, 0.980 of 51
       }},
      {"MarkCupContour",
       {
           {"none", {0.989, 0.979}},          // 1.000 1.000
           {"stride:2", {0.979, 0.959}},      // 1.000 1.000
           {"stride:3", {0.969, 0.939}},      // 1.000 1.000
           {"noise:15", {0.989, 0.979}},      // 1.000/1.000/1.000 1.000/1.000/1.000
           {"blur:2.5", {0.989, 0.979}},      // 1.000 1.000
           {"lowlight:0.3", {0.989, 0.979}},  // 1.000/1.000/1.000 1.000/1.000/1.000
           {"jpeg:15", {0.989, 0.979}},       // 1.000 1.000
           {"downscale:2", {0.983, 0.749}},   // 0.993 0.769
           {"grey30@120", {0.979, 0.0, 7}},   // delay 1, 1.000 of 149
           {"jump60@120", {0.973, 0.0, 15}},  // delay 5, 1.000 of 115
           {"grey30@180", {0.966, 0.0, 7}},   // delay 1, 1.000 of 89
           {"jump60@180", {0.948, 0.0, 9}},   // delay 2, 1.000 of 58
       }},
      {"ToolBox",
       {
           {"none", {0.986, 0.943}},          // 0.997 0.963
           {"stride:2", {0.59, 0.469}},       // 0.611 0.510
           {"stride:3", {0.666, 0.474}},      // 0.697 0.535
           {"noise:15", {0.989, 0.959}},      // 1.000/1.000/1.000 1.000/0.980/0.997
           {"blur:2.5", {0.989, 0.966}},      // 1.000 0.987
           {"lowlight:0.3", {0.484, 0.458}},  // 0.495/0.997/0.973 0.478/0.980/0.950
           {"jpeg:15", {0.484, 0.461}},       // 0.495 0.482
           {"downscale:2", {0.943, 0.916}},   // 0.953 0.936
           {"grey30@120", {0.977, 0.0, 39}},  // delay 17, 1.000 of 133
           {"jump60@120", {0.972, 0.0, 27}},  // delay 11, 1.000 of 109
           {"grey30@180", {0.966, 0.0, 7}},   // delay 1, 1.000 of 89
           {"jump60@180", {0.944, 0.0, 17}},  // delay 6, 1.000 of 54
       }},
      {"TransparentCup",
       {
           {"none", {0.989, 0.979}},          // 1.000 1.000
           {"stride:2", {0.979, 0.953}},      // 1.000 0.993
           {"stride:3", {0.878, 0.808}},      // 0.909 0.869
           {"noise:15", {0.989, 0.979}},      // 1.000/1.000/1.000 1.000/1.000/1.000
           {"blur:2.5", {0.989, 0.979}},      // 1.000 1.000
           {"lowlight:0.3", {0.989, 0.976}},  // 1.000/1.000/1.000 1.000/0.997/1.000
           {"jpeg:15", {0.989, 0.969}},       // 1.000 0.990
           {"downscale:2", {0.989, 0.979}},   // 1.000 1.000
           {"grey30@120", {0.979, 0.0, 7}},   // delay 1, 1.000 of 149
           {"jump60@120", {0.974, 0.0, 13}},  // delay 4, 1.000 of 116
           {"grey30@180", {0.966, 0.0, 7}},   // delay 1, 1.000 of 89
           {"jump60@180", {0.946, 0.0, 13}},  // delay 4, 1.000 of 56
       }},
  };
  return table;
}

// " frame (E_AL)" of the frames at or over `threshold` (numbered 1-based in the sequence), of a
// gap condition those after the gap.
std::string frames_over(const std::vector<LossFrame>& frames, const SequenceGap& gap, int first,
                        double threshold) {
  std::ostringstream list;
  int n = 0;
  for (const LossFrame& f : frames) {
    if ((gap.kind != GapVariantKind::kNone && f.index < gap.end()) || f.e_al < threshold) continue;
    if (n++ < 60) list << ' ' << first + f.index << " (" << f.e_al << ')';
  }
  if (n > 60) list << " ... " << n << " in all";
  return n == 0 ? " none" : list.str();
}

double rate(const std::vector<LossFrame>& frames, double threshold) {
  std::vector<double> errors;
  for (const LossFrame& f : frames) errors.push_back(f.e_al);
  return success_rate(errors, threshold);
}

class DatasetStress : public testing::TestWithParam<std::string> {};

TEST_P(DatasetStress, ConditionsStayWithinLimits) {
  SCBT_REQUIRE_DATASET(dataset);
  const std::string name = GetParam();
  const DatasetSequence sequence = select_dataset_sequences(dataset, {name}).at(0);
  const int first = windows().at(name);
  const std::vector<Condition> list = conditions();
  const std::vector<std::vector<LossFrame>> runs = run_conditions(sequence, first, list);
  const std::map<std::string, Limits>& sequence_limits = limits().at(name);
  for (size_t c = 0; c < list.size(); ++c) {
    const Condition& condition = list[c];
    const std::vector<LossFrame>& frames = runs[c];
    const char* label = condition.name.c_str();
    const auto limit = sequence_limits.find(condition.name);
    const bool has_limits = limit != sequence_limits.end();
    const Limits l = has_limits ? limit->second : Limits{};
    if (condition.gap.kind == GapVariantKind::kNone) {
      const double s10 = rate(frames, 10.0), s5 = rate(frames, 5.0);
      std::printf("%s %-13s S@10 %.4f S@5 %.4f (%zu frames from %d); floors %.3f %.3f\n",
                  name.c_str(), label, s10, s5, frames.size(), first, l.success_10, l.success_5);
      if (!has_limits) continue;
      EXPECT_GE(s10, l.success_10) << name << " " << label << ": E_AL >= 10 px on"
                                   << frames_over(frames, condition.gap, first, 10.0);
      EXPECT_GE(s5, l.success_5) << name << " " << label << ": E_AL >= 5 px on"
                                 << frames_over(frames, condition.gap, first, 5.0);
    } else {
      const LossScores scores = score_loss(frames, condition.gap, 10.0);
      const double after = scores.success_after.value_or(0.0);
      std::printf("%s %-13s delay %d, S@10 after %.4f (%d frames); limits <= %d, %.3f\n",
                  name.c_str(), label, scores.reacquire_delay, after, scores.after, l.delay,
                  l.success_10);
      if (!has_limits) continue;
      EXPECT_GE(scores.reacquire_delay, 0) << name << " " << label << ": never re-acquired";
      EXPECT_LE(scores.reacquire_delay, l.delay) << name << " " << label;
      EXPECT_GE(after, l.success_10) << name << " " << label << ": E_AL >= 10 px after the gap on"
                                     << frames_over(frames, condition.gap, first, 10.0);
    }
  }
  for (const Condition& condition : list) {
    EXPECT_TRUE(sequence_limits.count(condition.name))
        << name << " " << condition.name << " has no limits";
  }
}

INSTANTIATE_TEST_SUITE_P(Sequences, DatasetStress,
                         testing::Values("BookStand", "Bowl", "MarkCup", "MarkCupContour",
                                         "ToolBox", "TransparentCup"));

}  // namespace
}  // namespace scbt
