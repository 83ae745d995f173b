#include "scbt/io/frame_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "scbt/io/bounded_read.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

bool all_digits(const std::string& s) {
  return !s.empty() && s.size() <= 9 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

bool is_image_extension(std::string ext) {
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".jpg" || ext == ".jpeg" || ext == ".png" || ext == ".bmp" || ext == ".tif" ||
         ext == ".tiff" || ext == ".ppm" || ext == ".pgm" || ext == ".webp";
}

// Frames reach the tracker as 8-bit images of 1, 3 or 4 channels: 16-bit images are scaled down
// (65535 -> 255), 2-channel ones keep their first channel; other depths are refused by name.
void normalize_frame(cv::Mat* frame, const std::string& name) {
  if (frame->depth() == CV_16U) {
    frame->convertTo(*frame, CV_8U, 1.0 / 257.0);
  } else if (frame->depth() != CV_8U) {
    throw std::runtime_error(name + ": unsupported pixel depth (only 8- and 16-bit images)");
  }
  if (frame->channels() == 2) cv::extractChannel(*frame, *frame, 0);
  if (frame->channels() != 1 && frame->channels() != 3 && frame->channels() != 4) {
    throw std::runtime_error(name + ": unsupported channel count " +
                             std::to_string(frame->channels()));
  }
}

std::vector<unsigned char> read_file_bytes(const std::string& path) {
  const std::string text = read_file_bounded(path, {kMaxImageFileBytes, "an image file"});
  if (text.empty()) throw std::runtime_error(path + ": empty file");
  return std::vector<unsigned char>(text.begin(), text.end());
}

// Decoders fill a cut-off JPEG or PNG with grey and only warn, so the end markers are checked:
// a JPEG must end with EOI (FF D9, maybe followed by padding), a PNG with its IEND chunk.
bool is_truncated_image(const std::vector<unsigned char>& bytes) {
  const size_t n = bytes.size();
  if (n >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) {
    const size_t from = n > 1024 ? n - 1024 : 2;
    for (size_t i = n - 1; i > from; --i) {
      if (bytes[i - 1] == 0xFF && bytes[i] == 0xD9) return false;
    }
    return true;
  }
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (n >= 8 && std::equal(kPng, kPng + 8, bytes.begin())) {
    static const char kIend[] = "IEND";
    const size_t from = n > 64 ? n - 64 : 8;
    return std::search(bytes.begin() + from, bytes.end(), kIend, kIend + 4) == bytes.end();
  }
  return false;
}

class ImageFolderSource : public FrameSource {
 public:
  explicit ImageFolderSource(std::vector<std::string> files) : files_(std::move(files)) {}

  bool read(cv::Mat* frame) override {
    if (next_ >= files_.size()) return false;
    current_ = next_++;
    const std::string& name = files_[current_];
    const std::vector<unsigned char> bytes = read_file_bytes(name);
    if (is_truncated_image(bytes)) throw std::runtime_error(name + ": truncated image file");
    *frame = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
    if (frame->empty()) throw std::runtime_error(name + ": cannot decode image");
    normalize_frame(frame, files_[current_]);
    return true;
  }
  int frame_count() const override { return static_cast<int>(files_.size()); }
  std::string current_name() const override { return files_[current_]; }

 private:
  std::vector<std::string> files_;
  size_t next_ = 0;
  size_t current_ = 0;
};

class VideoSource : public FrameSource {
 public:
  VideoSource(cv::VideoCapture capture, std::string name, bool is_camera)
      : capture_(std::move(capture)), name_(std::move(name)), is_camera_(is_camera) {}

  // A frame that fails to decode before the announced end is reported (std::runtime_error) and
  // skipped: the next kMaxSkip frames are tried, and each failed one before a good frame is
  // reported in turn. When none of them decodes, the video is taken to end there. A frame the
  // decoder skips silently shows as a jump of the timestamp: reported the same way (see
  // frames_skipped_before).
  bool read(cv::Mat* frame) override {
    if (pending_bad_ > 0) {
      --pending_bad_;
      ++index_;
      throw std::runtime_error(current_name() + ": " + pending_reason_);
    }
    if (!pending_.empty()) {
      *frame = pending_;
      pending_.release();
      ++index_;
      normalize_frame(frame, current_name());
      return true;
    }
    if (capture_.read(*frame) && !frame->empty()) {
      const int skipped = frames_skipped_before();
      if (skipped > 0) {
        pending_ = frame->clone();
        pending_bad_ = skipped - 1;
        pending_reason_ = "skipped by the video decoder (its timestamp jumps past it)";
        ++index_;
        throw std::runtime_error(current_name() + ": " + pending_reason_);
      }
      ++index_;
      normalize_frame(frame, current_name());
      return true;
    }
    const int announced = frame_count();
    if (is_camera_ || announced < 0 || index_ + 1 >= announced) return false;
    constexpr int kMaxSkip = 8;
    for (int failed = 1; failed <= kMaxSkip && index_ + failed < announced; ++failed) {
      if (capture_.read(pending_) && !pending_.empty()) {
        pending_bad_ = failed - 1;
        pending_reason_ = "cannot decode video frame";
        previous_msec_ = capture_.get(cv::CAP_PROP_POS_MSEC);
        ++index_;
        throw std::runtime_error(current_name() + ": " + pending_reason_);
      }
    }
    pending_.release();
    return false;
  }
  int frame_count() const override {
    if (is_camera_) return -1;
    const double count = capture_.get(cv::CAP_PROP_FRAME_COUNT);
    return count > 0 ? static_cast<int>(count) : -1;
  }
  double fps() const override {
    const double fps = capture_.get(cv::CAP_PROP_FPS);
    return fps > 0 ? fps : 0.0;
  }
  std::string current_name() const override { return name_ + " frame " + std::to_string(index_); }

 private:
  // Frames between the previous frame read and the one just read, judged by their timestamps:
  // a gap of k frame periods (rounded; at least 1.5) means k - 1 frames were skipped. Only for
  // files whose frame rate and frame count are known, and never more than the count leaves.
  int frames_skipped_before() {
    const double msec = capture_.get(cv::CAP_PROP_POS_MSEC);
    const double previous = previous_msec_;
    previous_msec_ = msec;
    const double rate = fps();
    const int announced = frame_count();
    if (is_camera_ || rate <= 0 || announced < 0 || index_ == 0) return 0;
    const double periods = (msec - previous) * rate / 1000.0;
    if (!(periods >= 1.5)) return 0;
    const int skipped = static_cast<int>(std::lround(periods)) - 1;
    return std::min(skipped, announced - (index_ + 1));
  }

  mutable cv::VideoCapture capture_;
  std::string name_;
  bool is_camera_;
  int index_ = 0;
  int pending_bad_ = 0;         // failed frames still to report before `pending_`
  std::string pending_reason_;  // why they failed
  cv::Mat pending_;             // a good frame read past failed ones
  double previous_msec_ = 0.0;  // timestamp of the previous frame read
};

}  // namespace

