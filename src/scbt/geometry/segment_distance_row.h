// Squared distances from many points to one segment, the inner loop of the boundary distances
// between a fixed boundary and many candidate cycles (choice/boundary_distance_cache.h).
#pragma once

#include <cstddef>

#include "scbt/geometry/polygon.h"

namespace scbt {

// out[s] = distance_sq_to_segment({x[s], y[s]}, a, b) for s < count, equal to the last bit.
// The points come as two coordinate arrays so that two are done at once; `out` must not
// overlap them.
void distance_sq_row_to_segment(const double* x, const double* y, size_t count, const Point& a,
                                const Point& b, double* out);

}  // namespace scbt
