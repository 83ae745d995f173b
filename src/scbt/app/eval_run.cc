#include "scbt/app/eval_run.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/plot.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/frame_source.h"
#include "scbt/peers/polygon_tracker.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A polygon scaled into a smaller frame, kept inside it.
Polygon clamp_to_frame(Polygon polygon, cv::Size size) {
  for (Point& p : polygon) {
    p.x = std::clamp(p.x, 0.0, static_cast<double>(size.width));
    p.y = std::clamp(p.y, 0.0, static_cast<double>(size.height));
  }
  return polygon;
}

// A sequence's ground truth, loaded once and shared by its jobs.
struct Sequence {
  DatasetSequence files;
  std::vector<Polygon> truth;  // frame k at index k-1
};

// One (tracker, sequence) pair: either run a tracker or score a results folder.
struct Job {
  std::string tracker;
  std::string results_dir;  // empty: run `tracker`
  const Sequence* sequence = nullptr;
};

struct JobOutcome {
  std::vector<FrameRecord> frames;
  TimingStats timing;
  std::vector<std::string> warnings;
  std::string error;  // non-empty when the job failed
  double seconds = 0.0;
  bool done = false;
};

// Shared progress counters; the log is written under `mutex`.
struct Progress {
  std::mutex mutex;
  std::condition_variable changed;
  std::atomic<long> frames_done{0};
  int jobs_done = 0;
};

std::vector<Polygon> load_truth(const DatasetSequence& sequence, int max_frames) {
  const std::vector<std::string> lines = read_text_lines(sequence.ground_truth);
  std::vector<Polygon> truth;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (max_frames > 0 && static_cast<int>(truth.size()) >= max_frames) break;
    // Trailing blank lines are not frames.
    if (lines[i].find_first_not_of(" \t") == std::string::npos &&
        std::all_of(lines.begin() + i, lines.end(), [](const std::string& l) {
          return l.find_first_not_of(" \t") == std::string::npos;
        })) {
      break;
    }
    Polygon polygon;
    std::string error;
    if (!try_parse_polygon_line(lines[i], &polygon, &error) || !is_scorable_polygon(polygon)) {
      throw std::runtime_error(sequence.ground_truth + " line " + std::to_string(i + 1) + ": " +
                               (error.empty() ? "degenerate polygon" : error));
    }
    truth.push_back(std::move(polygon));
  }
  if (truth.empty()) throw std::runtime_error(sequence.ground_truth + ": no ground truth");
  return truth;
}

// Scores result lines against the truth: missing lines are failures, extra ones a warning.
std::vector<FrameRecord> score_lines(const std::vector<std::string>& lines,
                                     const std::vector<Polygon>& truth, cv::Size canvas,
                                     const std::string& what, std::vector<std::string>* warnings) {
  std::vector<FrameRecord> frames(truth.size());
  for (size_t k = 0; k < truth.size(); ++k) {
    FrameRecord& f = frames[k];
    f.frame = static_cast<int>(k + 1);
    if (k < lines.size()) {
      f.e_al = alignment_error_of_line(lines[k], truth[k], canvas, &f.note);
    } else {
      f.e_al = std::numeric_limits<double>::infinity();
      f.note = "missing result line";
    }
  }
  if (lines.size() < truth.size()) {
    warnings->push_back(what + ": " + std::to_string(lines.size()) + " result lines for " +
                        std::to_string(truth.size()) + " ground-truth frames; the " +
                        std::to_string(truth.size() - lines.size()) +
                        " missing frames count as failures");
  } else if (lines.size() > truth.size()) {
    warnings->push_back(what + ": " + std::to_string(lines.size()) + " result lines for " +
                        std::to_string(truth.size()) + " ground-truth frames; extra lines ignored");
  }
  return frames;
}

cv::Size first_frame_size(const std::string& frames) {
  std::unique_ptr<FrameSource> source = open_frame_source(frames);
  cv::Mat frame;
  if (!source->read(&frame)) throw std::runtime_error(frames + ": no frames");
  return frame.size();
}

std::string results_file(const std::string& out, const std::string& tracker,
                         const std::string& sequence) {
  return results_path((fs::path(out) / tracker).string(), sequence);
}

