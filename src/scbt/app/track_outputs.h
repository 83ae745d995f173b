// The outputs of `scbt track` as one writer of the sequence runner: the results file, the CSV,
// the annotated video and frames and the 3-D outputs, all in one OutputSet (io/output_set.h):
// streamed outputs get each frame as it is tracked, files are replaced only on commit().
#pragma once

#include <memory>
#include <string>

#include "scbt/app/sequence_runner.h"
#include "scbt/app/track_depth.h"
#include "scbt/app/track_run.h"
#include "scbt/io/output_set.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

class TrackOutputs : public FrameWriter {
 public:
  // Opens every output before the first frame (a folder, a missing folder or a video name
  // without a container fails here). `tracker` supplies the debug data of annotated frames.
  TrackOutputs(const TrackRunOptions& options, double fps, const Tracker* tracker);

  // Whether annotated frames are written (the tracker must then keep its debug data).
  bool annotate() const { return video_ != nullptr || frames_out_ != nullptr; }
  bool reader_gone() const { return set_.reader_gone(); }

  // The initial frame: its line, 3-D row and image (no CSV row: nothing was tracked). A tracked
  // frame: its line, CSV row, 3-D row and image; a bad one (the tracker did not see it) has no
  // 3-D and no image.
  void write(const TrackedFrame& frame) override;
  void commit() override { set_.commit(); }

 private:
  void write_image(cv::Mat image, int frame_number);

  const Tracker* tracker_;
  OutputSet set_;
  OutputFile* results_ = nullptr;
  OutputFile* csv_ = nullptr;
  VideoOutput* video_ = nullptr;
  FrameFolderOutput* frames_out_ = nullptr;
  std::unique_ptr<DepthTrackOutput> depth_;
};

// No output may overwrite an input or another output: checked before anything is read or
// written (std::invalid_argument naming both paths).
void check_track_paths(const TrackRunOptions& options);

}  // namespace scbt
