#include "scbt/app/demo_run.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "scbt/app/frame_writers.h"
#include "scbt/app/sequence_runner.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/render/annotate.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

constexpr double kVideoFps = 30.0;
const cv::Scalar kTruthColour(0, 200, 0);  // thin green, drawn over the tracked (yellow) outline

// The rendered clip as a frame source; truth() is the current frame's true outline.
class RenderedFrames : public FrameSource {
 public:
  RenderedFrames(const DemoOptions& options, const cv::Mat& background, const Polygon& model,
                 const std::vector<Pose>& poses)
      : options_(options), background_(background), model_(model), poses_(poses) {}
  bool read(cv::Mat* image) override {
    if (next_ >= static_cast<int>(poses_.size())) return false;
    frame_ = render_frame(options_.scene, background_, model_, poses_[next_], next_);
    ++next_;
    *image = frame_.image;
    return true;
  }
  int frame_count() const override { return static_cast<int>(poses_.size()); }
  double fps() const override { return kVideoFps; }
  std::string current_name() const override { return "frame " + std::to_string(next_); }
  const Polygon& truth() const { return frame_.truth; }

 private:
  const DemoOptions& options_;
  const cv::Mat& background_;
  const Polygon& model_;
  const std::vector<Pose>& poses_;
  SceneFrame frame_;
  int next_ = 0;
};

// truth.txt and errors.csv, and the error statistics of the summary.
class DemoScoreWriter : public FrameWriter {
 public:
  DemoScoreWriter(const RenderedFrames* frames, DemoSummary* summary)
      : frames_(frames),
        summary_(summary),
        truth_(summary->truth_path),
        errors_(summary->errors_path) {
    errors_.stream() << "frame,error_px,held,cost,area_similarity,line_ms,grouping_ms,total_ms\n";
  }
  void write(const TrackedFrame& f) override {
    truth_.stream() << format_polygon_line(frames_->truth()) << '\n';
    if (f.initial) {
      errors_.stream() << "1,0,0,0,1,0,0,0\n";
      return;
    }
    const TrackResult& r = *f.result;
    const double error = mean_boundary_distance(r.boundary, frames_->truth(), 0.5);
    summary_->errors.push_back(error);
    if (error > summary_->max_error) {
      summary_->max_error = error;
      summary_->worst_frame = f.number;
    }
    char row[200];
    std::snprintf(row, sizeof(row), "%d,%.4f,%d,%.6g,%.6g,%.4f,%.4f,%.4f\n", f.number, error,
                  r.held ? 1 : 0, r.cost, r.area_similarity, r.line_ms, r.grouping_ms,
                  r.total_ms());
    errors_.stream() << row;
  }
  void commit() override {
    truth_.commit();
    errors_.commit();
  }

 private:
  const RenderedFrames* frames_;
  DemoSummary* summary_;
  AtomicFile truth_;
  AtomicFile errors_;
};

// The caption of a frame: tracked or held, its error against the truth, the time.
std::string demo_caption(const TrackedFrame& f, const Polygon& truth) {
  if (f.initial) return "frame 1: initial boundary (truth)";
  char status[200];
  std::snprintf(status, sizeof(status), "frame %d  %s  error %.2f px  %.2f ms", f.number,
                f.result->held ? "HELD" : "tracked",
                mean_boundary_distance(f.result->boundary, truth, 0.5), f.result->total_ms());
  return status;
}

// The motion path must stay inside the frame.
void check_path(const cv::Rect2d& path, const cv::Size& size) {
  if (path.x < 0 || path.y < 0 || path.x + path.width > size.width ||
      path.y + path.height > size.height) {
    throw std::invalid_argument("the object's motion path leaves the " +
                                std::to_string(size.width) + "x" + std::to_string(size.height) +
                                " frame; move the start pose or shrink the amplitudes");
  }
}

}  // namespace

void DemoOptions::check() const {
  if (out_dir.empty()) throw std::invalid_argument("out_dir must not be empty");
  if (frames < 2 || frames > 100000) {
    throw std::invalid_argument("frames must be in 2..100000, got " + std::to_string(frames));
  }
  scene.check();
  motion.check();
  tracker.check();
}

DemoSummary run_demo(const DemoOptions& options, std::ostream& log) {
  options.check();
  const Polygon model = object_model(options.scene);
  const std::vector<Pose> poses = smooth_motion_path(options.motion, options.frames);
  const cv::Rect2d path = path_region(model, poses);
  check_path(path, options.scene.size);
  const cv::Mat background = render_background(options.scene, path);

  fs::create_directories(options.out_dir);
  const fs::path dir(options.out_dir);
  DemoSummary summary;
  summary.results_path = (dir / "results.txt").string();
  summary.truth_path = (dir / "truth.txt").string();
  summary.errors_path = (dir / "errors.csv").string();
  if (options.video) summary.video_path = (dir / "demo.avi").string();

  RenderedFrames frames(options, background, model, poses);
  BdspPolygonTracker bdsp{Tracker(options.tracker)};
  bdsp.tracker().set_keep_debug(options.video);
  ResultsWriter results(summary.results_path);
  DemoScoreWriter score(&frames, &summary);
  std::unique_ptr<AnnotationWriter> video;
  if (options.video) {
    video = std::make_unique<AnnotationWriter>(
        &bdsp.tracker(), summary.video_path, kVideoFps, "",
        [&frames](const TrackedFrame& f) { return demo_caption(f, frames.truth()); },
        [&frames](const TrackedFrame& f, cv::Mat* image) {
          if (!f.initial) draw_polygon(image, frames.truth(), kTruthColour, 1);
        });
  }
  RunStatistics stats;
  ProgressWriter progress(log, "demo", options.frames, !options.quiet);
  SequenceRunner runner(&bdsp, &frames, {&results, &score, video.get(), &stats, &progress});
  runner.read_first("demo");
  runner.start(frames.truth());
  while (runner.step()) {
  }
  progress.finish();
  runner.commit();

  summary.frames = stats.frames;
  summary.tracked = stats.tracked;
  summary.held = stats.held;
  const double n = summary.tracked;
  double error_sum = 0.0;
  int under_2px = 0;
  for (double e : summary.errors) {
    error_sum += e;
    under_2px += e < 2.0 ? 1 : 0;
  }
  summary.mean_error = error_sum / n;
  summary.share_under_2px = under_2px / n;
  summary.mean_ms = stats.total_ms / n;
  summary.fps = stats.fps();
  return summary;
}

std::string format_demo_summary(const DemoSummary& s) {
  char text[1024];
  std::snprintf(text, sizeof(text),
                "frames %d (tracked %d, held %d)\n"
                "boundary error vs truth: mean %.2f px, max %.2f px (frame %d), "
                "%.1f%% of frames under 2 px\n"
                "tracking time %.2f ms per frame, %.1f fps\n"
                "results %s\ntruth   %s\nerrors  %s\n",
                s.frames, s.tracked, s.held, s.mean_error, s.max_error, s.worst_frame,
                100.0 * s.share_under_2px, s.mean_ms, s.fps, s.results_path.c_str(),
                s.truth_path.c_str(), s.errors_path.c_str());
  std::string out = text;
  if (!s.video_path.empty()) out += "video   " + s.video_path + "\n";
  return out;
}

}  // namespace scbt