// Reads the next frame the perturbation shows (skipping stride - 1 frames after the first) and
// degrades it into `shown`; counts the frames read in `frame_number`.
bool read_shown_frame(FrameSource* source, const Perturbation& perturbation, int* frame_number,
                      cv::Mat* frame, cv::Mat* shown) {
  for (int skip = *frame_number == 0 ? 0 : perturbation.frame_stride() - 1; skip > 0; --skip) {
    if (!source->read(frame)) return false;
    ++*frame_number;
  }
  if (!source->read(frame)) return false;
  ++*frame_number;
  perturbation.apply(*frame, *frame_number, shown);
  return true;
}

void run_tracker_job(const Job& job, const EvalRunOptions& options, Progress* progress,
                     JobOutcome* outcome) {
  const Sequence& seq = *job.sequence;
  const std::string what = job.tracker + "/" + seq.files.name;
  const Perturbation& perturbation = options.perturbation;
  const double scale = perturbation.scale();
  std::unique_ptr<FrameSource> source = open_frame_source(seq.files.frames);
  cv::Mat frame, shown;
  int frame_number = 0;
  if (!read_shown_frame(source.get(), perturbation, &frame_number, &frame, &shown)) {
    throw std::runtime_error(seq.files.frames + ": no frames");
  }
  const cv::Size canvas = frame.size();
  // With a frame stride, the truth of the frames shown.
  std::vector<Polygon> truth;
  for (size_t k = 0; k < seq.truth.size(); k += perturbation.frame_stride()) {
    truth.push_back(seq.truth[k]);
  }
  std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker(job.tracker, options.tracker);
  try {
    tracker->init(shown,
                  clamp_to_frame(scale_polygon_to_frame(seq.truth.front(), scale), shown.size()));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": initial polygon (ground truth line 1): " + e.what());
  }
  const std::string path = results_file(options.out, job.tracker, seq.files.name);
  fs::create_directories(fs::path(path).parent_path());
  AtomicFile results(path);
  // Lines are kept to be scored exactly as written, so a later `--results` run agrees.
  std::vector<std::string> lines = {format_polygon_line(seq.truth.front())};
  results.stream() << lines.back() << '\n';
  progress->frames_done += 1;

  std::vector<FrameRecord> stats = {FrameRecord{}};  // frame 1: initial, untimed
  TimingStats& t = outcome->timing;
  t.has_timing = true;
  double fps_sum = 0.0;
  int fps_frames = 0;
  while ((options.max_frames <= 0 ||
          frame_number + perturbation.frame_stride() <= options.max_frames) &&
         read_shown_frame(source.get(), perturbation, &frame_number, &frame, &shown)) {
    const Clock::time_point start = Clock::now();
    const TrackResult r = tracker->track(shown);
    const double ms = 1000.0 * seconds_since(start);
    lines.push_back(format_polygon_line(scale_polygon_from_frame(r.boundary, scale)));
    results.stream() << lines.back() << '\n';
    FrameRecord f;
    f.has_timing = true;
    f.held = r.held;
    f.nodes = r.num_vertices;
    f.edges = r.num_edges;
    f.line_ms = r.line_ms;
    f.grouping_ms = r.grouping_ms;
    f.track_ms = ms;
    stats.push_back(f);
    ++t.tracked;
    t.held += r.held ? 1 : 0;
    t.edges += r.num_edges;
    t.nodes += r.num_vertices;
    t.line_ms += r.line_ms;
    t.grouping_ms += r.grouping_ms;
    t.track_ms += ms;
    if (ms > 0.0) {
      fps_sum += 1000.0 / ms;
      ++fps_frames;
    }
    progress->frames_done += 1;
  }
  results.commit();
  if (t.tracked > 0) {
    const double n = t.tracked;
    t.edges /= n;
    t.nodes /= n;
    t.line_ms /= n;
    t.grouping_ms /= n;
    t.track_ms /= n;
  }
  t.fps = fps_frames > 0 ? fps_sum / fps_frames : std::numeric_limits<double>::quiet_NaN();

  outcome->frames = score_lines(lines, truth, canvas, what, &outcome->warnings);
  for (size_t k = 0; k < outcome->frames.size(); ++k) {
    outcome->frames[k].frame = static_cast<int>(1 + k * perturbation.frame_stride());
  }
  for (size_t k = 1; k < outcome->frames.size() && k < stats.size(); ++k) {
    FrameRecord& f = outcome->frames[k];
    const FrameRecord& s = stats[k];
    f.has_timing = true;
    f.held = s.held;
    f.nodes = s.nodes;
    f.edges = s.edges;
    f.line_ms = s.line_ms;
    f.grouping_ms = s.grouping_ms;
    f.track_ms = s.track_ms;
  }
}

