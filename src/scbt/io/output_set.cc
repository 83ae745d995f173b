#include "scbt/io/output_set.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace scbt {
namespace fs = std::filesystem;
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The codec for a container named by its extension; 0 when the extension names none.
int video_fourcc(const std::string& ext) {
  if (ext == ".avi" || ext == ".mkv") return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
  if (ext == ".mp4" || ext == ".m4v") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return 0;
}

// Sends this process's stderr to /dev/null for its lifetime: FFmpeg prints its decoder's
// complaints about a cut-off file ("overread") past OpenCV's log level, and the one error line
// that follows says it all.
class QuietStderr {
 public:
  QuietStderr() : saved_(::dup(STDERR_FILENO)) {
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    if (saved_ < 0) return;
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_;
};

}  // namespace

VideoOutput::VideoOutput(std::string path, double fps) : fps_(fps > 0 ? fps : 30.0) {
  if (path == "-" || video_fourcc(lower_extension(path)) == 0) {
    throw std::invalid_argument("--video " + printable(path) +
                                ": the file name must end in .avi, .mkv, .mp4 or .m4v (the "
                                "container follows the extension)");
  }
  target_ = classify_output(path);
  if (target_.kind == OutputKind::kInPlace) {
    // Written through the name given (it carries the extension the writer needs); absolute, so
    // the writer cannot take a "name:" prefix for a protocol.
    writer_path_ = fs::absolute(path).string();
    return;
  }
  const int fd =
      create_temporary_sibling(target_.target, lower_extension(path), target_.path, &temporary_);
  try {
    copy_permissions(fd, target_);
  } catch (...) {
    ::close(fd);
    ::unlink(temporary_.c_str());
    throw;
  }
  ::close(fd);  // the name stays reserved; the writer reopens it
  writer_path_ = fs::absolute(temporary_).string();
}

VideoOutput::~VideoOutput() {
  if (writer_.isOpened()) writer_.release();
  if (!published_ && !temporary_.empty()) ::unlink(temporary_.c_str());
}

void VideoOutput::write(const cv::Mat& frame) {
  if (!writer_.isOpened()) {
    if (frames_ > 0) throw std::runtime_error(printable(target_.path) + ": video writer closed");
    // The FFmpeg backend only: others would read a "%d" in the name as an image sequence.
    const cv::utils::logging::LogLevel level =
        cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    writer_.open(writer_path_, cv::CAP_FFMPEG, video_fourcc(lower_extension(target_.path)), fps_,
                 frame.size());
    cv::utils::logging::setLogLevel(level);
    if (!writer_.isOpened()) {
      throw std::runtime_error(printable(target_.path) + ": cannot write video");
    }
  }
  writer_.write(frame);
  ++frames_;
}

void VideoOutput::finish() {
  if (writer_.isOpened()) writer_.release();
  if (temporary_.empty() || frames_ == 0) return;
  const cv::utils::logging::LogLevel level =
      cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  const QuietStderr quiet;
  // The count comes from the header, which is patched last and may be complete when the frames
  // are not: the last frame must also be there to read.
  cv::VideoCapture check(writer_path_, cv::CAP_FFMPEG);
  const int found = check.isOpened() ? static_cast<int>(check.get(cv::CAP_PROP_FRAME_COUNT)) : 0;
  cv::Mat last;
  const bool last_readable = found == frames_ && check.set(cv::CAP_PROP_POS_FRAMES, frames_ - 1) &&
                             check.read(last) && !last.empty();
  cv::utils::logging::setLogLevel(level);
  if (found != frames_) {
    throw std::runtime_error(printable(target_.path) + ": write failed: the finished video holds " +
                             std::to_string(found) + " of " + std::to_string(frames_) +
                             " frames (disk full?)");
  }
  if (!last_readable) {
    throw std::runtime_error(printable(target_.path) +
                             ": write failed: the finished video's last " + "frame (" +
                             std::to_string(frames_) + ") cannot be read back (disk full?)");
  }
}

void VideoOutput::publish() {
  if (published_ || temporary_.empty()) return;
  if (frames_ == 0) {
    // No frame was written (a run stopped before any): an empty file is no video.
    ::unlink(temporary_.c_str());
    published_ = true;
    return;
  }
  if (std::rename(temporary_.c_str(), target_.target.c_str()) != 0) {
    throw std::runtime_error(
        printable(target_.path) +
        ": cannot move the finished video into place: " + std::strerror(errno));
  }
  published_ = true;
}

FrameFolderOutput::FrameFolderOutput(std::string folder) : folder_(std::move(folder)) {
  std::error_code error;
  const fs::file_status status = fs::status(folder_, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) {
      throw std::runtime_error(printable(folder_) + ": exists and is not a folder");
    }
    return;
  }
  if (!fs::create_directories(folder_, error) || error) {
    throw std::runtime_error(printable(folder_) + ": cannot create the folder: " + error.message());
  }
  created_ = true;
}

FrameFolderOutput::~FrameFolderOutput() {
  if (published_) return;
  for (const auto& [temporary, final_name] : pending_) ::unlink(temporary.c_str());
  if (created_) ::rmdir(folder_.c_str());  // only if still empty
}

void FrameFolderOutput::write(int index, const cv::Mat& image) {
  char name[32];
  std::snprintf(name, sizeof(name), "%04d.jpg", index);
  const std::string final_name = (fs::path(folder_) / name).string();
  std::string temporary;
  const int fd = create_temporary_sibling(final_name, ".jpg", final_name, &temporary);
  pending_.emplace_back(temporary, final_name);
  // Encoded here and written through the descriptor, so that a failure has its reason (errno).
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".jpg", image, bytes)) {
    ::close(fd);
    throw std::runtime_error(printable(final_name) + ": cannot encode the image as JPEG");
  }
  const unsigned char* next = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, next, left);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) {
      const int error = errno;
      ::close(fd);
      throw std::runtime_error(printable(final_name) + ": write failed: " + std::strerror(error));
    }
    next += written;
    left -= static_cast<std::size_t>(written);
  }
  if (::close(fd) != 0) {
    throw std::runtime_error(printable(final_name) + ": write failed: " + std::strerror(errno));
  }
}

void FrameFolderOutput::publish() {
  for (const auto& [temporary, final_name] : pending_) {
    if (std::rename(temporary.c_str(), final_name.c_str()) != 0) {
      throw std::runtime_error(printable(final_name) +
                               ": cannot move into place: " + std::strerror(errno));
    }
  }
  published_ = true;
}

OutputFile& OutputSet::add_file(const std::string& path) {
  files_.push_back(std::make_unique<OutputFile>(path));
  return *files_.back();
}

VideoOutput& OutputSet::add_video(const std::string& path, double fps) {
  videos_.push_back(std::make_unique<VideoOutput>(path, fps));
  return *videos_.back();
}

FrameFolderOutput& OutputSet::add_frame_folder(const std::string& folder) {
  frame_folders_.push_back(std::make_unique<FrameFolderOutput>(folder));
  return *frame_folders_.back();
}

void OutputSet::end_record() {
  for (auto& file : files_) file->end_record();
}

bool OutputSet::reader_gone() const {
  return std::any_of(files_.begin(), files_.end(),
                     [](const auto& file) { return file->reader_gone(); });
}

void OutputSet::commit() {
  for (auto& file : files_) file->finish();
  for (auto& video : videos_) video->finish();
  for (auto& folder : frame_folders_) folder->finish();
  for (auto& file : files_) file->publish();
  for (auto& video : videos_) video->publish();
  for (auto& folder : frame_folders_) folder->publish();
}

}  // namespace scbt
