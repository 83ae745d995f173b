#include "scbt/cli/commands.h"

namespace scbt::cli {

void add_tracker_options(CLI::App* command, TrackerOptions* options, std::string* detector_name) {
  command
      ->add_option("--detector", *detector_name,
                   "Line segment detector: edlines (ours), opencv-edlines (OpenCV's EdgeDrawing), "
                   "lsd or fld")
      ->capture_default_str();
  command
      ->add_option("--filter-distance", options->filter_distance,
                   "Keep segments whose mean distance to the previous boundary is below this (px)")
      ->capture_default_str();
  command
      ->add_option("--min-area-similarity", options->min_area_similarity,
                   "Area similarity a candidate must exceed to be chosen (0..1)")
      ->capture_default_str();
  command
      ->add_option("--cost-tolerance", options->cost_tolerance,
                   "Candidates within this fraction of the best cost count as tied; the one "
                   "closest to the previous boundary wins (0: the paper's rule)")
      ->capture_default_str();
  command
      ->add_option("--similarity-exponent", options->similarity_exponent,
                   "Candidates are ranked by cost / similarity^k: a change of area costs "
                   "something, so that a cycle does not creep outward (0: the paper's rule)")
      ->capture_default_str();
  command
      ->add_option("--shape-weight", options->shape_weight,
                   "Candidates are also ranked by exp(w x their change of shape from the recent "
                   "confident boundaries): a leak into the background costs something (0: off)")
      ->capture_default_str();
  command
      ->add_option("--object-memory", options->object_memory,
                   "Remember the object's outline and edges from confident frames; a cycle that "
                   "departs from it along part of it (an occluder, a leak) is replaced by the "
                   "remembered outline fitted to the visible part (true/false)")
      ->capture_default_str();
  command
      ->add_option("--recover-by-motion", options->recover_by_motion,
                   "When lost, search again where image motion moved the boundary (true/false)")
      ->capture_default_str();
  command
      ->add_option("--predict-motion", options->predict_motion,
                   "Search where the boundary's motion predicts it; when nothing passes the area "
                   "gate, also with its predicted growth (true/false)")
      ->capture_default_str();
  command
      ->add_option("--measure-motion", options->measure_motion,
                   "With --predict-motion: the motion is the image motion around the boundary "
                   "(phase correlation), measured when the boundary moves fast; false: its last "
                   "velocity extrapolated (true/false)")
      ->capture_default_str();
  command
      ->add_option("--smooth-noisy-frames", options->smooth_noisy_frames,
                   "Smooth a noisy camera's frames before line detection as their noise calls "
                   "for, with the thresholds lowered accordingly (true/false)")
      ->capture_default_str();
  command
      ->add_option("--fall-back-unmoved", options->fall_back_unmoved,
                   "With --predict-motion: when nothing trusted is found where the motion "
                   "predicts the boundary, search where it was as well (true/false)")
      ->capture_default_str();
  command
      ->add_option("--gate-sustained-shrink", options->gate_sustained_shrink,
                   "With --predict-motion: when the boundary shrinks steadily, the area gate "
                   "compares candidates with its shrunken area; when nothing passes the gate, "
                   "one gate step smaller is searched (true/false)")
      ->capture_default_str();
  command
      ->add_option("--seed-stride", options->bdsp.seed_stride,
                   "BDSP seeds every Nth detected segment (the paper: 2)")
      ->capture_default_str();
  command
      ->add_option("--gradient-threshold", options->detector.gradient_threshold,
                   "EDLines gradient threshold")
      ->capture_default_str();
  command
      ->add_option("--anchor-threshold", options->detector.anchor_threshold,
                   "EDLines anchor threshold")
      ->capture_default_str();
  command
      ->add_option("--normalize-exposure", options->exposure.normalize,
                   "Stretch the grey levels of a frame that spans less than half the 8-bit range "
                   "(dim or low-contrast camera) to half of it before line detection, as far as "
                   "nothing saturates (true/false)")
      ->capture_default_str();
  command
      ->add_option("--adapt-to-blur", options->blur.adapt,
                   "Scale the EDLines thresholds down by the edge spread measured across the "
                   "tracked boundary when it is beyond a focused camera's (defocus, smoothing, "
                   "motion blur) (true/false)")
      ->capture_default_str();
  command
      ->add_option("--min-line-length", options->detector.min_line_length,
                   "Shortest segment kept (px); <= 0: EDLines' own choice")
      ->capture_default_str();
}

}  // namespace scbt::cli
