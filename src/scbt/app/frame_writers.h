// The writers the commands share: the results file, annotated video / frames,
// a raw video of the input, and the progress bar. Each plugs into SequenceRunner.
#pragma once

#include <functional>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/app/progress.h"
#include "scbt/app/sequence_runner.h"
#include "scbt/io/atomic_file.h"

namespace scbt {

// The results: one polygon line per frame from the first initial frame on (a re-initialisation
// replaces that frame's line). With a path, the file is opened at once (so a bad path fails before
// any work) and written on commit(); the lines are kept either way.
class ResultsWriter : public FrameWriter {
 public:
  explicit ResultsWriter(const std::string& path = "");
  void write(const TrackedFrame& frame) override;
  void commit() override;
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::unique_ptr<AtomicFile> file_;
  std::vector<std::string> lines_;
  int first_frame_ = 0;  // frame number of lines_[0]
};

// What happened in a frame, in words, for `scbt track --csv`: capped segments, re-acquired, the
// search step that found the boundary, lost or held and why, boundary vertices outside the frame.
std::string frame_note(const TrackResult& result, const cv::Size& frame_size);

// A video written under a temporary name, opened on the first image and renamed on commit()
// (removed if never committed). The codec follows the extension: .mp4 / .m4v MPEG-4, else MJPG.
class VideoFile {
 public:
  VideoFile(std::string path, double fps);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;
  void write(const cv::Mat& image);
  void commit();

 private:
  struct Writer;
  std::string path_;
  std::string temporary_;
  double fps_;
  std::unique_ptr<Writer> writer_;
  bool committed_ = false;
};

// Annotated frames (segments, graph, boundary and a caption; annotate.h) into a video and/or a
// folder of numbered JPEGs. Initial frames are drawn without debug data, bad frames are skipped.
class AnnotationWriter : public FrameWriter {
 public:
  // The caption of each frame's image.
  using Caption = std::function<std::string(const TrackedFrame&)>;
  // Draws extra content (e.g. the true outline) onto the annotated image.
  using Overlay = std::function<void(const TrackedFrame&, cv::Mat*)>;
  // `tracker` supplies the debug data of the last tracked frame (keep_debug must be on).
  AnnotationWriter(const Tracker* tracker, const std::string& video, double fps,
                   const std::string& frames_dir, Caption caption, Overlay overlay = {});
  void write(const TrackedFrame& frame) override;
  void commit() override;

 private:
  const Tracker* tracker_;
  std::unique_ptr<VideoFile> video_;
  std::string frames_dir_;
  Caption caption_;
  Overlay overlay_;
};

// The input frames as read, into a video (the interactive mode's --save-input).
class InputVideoWriter : public FrameWriter {
 public:
  InputVideoWriter(const std::string& path, double fps) : video_(path, fps) {}
  void write(const TrackedFrame& frame) override;
  void commit() override { video_.commit(); }

 private:
  VideoFile video_;
  int last_frame_ = 0;
};

// Advances a progress bar every `every` frames, counted from the first frame written (a start
// frame); finish() draws the final count.
class ProgressWriter : public FrameWriter {
 public:
  ProgressWriter(std::ostream& log, const std::string& label, int total, bool enabled,
                 int every = 1)
      : bar_(log, label, total, enabled), every_(every) {}
  void write(const TrackedFrame& frame) override;
  void finish() { bar_.finish(frames_); }
  void break_line() { bar_.break_line(); }

 private:
  ProgressBar bar_;
  int every_;
  int first_frame_ = 0;
  int frames_ = 0;
};

}  // namespace scbt
