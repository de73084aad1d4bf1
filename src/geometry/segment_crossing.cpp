#include "geometry/segment_crossing.hpp"

#include <algorithm>
#include <cstddef>

#include "geometry/exact_sign.hpp"

namespace cardemo {
namespace {

// Lexicographic order (x, then y): along any one line it orders the points as the line does.
bool before(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
}

const Eigen::Vector2d& lower(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return before(v, u) ? v : u;
}

const Eigen::Vector2d& upper(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return before(u, v) ? v : u;
}

}  // namespace

bool segmentsMeet(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& a,
                  const Eigen::Vector2d& b) {
  const int o1 = orientation(a, b, p0);
  const int o2 = orientation(a, b, p1);
  const int o3 = orientation(p0, p1, a);
  const int o4 = orientation(p0, p1, b);
  if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
    // All on one line (or points): the two closed intervals along it overlap.
    const Eigen::Vector2d& start = upper(lower(p0, p1), lower(a, b));
    const Eigen::Vector2d& end = lower(upper(p0, p1), upper(a, b));
    return !before(end, start);
  }
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

bool quadContains(const std::array<Eigen::Vector2d, 4>& corners, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (orientation(corners[i], corners[(i + 1) % corners.size()], p) < 0) return false;
  }
  return true;
}

bool segmentMeetsQuad(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                      const std::array<Eigen::Vector2d, 4>& corners) {
  if (quadContains(corners, p0) || quadContains(corners, p1)) return true;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (segmentsMeet(p0, p1, corners[i], corners[(i + 1) % corners.size()])) return true;
  }
  return false;
}

}  // namespace cardemo
