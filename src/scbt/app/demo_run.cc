#include "scbt/app/demo_run.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "scbt/app/progress.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/render/annotate.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

constexpr double kVideoFps = 30.0;
const cv::Scalar kTruthColour(0, 200, 0);  // thin green, drawn over the tracked (yellow) outline

// An MJPG .avi written under a temporary name and renamed when complete.
class VideoOutput {
 public:
  explicit VideoOutput(std::string path) : path_(std::move(path)) {
    const fs::path p(path_);
    temporary_ = (p.parent_path() / (".tmp-" + p.filename().string())).string();
  }
  ~VideoOutput() {
    if (writer_ && !committed_) {
      writer_->release();
      std::remove(temporary_.c_str());
    }
  }
  void write(const cv::Mat& image) {
    if (!writer_) {
      writer_ = std::make_unique<cv::VideoWriter>(
          temporary_, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kVideoFps, image.size());
      if (!writer_->isOpened()) throw std::runtime_error(path_ + ": cannot write video");
    }
    writer_->write(image);
  }
  void commit() {
    if (!writer_) return;
    writer_->release();
    fs::rename(temporary_, path_);
    committed_ = true;
  }

 private:
  std::string path_;
  std::string temporary_;
  std::unique_ptr<cv::VideoWriter> writer_;
  bool committed_ = false;
};

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
  const cv::Size size = options.scene.size;
  if (path.x < 0 || path.y < 0 || path.x + path.width > size.width ||
      path.y + path.height > size.height) {
    throw std::invalid_argument("the object's motion path leaves the " +
                                std::to_string(size.width) + "x" + std::to_string(size.height) +
                                " frame; move the start pose or shrink the amplitudes");
  }
  const cv::Mat background = render_background(options.scene, path);

  fs::create_directories(options.out_dir);
  const fs::path dir(options.out_dir);
  DemoSummary summary;
  summary.results_path = (dir / "results.txt").string();
  summary.truth_path = (dir / "truth.txt").string();
  summary.errors_path = (dir / "errors.csv").string();
  if (options.video) summary.video_path = (dir / "demo.avi").string();

  AtomicFile results(summary.results_path);
  AtomicFile truth(summary.truth_path);
  AtomicFile errors(summary.errors_path);
  errors.stream() << "frame,error_px,held,cost,area_similarity,line_ms,grouping_ms,total_ms\n";
  std::unique_ptr<VideoOutput> video;
  if (options.video) video = std::make_unique<VideoOutput>(summary.video_path);

  Tracker tracker(options.tracker);
  tracker.set_keep_debug(options.video);
  ProgressBar progress(log, "demo", options.frames, !options.quiet);

  SceneFrame frame = render_frame(options.scene, background, model, poses[0], 0);
  tracker.init(frame.image, frame.truth);
  results.stream() << format_polygon_line(frame.truth) << '\n';
  truth.stream() << format_polygon_line(frame.truth) << '\n';
  errors.stream() << "1,0,0,0,1,0,0,0\n";
  if (video) {
    TrackResult initial;
    initial.boundary = frame.truth;
    video->write(annotate_frame(frame.image, {}, initial, "frame 1: initial boundary (truth)"));
  }
  summary.frames = 1;

  double total_ms = 0.0;
  double error_sum = 0.0;
  int under_2px = 0;
  for (int k = 1; k < options.frames; ++k) {
    frame = render_frame(options.scene, background, model, poses[k], k);
    const TrackResult r = tracker.track(frame.image);
    const double error = mean_boundary_distance(r.boundary, frame.truth, 0.5);
    ++summary.frames;
    ++summary.tracked;
    summary.held += r.held ? 1 : 0;
    summary.errors.push_back(error);
    error_sum += error;
    under_2px += error < 2.0 ? 1 : 0;
    if (error > summary.max_error) {
      summary.max_error = error;
      summary.worst_frame = k + 1;
    }
    total_ms += r.total_ms();

    results.stream() << format_polygon_line(r.boundary) << '\n';
    truth.stream() << format_polygon_line(frame.truth) << '\n';
    char row[200];
    std::snprintf(row, sizeof(row), "%d,%.4f,%d,%.6g,%.6g,%.4f,%.4f,%.4f\n", k + 1, error,
                  r.held ? 1 : 0, r.cost, r.area_similarity, r.line_ms, r.grouping_ms,
                  r.total_ms());
    errors.stream() << row;
    if (video) {
      char status[200];
      std::snprintf(status, sizeof(status), "frame %d  %s  error %.2f px  %.2f ms", k + 1,
                    r.held ? "HELD" : "tracked", error, r.total_ms());
      cv::Mat annotated = annotate_frame(frame.image, tracker.debug(), r, status);
      draw_polygon(&annotated, frame.truth, kTruthColour, 1);
      video->write(annotated);
    }
    progress.update(k + 1);
  }
  progress.finish(summary.frames);

  const double n = summary.tracked;
  summary.mean_error = error_sum / n;
  summary.share_under_2px = under_2px / n;
  summary.mean_ms = total_ms / n;
  summary.fps = total_ms > 0.0 ? 1000.0 * n / total_ms : 0.0;

  results.commit();
  truth.commit();
  errors.commit();
  if (video) video->commit();
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
