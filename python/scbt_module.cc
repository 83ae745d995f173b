// The `scbt` Python module: the salient closed boundary tracker, its stages and the E_AL metric.
// Frames are numpy uint8 arrays as OpenCV's Python bindings give them, wrapped in cv::Mat headers
// without copying whenever their rows are compact; polygons and segments are float64 arrays.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "depth_bindings.h"
#include "options_bindings.h"
#include "scbt/version.h"

PYBIND11_MODULE(scbt, m) {
  using namespace scbt;
  m.doc() =
      "Real-time salient closed boundary tracking via line segment perceptual grouping "
      "(Qin et al., IROS 2017).\n\n"
      "Frames are numpy uint8 arrays of shape (H, W), (H, W, 1), (H, W, 3) (BGR) or (H, W, 4) "
      "(BGRA), as cv2 returns them; they are read in place when their rows are compact. "
      "Polygons are (N, 2) float arrays of x, y pixel coordinates; segments are (M, 4) float "
      "arrays of x1, y1, x2, y2. Bad options raise ValueError, wrong types TypeError.";
  m.attr("__version__") = SCBT_VERSION;

  register_options(m);
  register_tracker(m);
  register_stages(m);
  register_geometry(m);
  register_depth(m);
}
