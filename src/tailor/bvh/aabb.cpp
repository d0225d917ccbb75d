#include "tailor/bvh/aabb.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace tailor {

void swept_face_boxes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                      std::span<Aabb> boxes) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(faces.rows()), 4096),
                    [&](const tbb::blocked_range<Index>& range) {
                      for (Index f = range.begin(); f < range.end(); ++f) {
                        boxes[static_cast<std::size_t>(f)] =
                            swept_box(x0, x1, {faces(f, 0), faces(f, 1), faces(f, 2)});
                      }
                    });
}

}  // namespace tailor
