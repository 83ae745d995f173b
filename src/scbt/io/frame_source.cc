#include "scbt/io/frame_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

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

class ImageFolderSource : public FrameSource {
 public:
  explicit ImageFolderSource(std::vector<std::string> files) : files_(std::move(files)) {}

  bool read(cv::Mat* frame) override {
    if (next_ >= files_.size()) return false;
    current_ = next_++;
    *frame = cv::imread(files_[current_], cv::IMREAD_UNCHANGED);
    if (frame->empty()) throw std::runtime_error(files_[current_] + ": cannot decode image");
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

  bool read(cv::Mat* frame) override {
    if (!capture_.read(*frame) || frame->empty()) return false;
    ++index_;
    return true;
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
  mutable cv::VideoCapture capture_;
  std::string name_;
  bool is_camera_;
  int index_ = 0;
};

}  // namespace

std::vector<std::string> list_numbered_images(const std::string& folder) {
  std::vector<std::pair<long, std::string>> numbered;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const fs::path& path = entry.path();
    if (!is_image_extension(path.extension().string())) continue;
    const std::string stem = path.stem().string();
    if (!all_digits(stem)) continue;
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
    return std::make_unique<ImageFolderSource>(list_numbered_images(input));
  }
  if (!fs::is_regular_file(status)) {
    throw std::runtime_error(input + ": neither a video file, an image folder nor a camera index");
  }
  cv::VideoCapture video(input);
  if (!video.isOpened()) throw std::runtime_error(input + ": cannot open as a video");
  return std::make_unique<VideoSource>(std::move(video), fs::path(input).filename().string(),
                                       false);
}

}  // namespace scbt
