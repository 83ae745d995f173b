// Where frames come from: a video file, a folder of numbered images, or a camera.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace scbt {

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // Reads the next frame into `frame` (8-bit, 1, 3 or 4 channels; 16-bit images are scaled down);
  // false at the end of the input. Throws std::runtime_error naming the frame when a frame exists
  // but cannot be decoded (also a truncated JPEG / PNG, which decoders would fill with grey);
  // reading may go on after that, with the next frame.
  virtual bool read(cv::Mat* frame) = 0;
  // Number of frames when known in advance, else -1 (cameras, some videos).
  virtual int frame_count() const = 0;
  // Frames per second of the input when known, else 0.
  virtual double fps() const { return 0.0; }
  // Human-readable name of the current frame ("0042.jpg", "frame 42").
  virtual std::string current_name() const = 0;
};

// Opens INPUT: an all-digit string is a camera index, a directory is an image folder (numbered
// from 0 or 1), anything else a video file. Throws std::runtime_error with a message naming the
// input on failure.
std::unique_ptr<FrameSource> open_frame_source(const std::string& input);

// The image files of a folder whose names are numbers (e.g. 0001.jpg), sorted by that number.
// Throws std::runtime_error if the folder has none, the numbering has a gap, or an entry named
// like an image (0001.jpg) is not a regular file.
std::vector<std::string> list_numbered_images(const std::string& folder);

// The frames of a given list of image files, in that order (a TUM RGB-D rgb.txt's list).
std::unique_ptr<FrameSource> open_image_list_source(std::vector<std::string> files);

}  // namespace scbt
