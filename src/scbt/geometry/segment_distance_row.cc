#include "scbt/geometry/segment_distance_row.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace scbt {

void distance_sq_row_to_segment(const double* x, const double* y, size_t count, const Point& a,
                                const Point& b, double* out) {
  const double ab_x = b.x - a.x, ab_y = b.y - a.y;
  const double length_sq = ab_x * ab_x + ab_y * ab_y;
  size_t s = 0;
  // A zero-length segment takes the scalar path (distance_sq_to_segment's other branch).
#if defined(__SSE2__)
  // GCC does not vectorise the clamp followed by arithmetic (it reports control flow), so the
  // pair loop is written out. The operations are distance_sq_to_segment's, in its order; the
  // clamp is max(0, t) then min(1, .) with the constant first, which returns t for t = -0.0 and
  // NaN as std::clamp does.
  if (length_sq > 0.0) {
    const __m128d a_x = _mm_set1_pd(a.x), a_y = _mm_set1_pd(a.y);
    const __m128d d_x = _mm_set1_pd(ab_x), d_y = _mm_set1_pd(ab_y);
    const __m128d length = _mm_set1_pd(length_sq);
    const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
    for (; s + 2 <= count; s += 2) {
      const __m128d p_x = _mm_loadu_pd(x + s), p_y = _mm_loadu_pd(y + s);
      __m128d t =
          _mm_add_pd(_mm_mul_pd(_mm_sub_pd(p_x, a_x), d_x), _mm_mul_pd(_mm_sub_pd(p_y, a_y), d_y));
      t = _mm_div_pd(t, length);
      t = _mm_min_pd(one, _mm_max_pd(zero, t));
      const __m128d e_x = _mm_sub_pd(p_x, _mm_add_pd(a_x, _mm_mul_pd(t, d_x)));
      const __m128d e_y = _mm_sub_pd(p_y, _mm_add_pd(a_y, _mm_mul_pd(t, d_y)));
      _mm_storeu_pd(out + s, _mm_add_pd(_mm_mul_pd(e_x, e_x), _mm_mul_pd(e_y, e_y)));
    }
  }
#endif
  for (; s < count; ++s) out[s] = distance_sq_to_segment(Point(x[s], y[s]), a, b);
}

}  // namespace scbt
