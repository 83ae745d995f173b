#include "scbt/app/track_run.h"

#include <filesystem>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <stdexcept>

#include "scbt/app/progress.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/frame_source.h"
#include "scbt/render/annotate.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

int video_fourcc(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".mp4" || ext == ".m4v") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
}

void write_csv_header(std::ostream& csv) {
  csv << "frame,held,cost,area_similarity,detected,kept,vertices,edges,candidates,line_ms,"
         "grouping_ms,total_ms\n";
}

void write_csv_row(std::ostream& csv, int frame, const TrackResult& r) {
  char line[256];
  std::snprintf(line, sizeof(line), "%d,%d,%.6g,%.6g,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f\n", frame,
                r.held ? 1 : 0, r.cost, r.area_similarity, r.num_detected, r.num_kept,
                r.num_vertices, r.num_edges, r.num_candidates, r.line_ms, r.grouping_ms,
                r.total_ms());
  csv << line;
}

}  // namespace

Polygon load_initial_polygon(const TrackRunOptions& options) {
  if (options.init_file.empty() == options.init_points.empty()) {
    throw std::invalid_argument("give exactly one of --init FILE or --init-points \"x,y ...\"");
  }
  if (!options.init_file.empty()) return read_first_polygon(options.init_file);
  try {
    return parse_points_list(options.init_points);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--init-points: ") + e.what());
  }
}

TrackSummary run_track(const TrackRunOptions& options, std::ostream& log) {
  if (options.output.empty()) throw std::invalid_argument("--output is required");
  const Polygon initial = load_initial_polygon(options);
  Tracker tracker(options.tracker);
  std::unique_ptr<FrameSource> source = open_frame_source(options.input);

  cv::Mat frame;
  if (!source->read(&frame)) throw std::runtime_error(options.input + ": no frames");
  try {
    tracker.init(frame, initial);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("initial polygon: ") + e.what());
  }
  const bool annotate = !options.video.empty() || !options.frames_out.empty();
  tracker.set_keep_debug(annotate);

  AtomicFile results(options.output);
  std::unique_ptr<AtomicFile> csv;
  if (!options.csv.empty()) {
    csv = std::make_unique<AtomicFile>(options.csv);
    write_csv_header(csv->stream());
  }
  std::unique_ptr<cv::VideoWriter> video;
  std::string video_temporary;
  if (!options.frames_out.empty()) fs::create_directories(options.frames_out);

  results.stream() << format_polygon_line(initial) << '\n';
  TrackSummary summary;
  summary.frames = 1;
  double total_ms = 0.0;
  ProgressBar progress(log, "tracking", source->frame_count(), !options.quiet);

  auto emit_annotation = [&](const cv::Mat& image, int index) {
    if (!options.video.empty()) {
      if (!video) {
        // The writer picks its container from the extension, so the temporary keeps it.
        const fs::path path(options.video);
        video_temporary = (path.parent_path() / (".tmp-" + path.filename().string())).string();
        const double fps = source->fps() > 0 ? source->fps() : 30.0;
        video = std::make_unique<cv::VideoWriter>(video_temporary, video_fourcc(options.video), fps,
                                                  image.size());
        if (!video->isOpened()) throw std::runtime_error(options.video + ": cannot write video");
      }
      video->write(image);
    }
    if (!options.frames_out.empty()) {
      char name[32];
      std::snprintf(name, sizeof(name), "%04d.jpg", index);
      const std::string path = (fs::path(options.frames_out) / name).string();
      if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write image");
    }
  };

  try {
    if (annotate) {
      TrackResult first;
      first.boundary = initial;
      emit_annotation(annotate_frame(frame, {}, first, "frame 1: initial boundary"), 1);
    }
    while ((options.max_frames <= 0 || summary.frames < options.max_frames) &&
           source->read(&frame)) {
      const TrackResult r = tracker.track(frame);
      ++summary.frames;
      ++summary.tracked;
      summary.held += r.held ? 1 : 0;
      summary.mean_line_ms += r.line_ms;
      summary.mean_grouping_ms += r.grouping_ms;
      summary.mean_vertices += r.num_vertices;
      summary.mean_edges += r.num_edges;
      total_ms += r.total_ms();
      results.stream() << format_polygon_line(r.boundary) << '\n';
      if (csv) write_csv_row(csv->stream(), summary.frames, r);
      if (annotate) {
        char status[160];
        std::snprintf(status, sizeof(status), "frame %d  %s  %.2f ms  cost %.4f  sim %.3f",
                      summary.frames, r.held ? "HELD" : "tracked", r.total_ms(), r.cost,
                      r.area_similarity);
        emit_annotation(annotate_frame(frame, tracker.debug(), r, status), summary.frames);
      }
      progress.update(summary.frames);
    }
  } catch (...) {
    if (video) {
      video->release();
      std::remove(video_temporary.c_str());
    }
    throw;
  }
  progress.finish(summary.frames);

  if (summary.tracked > 0) {
    const double n = summary.tracked;
    summary.mean_line_ms /= n;
    summary.mean_grouping_ms /= n;
    summary.mean_vertices /= n;
    summary.mean_edges /= n;
    summary.fps = total_ms > 0 ? 1000.0 * n / total_ms : 0.0;
  }
  results.commit();
  if (csv) csv->commit();
  if (video) {
    video->release();
    fs::rename(video_temporary, options.video);
  }
  if (!options.quiet) log << format_summary(summary);
  return summary;
}

std::string format_summary(const TrackSummary& s) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "frames %d (tracked %d, held %d)\n"
                "mean line time %.3f ms, grouping time %.3f ms, %.1f fps\n"
                "mean graph vertices %.1f, edges %.1f\n",
                s.frames, s.tracked, s.held, s.mean_line_ms, s.mean_grouping_ms, s.fps,
                s.mean_vertices, s.mean_edges);
  return text;
}

}  // namespace scbt
