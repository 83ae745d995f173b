// Accuracy of the bdsp tracker on the dataset under camera-like perturbations (eval/perturb.h),
// for measuring robustness quickly: each sequence is decoded once and every perturbation's
// tracker is fed from the same decoded frame. Prints per perturbation the pooled success at 5 /
// 10 / 20 px, per-sequence success at 10 px and the mean tracking time per frame.
//
//   perturb_sweep --dataset DIR [--perturb "none stride:2 noise:15 ..."] [--sequences A,B]
//                 [--jobs N] [--frames-csv FILE] [tracker options as scbt eval]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>
#include <utility>

#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/perturb.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/frame_source.h"
#include "scbt/tracker/tracker.h"

namespace {

struct FrameScore {
  int frame = 0;
  double e_al = 0.0;
  bool held = false;
  double ms = 0.0;
  scbt::TrackState state = scbt::TrackState::kTracking;
  double confidence = 0.0;
  double gap_share = 0.0;
  double edge_support = 0.0;
  double shape_change = 0.0;
};

// Keeps a scaled polygon inside the frame the tracker sees.
scbt::Polygon clamp_to_frame(scbt::Polygon polygon, cv::Size size) {
  for (scbt::Point& p : polygon) {
    p.x = std::clamp(p.x, 0.0, static_cast<double>(size.width));
    p.y = std::clamp(p.y, 0.0, static_cast<double>(size.height));
  }
  return polygon;
}

std::vector<scbt::Polygon> load_truth(const std::string& path) {
  std::vector<scbt::Polygon> truth;
  for (const std::string& line : scbt::read_text_lines(path)) {
    scbt::Polygon p;
    std::string error;
    if (!scbt::try_parse_polygon_line(line, &p, &error)) break;
    truth.push_back(p);
  }
  return truth;
}

// Runs every perturbation's tracker over one sequence; scores[c] gets perturbation c's frames.
void run_sequence(const scbt::DatasetSequence& sequence,
                  const std::vector<scbt::Perturbation>& perturbations,
                  const scbt::TrackerOptions& options, int max_frames,
                  std::vector<std::vector<FrameScore>>* scores) {
  const std::vector<scbt::Polygon> truth = load_truth(sequence.ground_truth);
  std::unique_ptr<scbt::FrameSource> source = scbt::open_frame_source(sequence.frames);
  std::vector<scbt::Tracker> trackers;
  for (size_t c = 0; c < perturbations.size(); ++c) trackers.emplace_back(options);
  scores->assign(perturbations.size(), {});
  cv::Mat frame, degraded;
  for (int k = 1; k <= static_cast<int>(truth.size()); ++k) {
    if (max_frames > 0 && k > max_frames) break;
    if (!source->read(&frame)) break;
    for (size_t c = 0; c < perturbations.size(); ++c) {
      const scbt::Perturbation& p = perturbations[c];
      if ((k - 1) % p.frame_stride() != 0) continue;
      p.apply(frame, k, &degraded);
      if (k == 1) {
        trackers[c].init(degraded, clamp_to_frame(scbt::scale_polygon_to_frame(truth[0], p.scale()),
                                                  degraded.size()));
        continue;
      }
      const scbt::TrackResult r = trackers[c].track(degraded);
      FrameScore s;
      s.frame = k;
      s.held = r.held;
      s.ms = r.total_ms();
      s.state = r.state;
      s.confidence = r.confidence;
      s.gap_share = r.evidence.gap_share;
      s.edge_support = r.evidence.edge_support;
      s.shape_change = r.evidence.shape_change;
      s.e_al = scbt::alignment_error(scbt::scale_polygon_from_frame(r.boundary, p.scale()),
                                     truth[k - 1], frame.size());
      (*scores)[c].push_back(s);
    }
  }
}

double rate(const std::vector<const FrameScore*>& frames, double threshold) {
  if (frames.empty()) return 0.0;
  long n = 0;
  for (const FrameScore* f : frames) n += f->e_al < threshold;
  return static_cast<double>(n) / frames.size();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Tracking accuracy under camera-like perturbations");
  std::string dataset, perturb_list = "none", sequence_list, frames_csv;
  int jobs = 2, max_frames = 0;
  scbt::TrackerOptions options;
  app.add_option("--dataset", dataset, "dataset folder")->required();
  app.add_option("--perturb", perturb_list, "perturbation specs separated by ';' or spaces");
  app.add_option("--sequences", sequence_list, "comma-separated sequences (default all)");
  app.add_option("-j,--jobs", jobs, "parallel sequences");
  app.add_option("--max-frames", max_frames, "only the first N frames");
  app.add_option("--frames-csv", frames_csv, "write per-frame E_AL here");
  std::uint64_t perturb_seed = 1;
  app.add_option("--perturb-seed", perturb_seed, "seed of the noise perturbations");
  app.add_option("--gradient-threshold", options.detector.gradient_threshold);
  app.add_option("--anchor-threshold", options.detector.anchor_threshold);
  app.add_option("--filter-distance", options.filter_distance);
  app.add_option("--roi-padding", options.detector.roi_padding);
  app.add_option("--cost-tolerance", options.cost_tolerance);
  app.add_option("--similarity-exponent", options.similarity_exponent);
  app.add_option("--shape-weight", options.shape_weight);
  app.add_option("--recover-by-motion", options.recover_by_motion);
  app.add_option("--predict-motion", options.predict_motion);
  // Switches that act only with --predict-motion: off with it unless given.
  const std::pair<CLI::Option*, bool*> with_prediction[] = {
      {app.add_option("--confirm-motion", options.confirm_motion), &options.confirm_motion},
      {app.add_option("--measure-motion", options.measure_motion), &options.measure_motion},
      {app.add_option("--fall-back-unmoved", options.fall_back_unmoved),
       &options.fall_back_unmoved},
      {app.add_option("--gate-sustained-shrink", options.gate_sustained_shrink),
       &options.gate_sustained_shrink}};
  app.add_option("--smooth-noisy-frames", options.smooth_noisy_frames);
  app.add_option("--min-predicted-move", options.min_predicted_move);
  app.add_option("--min-motion-agreement", options.min_motion_agreement);
  app.add_option("--adaptive-thresholds", options.adaptive_thresholds.enabled);
  app.add_option("--normalize-exposure", options.exposure.normalize);
  app.add_option("--adapt-to-blur", options.blur.adapt);
  app.add_option("--full-contrast", options.exposure.full_contrast);
  app.add_option("--retry-weak-frames", options.adaptive_thresholds.retry_weak_frames);
  app.add_option("--keep-retry-winner", options.adaptive_thresholds.keep_retry_winner);
  app.add_option("--boundary-fraction", options.adaptive_thresholds.boundary_fraction);
  app.add_option("--noise-deviations", options.adaptive_thresholds.noise_deviations);
  app.add_option("--smooth-noise", options.adaptive_thresholds.smooth_noise);
  app.add_option("--smoothed-noise", options.adaptive_thresholds.smoothed_noise);
  app.add_option("--loss-handling", options.loss.enabled);
  CLI11_PARSE(app, argc, argv);
  for (const auto& [flag, value] : with_prediction) {
    if (!options.predict_motion && flag->count() == 0) *value = false;
  }
  try {
    options.check();
    const std::vector<scbt::Perturbation> perturbations =
        scbt::parse_perturbation_list(perturb_list, perturb_seed);
    std::vector<std::string> names;
    std::stringstream ss(sequence_list);
    for (std::string n; std::getline(ss, n, ',');) names.push_back(n);
    const std::vector<scbt::DatasetSequence> sequences =
        scbt::select_dataset_sequences(dataset, names);
    // scores[s][c]: sequence s, perturbation c.
    std::vector<std::vector<std::vector<FrameScore>>> scores(sequences.size());
    std::atomic<size_t> next{0};
    std::mutex log_mutex;
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(1, jobs); ++w) {
      workers.emplace_back([&]() {
        for (size_t s; (s = next++) < sequences.size();) {
          run_sequence(sequences[s], perturbations, options, max_frames, &scores[s]);
          std::lock_guard<std::mutex> lock(log_mutex);
          std::cerr << "done " << sequences[s].name << "\n";
        }
      });
    }
    for (std::thread& t : workers) t.join();

    std::printf("%-18s %6s %6s %6s %6s %6s", "perturbation", "S@5", "S@10", "S@20", "held", "ms");
    for (const auto& s : sequences) std::printf(" %8.8s", s.name.c_str());
    std::printf("\n");
    for (size_t c = 0; c < perturbations.size(); ++c) {
      std::vector<const FrameScore*> pooled;
      double ms = 0.0;
      long held = 0;
      for (size_t s = 0; s < sequences.size(); ++s) {
        for (const FrameScore& f : scores[s][c]) {
          pooled.push_back(&f);
          ms += f.ms;
          held += f.held;
        }
      }
      std::printf("%-18s %6.3f %6.3f %6.3f %6ld %6.3f", perturbations[c].name().c_str(),
                  rate(pooled, 5), rate(pooled, 10), rate(pooled, 20), held,
                  pooled.empty() ? 0.0 : ms / pooled.size());
      for (size_t s = 0; s < sequences.size(); ++s) {
        std::vector<const FrameScore*> frames;
        for (const FrameScore& f : scores[s][c]) frames.push_back(&f);
        std::printf(" %8.3f", rate(frames, 10));
      }
      std::printf("\n");
    }
    if (!frames_csv.empty()) {
      std::ofstream csv(frames_csv);
      csv << "perturbation,sequence,frame,e_al,held,ms,state,confidence,gap_share,edge_support,"
             "shape_change\n";
      for (size_t c = 0; c < perturbations.size(); ++c) {
        for (size_t s = 0; s < sequences.size(); ++s) {
          for (const FrameScore& f : scores[s][c]) {
            csv << perturbations[c].name() << ',' << sequences[s].name << ',' << f.frame << ','
                << f.e_al << ',' << f.held << ',' << f.ms << ',' << scbt::to_string(f.state) << ','
                << f.confidence << ',' << f.gap_share << ',' << f.edge_support << ','
                << f.shape_change << '\n';
          }
        }
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "perturb_sweep: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