std::vector<std::string> list_numbered_images(const std::string& folder) {
  std::vector<std::pair<long, std::string>> numbered;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const fs::path& path = entry.path();
    if (!is_image_extension(path.extension().string())) continue;
    const std::string stem = path.stem().string();
    if (!all_digits(stem)) continue;
    // A folder (or FIFO, ...) named like a frame would silently shift every later frame.
    if (!entry.is_regular_file()) {
      throw std::runtime_error(path.string() + ": named like a frame but not a regular file");
    }
    numbered.emplace_back(std::stol(stem), path.string());
  }
  if (numbered.empty()) {
    throw std::runtime_error(folder + ": no numbered images (e.g. 0001.jpg) in this folder");
  }
  std::sort(numbered.begin(), numbered.end());
  for (size_t i = 1; i < numbered.size(); ++i) {
    if (numbered[i].first == numbered[i - 1].first) {
      throw std::runtime_error(folder + ": two images numbered " +
                               std::to_string(numbered[i].first));
    }
    if (numbered[i].first != numbered[i - 1].first + 1) {
      throw std::runtime_error(folder + ": image numbering has a gap after " +
                               fs::path(numbered[i - 1].second).filename().string());
    }
  }
  std::vector<std::string> files;
  for (auto& [number, file] : numbered) files.push_back(std::move(file));
  return files;
}

std::unique_ptr<FrameSource> open_image_list_source(std::vector<std::string> files) {
  return std::make_unique<ImageFolderSource>(std::move(files));
}

std::unique_ptr<FrameSource> open_frame_source(const std::string& input) {
  if (all_digits(input) && !fs::exists(input)) {
    cv::VideoCapture camera(std::stoi(input));
    if (!camera.isOpened()) throw std::runtime_error("camera " + input + ": cannot open");
    return std::make_unique<VideoSource>(std::move(camera), "camera " + input, true);
  }
  std::error_code error;
  const fs::file_status status = fs::status(input, error);
  if (error || !fs::exists(status)) throw std::runtime_error(input + ": no such file or folder");
  if (fs::is_directory(status)) {
    std::vector<std::string> files = list_numbered_images(input);
    // The initial polygon is the first frame's: a sequence starting at 0005 has lost frames.
    const std::string first = fs::path(files.front()).stem().string();
    if (std::stol(first) > 1) {
      throw std::runtime_error(input + ": image numbering starts at " +
                               fs::path(files.front()).filename().string() +
                               ", not at 0 or 1 (frames missing?)");
    }
    return std::make_unique<ImageFolderSource>(std::move(files));
  }
  if (!fs::is_regular_file(status)) {
    throw std::runtime_error(input + ": neither a video file, an image folder nor a camera index");
  }
  // The backends that fail to open a file log multi-line warnings of their own; the one-line
  // error below says it all.
  const cv::utils::logging::LogLevel level =
      cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  // File backends only: CAP_ANY would also try the camera ones (gphoto2 scans USB and leaks).
  cv::VideoCapture video(input, cv::CAP_FFMPEG);
  if (!video.isOpened()) video.open(input, cv::CAP_GSTREAMER);
  cv::utils::logging::setLogLevel(level);
  if (!video.isOpened()) throw std::runtime_error(input + ": cannot open as a video");
  return std::make_unique<VideoSource>(std::move(video), fs::path(input).filename().string(),
                                       false);
}

}  // namespace scbt
