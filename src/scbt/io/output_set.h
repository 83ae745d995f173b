// The outputs of one run, prepared before the first frame and committed together: only when
// every one of them is complete does any of them replace an old file; on any failure none does
// and no temporary file is left (OutputFile explains how each kind of path is written).
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scbt/io/output_file.h"

namespace scbt {

// An annotated video. The container follows the extension (.avi, .mkv: MJPG; .mp4, .m4v: MPEG-4).
class VideoOutput {
 public:
  // Classifies `path` now; throws std::invalid_argument for an extension that names no video
  // container and std::runtime_error for a path that cannot be written.
  VideoOutput(std::string path, double fps);
  ~VideoOutput();
  VideoOutput(const VideoOutput&) = delete;
  VideoOutput& operator=(const VideoOutput&) = delete;

  // Opens the writer on the first frame (the size is known then). Throws std::runtime_error.
  void write(const cv::Mat& frame);
  int frames() const { return frames_; }
  // Closes the writer and, for a regular file, reads the finished file's frame count back:
  // OpenCV's writer reports no error of its own (a full disk gave half a video and exit 0).
  void finish();
  void publish();

 private:
  OutputTarget target_;
  std::string temporary_;
  std::string writer_path_;
  double fps_;
  cv::VideoWriter writer_;
  int frames_ = 0;
  bool published_ = false;
};

// A folder of annotated frames NNNN.jpg: each written to a temporary name, renamed on publish.
class FrameFolderOutput {
 public:
  // Creates the folder if needed. Throws std::runtime_error when it is a file or cannot be made.
  explicit FrameFolderOutput(std::string folder);
  ~FrameFolderOutput();
  FrameFolderOutput(const FrameFolderOutput&) = delete;
  FrameFolderOutput& operator=(const FrameFolderOutput&) = delete;

  void write(int index, const cv::Mat& image);
  void finish() {}
  void publish();

 private:
  std::string folder_;
  bool created_ = false;
  std::vector<std::pair<std::string, std::string>> pending_;  // temporary, final
  bool published_ = false;
};

class OutputSet {
 public:
  OutputFile& add_file(const std::string& path);
  VideoOutput& add_video(const std::string& path, double fps);
  FrameFolderOutput& add_frame_folder(const std::string& folder);

  // After each frame: live outputs (standard output, FIFOs, devices) get their lines now.
  void end_record();
  // True once the reader of a streamed output has gone (EPIPE).
  bool reader_gone() const;
  // Finishes every output, then publishes them all; throws on the first failure, before any
  // old file is replaced (the destructors then remove the temporary files).
  void commit();

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
  std::vector<std::unique_ptr<VideoOutput>> videos_;
  std::vector<std::unique_ptr<FrameFolderOutput>> frame_folders_;
};

}  // namespace scbt