void run_score_job(const Job& job, const EvalRunOptions& options, Progress* progress,
                   JobOutcome* outcome) {
  const Sequence& seq = *job.sequence;
  const std::string what = job.tracker + "/" + seq.files.name;
  const std::string path = results_path(job.results_dir, seq.files.name);
  if (!fs::exists(path)) {
    outcome->warnings.push_back(what + ": no " + path + "; every frame counts as a failure");
    std::vector<std::string> ignored;
    outcome->frames = score_lines({}, seq.truth, {1, 1}, what, &ignored);
    progress->frames_done += static_cast<long>(seq.truth.size());
    return;
  }
  std::vector<std::string> lines = read_text_lines(path);
  if (options.max_frames > 0 && static_cast<int>(lines.size()) > options.max_frames) {
    lines.resize(options.max_frames);
  }
  // Trailing blank lines (an editor's final newline) are not frames.
  while (!lines.empty() && lines.back().find_first_not_of(" \t") == std::string::npos) {
    lines.pop_back();
  }
  const cv::Size canvas = first_frame_size(seq.files.frames);
  outcome->frames = score_lines(lines, seq.truth, canvas, what, &outcome->warnings);
  progress->frames_done += static_cast<long>(seq.truth.size());
}

std::string job_line(const Job& job, const JobOutcome& o, int done, int total, long frames,
                     long total_frames, double elapsed) {
  char head[160];
  std::snprintf(head, sizeof(head), "[%*d/%d] %-8s %-16s", total >= 10 ? 2 : 1, done, total,
                job.tracker.c_str(), job.sequence->files.name.c_str());
  std::string line = head;
  char body[256];
  if (!o.error.empty()) {
    line += " FAILED: " + o.error;
  } else {
    std::vector<double> errors;
    for (const FrameRecord& f : o.frames) errors.push_back(f.e_al);
    const ErrorStats e = error_stats(errors);
    std::snprintf(body, sizeof(body), " %5d frames  S@10 %5.1f%%  AUC %.3f  mean E_AL %6.2f",
                  e.frames, 100.0 * e.success_10, e.auc, e.mean);
    line += body;
    if (o.timing.has_timing) {
      if (o.timing.fps > 10000.0) {
        line += "  >10000 fps";
      } else {
        std::snprintf(body, sizeof(body), "  %6.1f fps", o.timing.fps);
        line += body;
      }
    }
    std::snprintf(body, sizeof(body), "  (%.1f s)", o.seconds);
    line += body;
  }
  std::snprintf(body, sizeof(body), " | %ld/%ld frames, %.1f frames/s", frames, total_frames,
                elapsed > 0 ? frames / elapsed : 0.0);
  return line + body;
}

// Means of the per-sequence timings weighted by their tracked frames.
TimingStats pool_timing(const std::vector<const TimingStats*>& parts) {
  TimingStats pooled;
  double fps_weight = 0.0;
  for (const TimingStats* t : parts) {
    if (!t->has_timing) return TimingStats{};
    pooled.has_timing = true;
    pooled.tracked += t->tracked;
    pooled.held += t->held;
    pooled.edges += t->edges * t->tracked;
    pooled.nodes += t->nodes * t->tracked;
    pooled.line_ms += t->line_ms * t->tracked;
    pooled.grouping_ms += t->grouping_ms * t->tracked;
    pooled.track_ms += t->track_ms * t->tracked;
    if (std::isfinite(t->fps)) {
      pooled.fps += t->fps * t->tracked;
      fps_weight += t->tracked;
    }
  }
  if (pooled.tracked > 0) {
    const double n = pooled.tracked;
    pooled.edges /= n;
    pooled.nodes /= n;
    pooled.line_ms /= n;
    pooled.grouping_ms /= n;
    pooled.track_ms /= n;
  }
  pooled.fps = fps_weight > 0 ? pooled.fps / fps_weight : std::numeric_limits<double>::quiet_NaN();
  return pooled;
}

