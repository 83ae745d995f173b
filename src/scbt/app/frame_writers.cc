#include "scbt/app/frame_writers.h"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "scbt/geometry/polygon_io.h"
#include "scbt/render/annotate.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

int video_fourcc(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".mp4" || ext == ".m4v") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
}

}  // namespace

ResultsWriter::ResultsWriter(const std::string& path) {
  if (!path.empty()) file_ = std::make_unique<AtomicFile>(path);
}

void ResultsWriter::write(const TrackedFrame& frame) {
  if (lines_.empty()) first_frame_ = frame.number;
  const size_t index = static_cast<size_t>(frame.number - first_frame_);
  if (index >= lines_.size()) lines_.resize(index + 1);
  lines_[index] = format_polygon_line(frame.result->boundary);
}

void ResultsWriter::commit() {
  if (!file_) return;
  for (const std::string& line : lines_) file_->stream() << line << '\n';
  file_->commit();
}

std::string frame_note(const TrackResult& r, const cv::Size& size) {
  std::string note;
  auto add = [&note](const std::string& text) { note += (note.empty() ? "" : "; ") + text; };
  if (r.num_dropped > 0) {
    add("segments capped: " + std::to_string(r.num_dropped) + " of " +
        std::to_string(r.num_kept + r.num_dropped) + " near the boundary dropped");
  }
  if (r.reacquired) add("re-acquired: the lost object was found again");
  if (r.step != SearchStep::kNone) add(std::string("step: ") + step_name(r.step));
  if (r.state == TrackState::kLost) {
    add("lost: the last confident boundary is repeated");
  } else if (r.held) {
    if (r.num_detected == 0) {
      add("held: no segments detected");
    } else if (r.num_kept == 0) {
      add("held: no segments near the boundary");
    } else if (r.num_candidates == 0) {
      add("held: no closed cycle among the segments");
    } else {
      add("held: every candidate rejected");
    }
  }
  int outside = 0;
  for (const Point& p : r.boundary) {
    outside += (p.x < 0 || p.y < 0 || p.x > size.width || p.y > size.height) ? 1 : 0;
  }
  if (outside > 0) add(std::to_string(outside) + " boundary vertices outside the frame");
  return note;
}

struct VideoFile::Writer {
  cv::VideoWriter video;
};

VideoFile::VideoFile(std::string path, double fps) : path_(std::move(path)), fps_(fps) {
  // The writer picks its container from the extension, so the temporary keeps it.
  const fs::path p(path_);
  temporary_ = (p.parent_path() / (".tmp-" + p.filename().string())).string();
}

VideoFile::~VideoFile() {
  if (writer_ && !committed_) {
    writer_->video.release();
    std::remove(temporary_.c_str());
  }
}

void VideoFile::write(const cv::Mat& image) {
  if (!writer_) {
    writer_ = std::make_unique<Writer>();
    if (!writer_->video.open(temporary_, video_fourcc(path_), fps_, image.size(),
                             image.channels() != 1)) {
      throw std::runtime_error(path_ + ": cannot write video");
    }
  }
  writer_->video.write(image);
}

void VideoFile::commit() {
  if (!writer_ || committed_) return;
  writer_->video.release();
  fs::rename(temporary_, path_);
  committed_ = true;
}

AnnotationWriter::AnnotationWriter(const Tracker* tracker, const std::string& video, double fps,
                                   const std::string& frames_dir, Caption caption, Overlay overlay)
    : tracker_(tracker),
      frames_dir_(frames_dir),
      caption_(std::move(caption)),
      overlay_(std::move(overlay)) {
  if (!video.empty()) video_ = std::make_unique<VideoFile>(video, fps);
}

void AnnotationWriter::write(const TrackedFrame& frame) {
  if (!frame.bad.empty()) return;
  static const TrackDebug kNoDebug;
  cv::Mat image = annotate_frame(*frame.image, frame.initial ? kNoDebug : tracker_->debug(),
                                 *frame.result, caption_(frame));
  if (overlay_) overlay_(frame, &image);
  if (video_) video_->write(image);
  if (!frames_dir_.empty()) {
    if (frame.initial) fs::create_directories(frames_dir_);
    char name[32];
    std::snprintf(name, sizeof(name), "%04d.jpg", frame.number);
    const std::string path = (fs::path(frames_dir_) / name).string();
    if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write image");
  }
}

void AnnotationWriter::commit() {
  if (video_) video_->commit();
}

void InputVideoWriter::write(const TrackedFrame& frame) {
  // A re-initialisation shows no new frame.
  if (frame.number == last_frame_) return;
  last_frame_ = frame.number;
  video_.write(*frame.image);
}

void ProgressWriter::write(const TrackedFrame& frame) {
  if (first_frame_ == 0) first_frame_ = frame.number;
  frames_ = frame.number - first_frame_ + 1;
  if (frames_ % every_ == 0) bar_.update(frames_);
}

}  // namespace scbt
