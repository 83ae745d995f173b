#include "scbt/app/eval_jobs.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "scbt/app/sequence_runner.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/bounded_read.h"
#include "scbt/io/frame_source.h"
#include "scbt/peers/polygon_tracker.h"

namespace scbt {
namespace fs = std::filesystem;

double seconds_since(EvalClock::time_point start) {
  return std::chrono::duration<double>(EvalClock::now() - start).count();
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::vector<Polygon> load_truth(const DatasetSequence& sequence, int max_frames) {
  const std::vector<std::string> lines =
      read_text_lines(sequence.ground_truth, kMaxTextFileBytes, "a ground-truth file");
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

SequenceGap sequence_gap(const EvalRunOptions& options, int frames) {
  switch (options.gap) {
    case GapVariantKind::kNone:
      return SequenceGap();
    case GapVariantKind::kGrey:
      return SequenceGap::grey(frames, 30, options.gap_position);
    case GapVariantKind::kDrop:
      return SequenceGap::drop(frames, 60, options.gap_position);
  }
  return SequenceGap();
}

namespace {

// A polygon scaled into a smaller frame, kept inside it.
Polygon clamp_to_frame(Polygon polygon, cv::Size size) {
  for (Point& p : polygon) {
    p.x = std::clamp(p.x, 0.0, static_cast<double>(size.width));
    p.y = std::clamp(p.y, 0.0, static_cast<double>(size.height));
  }
  return polygon;
}

// Shared progress counters; the log is written under `mutex`.
struct Progress {
  std::mutex mutex;
  std::condition_variable changed;
  std::atomic<long> frames_done{0};
  int jobs_done = 0;
};

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

// The frames a run shows the tracker: every stride-th frame, without the gap's dropped ones, up
// to max_frames of the sequence (0: all).
class ShownFrames : public FrameSource {
 public:
  ShownFrames(const std::string& frames, const Perturbation& perturbation, const SequenceGap& gap,
              const OcclusionPlan* occlusion, int max_frames)
      : source_(open_frame_source(frames)),
        perturbation_(perturbation),
        gap_(gap),
        occlusion_(occlusion),
        max_frames_(max_frames) {}

  // Reads the next frame shown (skipping stride - 1 frames after the first, and dropped frames),
  // greys it in a grey gap and degrades it into `shown`.
  bool read(cv::Mat* shown) override {
    const int stride = perturbation_.frame_stride();
    if (number_ > 0 && max_frames_ > 0 && number_ + stride > max_frames_) return false;
    for (int skip = number_ == 0 ? 0 : stride - 1; skip > 0; --skip) {
      if (!source_->read(&frame_)) return false;
      ++number_;
    }
    do {
      if (!source_->read(&frame_)) return false;
      ++number_;
    } while (gap_.dropped(number_ - 1));
    gap_.apply(number_ - 1, &frame_);
    if (occlusion_ != nullptr) occlusion_->draw(number_ - 1, &frame_);
    perturbation_.apply(frame_, number_, shown);
    return true;
  }
  int frame_count() const override { return -1; }
  std::string current_name() const override { return source_->current_name(); }
  cv::Size size() const { return frame_.size(); }  // of the last frame read, before degrading

 private:
  std::unique_ptr<FrameSource> source_;
  const Perturbation& perturbation_;
  const SequenceGap& gap_;
  const OcclusionPlan* occlusion_;  // drawn before the perturbation (kOcclude), else nullptr
  int max_frames_;
  cv::Mat frame_;
  int number_ = 0;  // 1-based in the sequence, of the last frame read
};

// The frame numbers (1-based) scored: those shown, within the ground truth.
std::vector<int> scored_numbers(int truth_frames, int stride, const SequenceGap& gap) {
  std::vector<int> numbers;
  for (int k = 0; k < truth_frames; k += stride) {
    if (!gap.dropped(k)) numbers.push_back(k + 1);
  }
  return numbers;
}

void add_timing(const TrackResult& r, double ms, TimingStats* t, FrameRecord* f) {
  f->has_timing = true;
  f->held = r.held;
  f->nodes = r.num_vertices;
  f->edges = r.num_edges;
  f->line_ms = r.line_ms;
  f->grouping_ms = r.grouping_ms;
  f->track_ms = ms;
  ++t->tracked;
  t->held += r.held ? 1 : 0;
  t->edges += r.num_edges;
  t->nodes += r.num_vertices;
  t->line_ms += r.line_ms;
  t->grouping_ms += r.grouping_ms;
  t->track_ms += ms;
}

void finish_timing(double fps_sum, int fps_frames, TimingStats* t) {
  if (t->tracked > 0) {
    const double n = t->tracked;
    t->edges /= n;
    t->nodes /= n;
    t->line_ms /= n;
    t->grouping_ms /= n;
    t->track_ms /= n;
  }
  t->fps = fps_frames > 0 ? fps_sum / fps_frames : std::numeric_limits<double>::quiet_NaN();
}

// Per tracked frame of a run: its timing record and what the loss scores need.
struct TrackedLine {
  FrameRecord stats;
  double confidence = 0.0;
  bool tracking = false;
};

// Scores the lines, numbers the records by frame, copies the timings, keeps the loss data and
// leaves the gap's frames out of the scores (nothing to see there, or not shown).
void score_run(const std::vector<std::string>& lines, const std::vector<TrackedLine>& tracked,
               const std::vector<int>& numbers, const std::vector<Polygon>& truth, cv::Size canvas,
               const std::string& what, EvalJobOutcome* outcome) {
  std::vector<FrameRecord> frames = score_lines(lines, truth, canvas, what, &outcome->warnings);
  for (size_t k = 0; k < frames.size(); ++k) {
    FrameRecord& f = frames[k];
    f.frame = numbers[k];
    if (k == 0 || k >= tracked.size()) continue;  // the initial frame is not tracked
    const TrackedLine& t = tracked[k];
    const std::string note = f.note;
    const double e_al = f.e_al;
    f = t.stats;
    f.frame = numbers[k];
    f.note = note;
    f.e_al = e_al;
    outcome->loss.push_back({numbers[k] - 1, f.e_al, t.confidence, t.tracking});
  }
  for (FrameRecord& f : frames) {
    if (!outcome->gap.in_gap(f.frame - 1)) outcome->frames.push_back(std::move(f));
  }
}

// A tracker job's results file and what is scored and timed: the initial line is the ground
// truth's (untimed), every other line the boundary scaled back to the sequence's frames. Lines
// are kept to be scored exactly as written, so a later `--results` run agrees. The file is
// opened on the initial frame, once the tracker took the initial polygon.
class EvalTrackWriter : public FrameWriter {
 public:
  EvalTrackWriter(std::string path, const Polygon& first_truth, double scale, Progress* progress)
      : path_(std::move(path)), first_truth_(first_truth), scale_(scale), progress_(progress) {}

  void write(const TrackedFrame& f) override {
    if (f.initial) {
      fs::create_directories(fs::path(path_).parent_path());
      results_ = std::make_unique<AtomicFile>(path_);
      lines.push_back(format_polygon_line(first_truth_));
      tracked.resize(1);
    } else {
      const TrackResult& r = *f.result;
      lines.push_back(format_polygon_line(scale_polygon_from_frame(r.boundary, scale_)));
      TrackedLine line{FrameRecord{}, r.confidence, r.state == TrackState::kTracking};
      add_timing(r, f.wall_ms, &timing, &line.stats);
      tracked.push_back(line);
      if (f.wall_ms > 0.0) {
        fps_sum += 1000.0 / f.wall_ms;
        ++fps_frames;
      }
    }
    results_->stream() << lines.back() << '\n';
    progress_->frames_done += 1;
  }
  void commit() override { results_->commit(); }

  std::vector<std::string> lines;
  std::vector<TrackedLine> tracked;  // frame 1: initial, untimed
  TimingStats timing;
  double fps_sum = 0.0;
  int fps_frames = 0;

 private:
  std::string path_;
  const Polygon& first_truth_;
  double scale_;
  Progress* progress_;
  std::unique_ptr<AtomicFile> results_;
};

void run_tracker_job(const EvalJob& job, const EvalRunOptions& options, Progress* progress,
                     EvalJobOutcome* outcome) {
  const EvalSequence& seq = *job.sequence;
  const std::string what = job.tracker + "/" + seq.files.name;
  const Perturbation& perturbation = options.perturbation;
  const double scale = perturbation.scale();
  outcome->gap = sequence_gap(options, static_cast<int>(seq.truth.size()));
  std::optional<OcclusionPlan> occlusion;
  if (perturbation.kind == PerturbationKind::kOcclude) {
    // Each sequence gets its own positions from the seed.
    std::uint64_t seed = perturbation.seed;
    for (char c : seq.files.name) seed = seed * 1099511628211ULL + static_cast<unsigned char>(c);
    occlusion.emplace(perturbation.occlusion, seq.truth, seed);
  }
  ShownFrames source(seq.files.frames, perturbation, outcome->gap,
                     occlusion ? &*occlusion : nullptr, options.max_frames);
  std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker(job.tracker, options.tracker);
  EvalTrackWriter writer(
      results_path((fs::path(options.out) / job.tracker).string(), seq.files.name),
      seq.truth.front(), scale, progress);
  SequenceRunner runner(tracker.get(), &source, {&writer});
  const cv::Mat& shown = runner.read_first(seq.files.frames);
  const cv::Size canvas = source.size();
  const Polygon initial =
      clamp_to_frame(scale_polygon_to_frame(seq.truth.front(), scale), shown.size());
  try {
    tracker->init(shown, initial);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": initial polygon (ground truth line 1): " + e.what());
  }
  runner.write_initial(initial);
  runner.run();
  if (occlusion) {
    // Where the occluders were, for scoring the frames during and after each (start and end
    // frame, 1-based, end exclusive, and the most of the outline hidden).
    AtomicFile events(results_path((fs::path(options.out) / job.tracker).string(),
                                   seq.files.name + ".occlusion"));
    events.stream() << "# start end hidden\n";
    for (const OcclusionEvent& e : occlusion->events()) {
      double hidden = 0.0;
      for (int k = e.start; k < e.end(); ++k)
        hidden = std::max(hidden, occlusion->hidden_fraction(k));
      events.stream() << e.start + 1 << ' ' << e.end() + 1 << ' ' << hidden << '\n';
    }
    events.commit();
  }
  outcome->timing = writer.timing;
  outcome->timing.has_timing = true;
  finish_timing(writer.fps_sum, writer.fps_frames, &outcome->timing);
  const std::vector<int> numbers =
      scored_numbers(static_cast<int>(seq.truth.size()), perturbation.frame_stride(), outcome->gap);
  std::vector<Polygon> truth;
  for (int n : numbers) truth.push_back(seq.truth[n - 1]);
  score_run(writer.lines, writer.tracked, numbers, truth, canvas, what, outcome);
}

void run_score_job(const EvalJob& job, const EvalRunOptions& options, Progress* progress,
                   EvalJobOutcome* outcome) {
  const EvalSequence& seq = *job.sequence;
  const std::string what = job.tracker + "/" + seq.files.name;
  const std::string path = results_path(job.results_dir, seq.files.name);
  if (!fs::exists(path)) {
    outcome->warnings.push_back(what + ": no " + path + "; every frame counts as a failure");
    std::vector<std::string> ignored;
    outcome->frames = score_lines({}, seq.truth, {1, 1}, what, &ignored);
    progress->frames_done += static_cast<long>(seq.truth.size());
    return;
  }
  std::vector<std::string> lines = read_text_lines(path, kMaxTextFileBytes, "a results file");
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

std::string job_line(const EvalJob& job, const EvalJobOutcome& o, int done, int total, long frames,
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

// A heartbeat while long jobs run, so a quiet minute does not look like a hang.
void wait_for_jobs(Progress* progress, int jobs, long total_frames, bool quiet,
                   EvalClock::time_point start, std::ostream& log) {
  std::unique_lock<std::mutex> lock(progress->mutex);
  while (progress->jobs_done < jobs) {
    const int before = progress->jobs_done;
    progress->changed.wait_for(lock, std::chrono::seconds(15));
    if (progress->jobs_done == before && progress->jobs_done < jobs && !quiet) {
      const double elapsed = seconds_since(start);
      char line[160];
      std::snprintf(
          line, sizeof(line), "  ... %ld/%ld frames, %.1f frames/s, %d/%d jobs done, %.0f s\n",
          progress->frames_done.load(), total_frames,
          elapsed > 0 ? progress->frames_done / elapsed : 0.0, progress->jobs_done, jobs, elapsed);
      log << line << std::flush;
    }
  }
}

}  // namespace

std::vector<EvalJobOutcome> run_eval_jobs(const std::vector<EvalJob>& jobs,
                                          const EvalRunOptions& options, int threads,
                                          std::ostream& log) {
  const EvalClock::time_point start = EvalClock::now();
  std::vector<size_t> order(jobs.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return jobs[a].sequence->truth.size() > jobs[b].sequence->truth.size();
  });
  long total_frames = 0;
  for (const EvalJob& job : jobs) total_frames += static_cast<long>(job.sequence->truth.size());
  const int total = static_cast<int>(jobs.size());

  // The pool: each thread takes the next job until none is left.
  std::vector<EvalJobOutcome> outcomes(jobs.size());
  Progress progress;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < order.size(); i = next++) {
      const EvalJob& job = jobs[order[i]];
      EvalJobOutcome& outcome = outcomes[order[i]];
      const EvalClock::time_point job_start = EvalClock::now();
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
      ++progress.jobs_done;
      if (!options.quiet) {
        log << job_line(job, outcome, progress.jobs_done, total, progress.frames_done, total_frames,
                        seconds_since(start))
            << '\n';
        for (const std::string& w : outcome.warnings) log << "  warning: " << w << '\n';
        log << std::flush;
      }
      progress.changed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
  wait_for_jobs(&progress, total, total_frames, options.quiet, start, log);
  for (std::thread& t : pool) t.join();
  return outcomes;
}

}  // namespace scbt