std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

bool valid_name(const std::string& name) {
  return !name.empty() && name.find_first_of(",\"\r\n/\\") == std::string::npos && name != "." &&
         name != "..";
}

}  // namespace

std::pair<std::string, std::string> parse_results_spec(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
    throw std::invalid_argument("--results '" + spec + "': expected NAME=DIR");
  }
  std::string name = spec.substr(0, eq);
  if (!valid_name(name)) {
    throw std::invalid_argument("--results '" + spec + "': name '" + name +
                                "' must be non-empty without , \" / or \\");
  }
  return {name, spec.substr(eq + 1)};
}

void EvalRunOptions::check() const {
  if (dataset.empty()) throw std::invalid_argument("--dataset is required");
  if (out.empty()) throw std::invalid_argument("--out is required");
  if (jobs < 0) throw std::invalid_argument("--jobs " + std::to_string(jobs) + " must be >= 0");
  if (max_frames < 0) {
    throw std::invalid_argument("--max-frames " + std::to_string(max_frames) + " must be >= 0");
  }
  if (max_frames == 1) {
    throw std::invalid_argument("--max-frames 1 leaves nothing to track (use 0 for all frames)");
  }
  const std::vector<std::string> known = polygon_tracker_names();
  std::set<std::string> names;
  for (const std::string& name : trackers) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw std::invalid_argument("unknown tracker '" + name + "' (known: " + join(known) + ")");
    }
    if (!names.insert(name).second) {
      throw std::invalid_argument("tracker '" + name + "' given twice");
    }
  }
  for (const std::string& spec : results) {
    const std::string name = parse_results_spec(spec).first;
    if (!names.insert(name).second) {
      throw std::invalid_argument("--results name '" + name + "' is used twice");
    }
  }
  tracker.check();
}

