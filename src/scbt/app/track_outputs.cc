#include "scbt/app/track_outputs.h"

#include <cstdio>
#include <vector>

#include "scbt/app/frame_writers.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/printable.h"
#include "scbt/io/same_file.h"
#include "scbt/render/annotate.h"

namespace scbt {
namespace {

void write_csv_header(std::ostream& csv) {
  csv << "frame,held,state,confidence,visible,cost,area_similarity,detected,kept,vertices,edges,"
         "candidates,line_ms,grouping_ms,total_ms,note\n";
}

void write_csv_row(std::ostream& csv, int frame, const TrackResult& r, const std::string& note) {
  char line[256];
  std::snprintf(line, sizeof(line), "%d,%d,%s,%.4f,%.4f,%.6g,%.6g,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,",
                frame, r.held ? 1 : 0, to_string(r.state).c_str(), r.confidence, r.visible, r.cost,
                r.area_similarity, r.num_detected, r.num_kept, r.num_vertices, r.num_edges,
                r.num_candidates, r.line_ms, r.grouping_ms, r.total_ms());
  csv << line << csv_field(note) << '\n';
}

// The caption of an annotated frame: number, state, confidence, time and the chosen cycle.
std::string frame_caption(int frame_number, const TrackResult& r) {
  char status[200];
  std::snprintf(status, sizeof(status), "frame %d  %s%s  conf %.2f  %.2f ms  cost %.4f  sim %.3f",
                frame_number, to_string(r.state).c_str(), r.reacquired ? " (re-acquired)" : "",
                r.confidence, r.total_ms(), r.cost, r.area_similarity);
  return status;
}

}  // namespace

TrackOutputs::TrackOutputs(const TrackRunOptions& options, double fps, const Tracker* tracker)
    : tracker_(tracker) {
  if (!options.output.empty()) results_ = &set_.add_file(options.output);
  if (!options.csv.empty()) csv_ = &set_.add_file(options.csv);
  if (!options.video.empty()) video_ = &set_.add_video(options.video, fps);
  if (!options.frames_out.empty()) frames_out_ = &set_.add_frame_folder(options.frames_out);
  if (options.depth.enabled()) depth_ = std::make_unique<DepthTrackOutput>(options.depth, &set_);
}

void TrackOutputs::write(const TrackedFrame& frame) {
  const TrackResult& r = *frame.result;
  const int number = frame.number;
  if (csv_ && frame.initial) write_csv_header(csv_->stream());
  if (results_) results_->stream() << format_polygon_line(r.boundary) << '\n';
  if (csv_ && !frame.initial) {
    write_csv_row(
        csv_->stream(), number, r,
        frame.bad.empty() ? frame_note(r, frame.image->size()) : "bad frame: " + frame.bad);
  }
  const bool seen = frame.bad.empty();
  if (depth_) depth_->write(number, seen ? &r : nullptr, frame.image->size());
  if (annotate() && frame.initial) {
    write_image(annotate_frame(*frame.image, {}, r,
                               "frame " + std::to_string(number) + ": initial boundary"),
                number);
  } else if (annotate() && seen) {
    write_image(annotate_frame(*frame.image, tracker_->debug(), r, frame_caption(number, r)),
                number);
  }
  set_.end_record();
}

void TrackOutputs::write_image(cv::Mat image, int frame_number) {
  if (depth_) depth_->draw(&image);
  if (video_) video_->write(image);
  if (frames_out_) frames_out_->write(frame_number, image);
}

void check_track_paths(const TrackRunOptions& options) {
  std::vector<NamedPath> inputs = {{"INPUT", options.input}};
  if (!options.init_file.empty()) inputs.push_back({"--init", options.init_file});
  std::vector<NamedPath> outputs;
  if (!options.output.empty()) outputs.push_back({"-o", options.output});
  if (!options.csv.empty()) outputs.push_back({"--csv", options.csv});
  if (!options.video.empty()) outputs.push_back({"--video", options.video});
  std::vector<NamedPath> output_folders;
  if (!options.frames_out.empty()) output_folders.push_back({"--frames-out", options.frames_out});
  add_depth_paths(options.depth, &inputs, &outputs);
  check_no_overwrite(inputs, outputs, output_folders);
}

}  // namespace scbt