EvalRunSummary run_eval(const EvalRunOptions& options, std::ostream& log) {
  const Clock::time_point start = Clock::now();
  options.check();
  EvalRunSummary summary;

  // Everything that can be checked is checked before any work starts.
  const std::vector<DatasetSequence> selected =
      select_dataset_sequences(options.dataset, options.sequences);
  std::vector<std::string> trackers = options.trackers;
  if (trackers.empty() && options.results.empty()) trackers = polygon_tracker_names();
  std::vector<std::pair<std::string, std::string>> results;
  for (const std::string& spec : options.results) {
    results.push_back(parse_results_spec(spec));
    const std::string& dir = results.back().second;
    if (!fs::is_directory(dir)) {
      throw std::runtime_error("--results " + spec + ": '" + dir + "' is not a directory");
    }
    const bool any = std::any_of(selected.begin(), selected.end(), [&](const DatasetSequence& s) {
      return fs::exists(results_path(dir, s.name));
    });
    if (!any) {
      throw std::runtime_error("--results " + spec + ": no <Seq>.txt file for any selected " +
                               "sequence in '" + dir + "'");
    }
  }
  std::vector<Sequence> sequences;
  sequences.reserve(selected.size());
  for (const DatasetSequence& files : selected) {
    sequences.push_back({files, load_truth(files, options.max_frames)});
  }

  // Jobs, longest sequences first so the pool ends together.
  std::vector<Job> jobs;
  for (const std::string& name : trackers) {
    for (const Sequence& s : sequences) jobs.push_back({name, "", &s});
  }
  for (const auto& [name, dir] : results) {
    for (const Sequence& s : sequences) jobs.push_back({name, dir, &s});
  }
  std::vector<size_t> order(jobs.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return jobs[a].sequence->truth.size() > jobs[b].sequence->truth.size();
  });
  long total_frames = 0;
  for (const Job& job : jobs) total_frames += static_cast<long>(job.sequence->truth.size());

  fs::create_directories(options.out);
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::max(
      1, std::min(options.jobs > 0 ? options.jobs : hardware, static_cast<int>(jobs.size())));
  summary.jobs = static_cast<int>(jobs.size());
  summary.threads = threads;
  if (!options.quiet) {
    log << "eval: " << jobs.size() << " jobs (" << join(trackers)
        << (trackers.empty() ? "" : " run")
        << (results.empty() ? ""
                            : std::string(trackers.empty() ? "" : "; ") + "scoring " +
                                  std::to_string(results.size()) + " results folders")
        << ") on " << sequences.size() << " sequences, " << total_frames << " frames, " << threads
        << " threads\n"
        << std::flush;
  }

  // The pool: each thread takes the next job until none is left.
  std::vector<JobOutcome> outcomes(jobs.size());
  Progress progress;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < order.size(); i = next++) {
      const Job& job = jobs[order[i]];
      JobOutcome& outcome = outcomes[order[i]];
      const Clock::time_point job_start = Clock::now();
      try {
        if (job.results_dir.empty()) {
          run_tracker_job(job, options, &progress, &outcome);
        } else {
          run_score_job(job, options, &progress, &outcome);
        }
      } catch (const std::exception& e) {
        outcome.error = e.what();
      }
      outcome.seconds = seconds_since(job_start);
      std::lock_guard<std::mutex> lock(progress.mutex);
      outcome.done = true;
      ++progress.jobs_done;
      if (!options.quiet) {
        log << job_line(job, outcome, progress.jobs_done, summary.jobs, progress.frames_done,
                        total_frames, seconds_since(start))
            << '\n';
        for (const std::string& w : outcome.warnings) log << "  warning: " << w << '\n';
        log << std::flush;
      }
      progress.changed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
  {
    // A heartbeat while long jobs run, so a quiet minute does not look like a hang.
    std::unique_lock<std::mutex> lock(progress.mutex);
    while (progress.jobs_done < summary.jobs) {
      const int before = progress.jobs_done;
      progress.changed.wait_for(lock, std::chrono::seconds(15));
      if (progress.jobs_done == before && progress.jobs_done < summary.jobs && !options.quiet) {
        const double elapsed = seconds_since(start);
        char line[160];
        std::snprintf(line, sizeof(line),
                      "  ... %ld/%ld frames, %.1f frames/s, %d/%d jobs done, %.0f s\n",
                      progress.frames_done.load(), total_frames,
                      elapsed > 0 ? progress.frames_done / elapsed : 0.0, progress.jobs_done,
                      summary.jobs, elapsed);
        log << line << std::flush;
      }
    }
  }
  for (std::thread& t : pool) t.join();

  // Scores in a stable order: trackers as given, then results; sequences as selected.
  std::vector<std::string> failures;
  std::vector<NamedCurve> curves;
  std::map<std::string, PlotPanel> panels;
  PlotPanel all_panel{"All sequences", {}};
  std::vector<std::string> names = trackers;
  for (const auto& r : results) names.push_back(r.first);
  for (const std::string& name : names) {
    std::vector<double> pooled_errors;
    std::vector<const TimingStats*> timings;
    bool complete = true;
    for (size_t i = 0; i < jobs.size(); ++i) {
      if (jobs[i].tracker != name) continue;
      const JobOutcome& o = outcomes[i];
      const std::string& seq = jobs[i].sequence->files.name;
      for (const std::string& w : o.warnings) summary.warnings.push_back(w);
      if (!o.error.empty()) {
        failures.push_back(name + "/" + seq + ": " + o.error);
        complete = false;
        continue;
      }
      std::vector<double> errors;
      for (const FrameRecord& f : o.frames) errors.push_back(f.e_al);
      pooled_errors.insert(pooled_errors.end(), errors.begin(), errors.end());
      timings.push_back(&o.timing);
      SequenceScore score{name, seq, error_stats(errors), o.timing};
      summary.scores.push_back(score);
      const SuccessCurve curve = success_curve(errors);
      curves.push_back({name, seq, curve});
      PlotPanel& panel = panels[seq];
      panel.title = seq;
      panel.lines.push_back({name, curve, score.errors.auc});
    }
    if (sequences.size() > 1 && complete && !pooled_errors.empty()) {
      SequenceScore pooled{name, kAllSequences, error_stats(pooled_errors), pool_timing(timings)};
      summary.scores.push_back(pooled);
      const SuccessCurve curve = success_curve(pooled_errors);
      curves.push_back({name, kAllSequences, curve});
      all_panel.lines.push_back({name, curve, pooled.errors.auc});
    }
  }

  // Outputs, each written atomically.
  const fs::path out(options.out);
  {
    AtomicFile file((out / "frames.csv").string());
    write_frame_csv_header(file.stream());
    for (size_t i = 0; i < jobs.size(); ++i) {
      if (outcomes[i].error.empty()) {
        write_frame_csv_rows(file.stream(), jobs[i].tracker, jobs[i].sequence->files.name,
                             outcomes[i].frames);
      }
    }
    file.commit();
    summary.files.push_back(file.path());
  }
  {
    AtomicFile file((out / "summary.csv").string());
    write_summary_csv(file.stream(), summary.scores);
    file.commit();
    summary.files.push_back(file.path());
  }
  {
    AtomicFile file((out / "curves.csv").string());
    write_curves_csv(file.stream(), curves);
    file.commit();
    summary.files.push_back(file.path());
  }
  ReportInfo info;
  info.dataset = options.dataset;
  if (options.plot) {
    std::vector<PlotPanel> shown;
    for (const Sequence& s : sequences) {
      if (panels.count(s.files.name)) shown.push_back(panels[s.files.name]);
    }
    if (!all_panel.lines.empty()) shown.push_back(all_panel);
    const std::string png = (out / "success_curves.png").string();
    write_png(png, render_success_curves(shown));
    summary.files.push_back(png);
    info.plot_file = "success_curves.png";
  }
  summary.seconds = seconds_since(start);
  std::vector<std::string> sequence_names;
  for (const Sequence& s : sequences) sequence_names.push_back(s.files.name);
  if (!trackers.empty()) {
    const TrackerOptions& t = options.tracker;
    char line[384];
    std::snprintf(line, sizeof(line),
                  "bdsp options: detector %s, filter distance %g px, min area similarity %g, "
                  "cost tolerance %g, recover by motion %s, detection window %s, seed stride %d",
                  to_string(t.detector.kind).c_str(), t.filter_distance, t.min_area_similarity,
                  t.cost_tolerance, t.recover_by_motion ? "on" : "off",
                  t.detector.crop_to_boundary ? "on" : "off", t.bdsp.seed_stride);
    info.notes.push_back("Trackers run: " + join(trackers) +
                         " (initialised from ground-truth "
                         "line 1; results in <tracker>/<Seq>.txt)");
    info.notes.push_back(line);
    if (options.perturbation.kind != PerturbationKind::kNone) {
      info.notes.push_back("Frames perturbed: " + options.perturbation.name() +
                           " (eval/perturb.h; seed " + std::to_string(options.perturbation.seed) +
                           ")");
    }
  }
  for (const auto& [name, dir] : results) {
    info.notes.push_back("Results scored: " + name + " = `" + dir + "`");
  }
  info.notes.push_back("Sequences: " + join(sequence_names) +
                       (options.max_frames > 0
                            ? " (first " + std::to_string(options.max_frames) + " frames only)"
                            : ""));
  char timing[200];
  std::snprintf(timing, sizeof(timing),
                "%d jobs on %d threads in %.1f s wall time (timings are per process and grow "
                "when jobs share cores)",
                summary.jobs, threads, summary.seconds);
  info.notes.push_back(timing);
  for (const std::string& w : summary.warnings) info.notes.push_back("Warning: " + w);
  for (const std::string& f : failures) info.notes.push_back("FAILED: " + f);
  {
    AtomicFile file((out / "report.md").string());
    write_markdown_report(file.stream(), summary.scores, info);
    file.commit();
    summary.files.insert(summary.files.begin(), file.path());
  }
  if (!options.quiet) {
    log << "eval: wrote " << join(summary.files) << " in " << std::fixed;
    log.precision(1);
    log << summary.seconds << " s\n" << std::defaultfloat << std::flush;
  }
  if (!failures.empty()) {
    throw std::runtime_error(std::to_string(failures.size()) + " of " +
                             std::to_string(summary.jobs) +
                             " jobs failed; first: " + failures.front());
  }
  return summary;
}

}  // namespace scbt
