#include "lab/kernels/manifold2.hpp"

#include <cassert>
#include <cmath>

#include "geometry/finite.hpp"

// Reference face / incident edge / clipping after Erin Catto, "Contact Manifolds" (GDC 2007) and
// Box2D's b2CollidePolygons (v2.x); clipping is Sutherland-Hodgman against the reference face's
// side planes (Ericson, Real-Time Collision Detection, 8.3.4). Own implementation, specialised to
// two boxes: one relative pose, the eight face separations in closed form, and every face normal
// an axis of its box's frame, so each dot product with it is one signed coordinate.

namespace cardemo {
namespace {

// Face k of a box (k*90 degrees from the local +x) has the outward normal sign(k) * e_axis(k).
constexpr int axisOf(int k) {
  return k & 1;
}
constexpr double signOf(int k) {
  return k < 2 ? 1.0 : -1.0;
}

// The pair seen from A's frame and from B's: each centre offset and the relative rotation.
struct PairPose {
  double ta[2];  // B's centre minus A's centre, in A's frame
  double tb[2];  // A's centre minus B's centre, in B's frame
  double c, s;   // B's axis in A's frame is (c, s); B's perp is (-s, c)
};

PairPose pairPose(const Obb2& a, const Obb2& b) {
  // Subtract in double first so that the pair is accurate far from the origin (STYLE 8).
  const double dx = b.center.x() - a.center.x(), dy = b.center.y() - a.center.y();
  const double ax = a.axis.x(), ay = a.axis.y(), bx = b.axis.x(), by = b.axis.y();
  PairPose p;
  p.ta[0] = ax * dx + ay * dy;
  p.ta[1] = ax * dy - ay * dx;
  // A's centre minus B's is exactly -d, so its B-frame coordinates are exactly minus B^T d.
  p.tb[0] = -(bx * dx + by * dy);
  p.tb[1] = -(bx * dy - by * dx);
  p.c = ax * bx + ay * by;
  p.s = ax * by - ay * bx;
  return p;
}

// The separations of the eight faces: 0-3 of A, 4-7 of B. Face k of `self` separates `other` by
// the signed distance of other's nearest point to the face's line (Box2D b2FindMaxSeparation,
// specialised to boxes): sign(k) t[axis(k)] - self's half extent - other's radius on that axis.
// A's axes in B's frame are (c, -s) and (s, c), so both boxes' radii use the same |c| and |s|.
void faceSeparations(const Obb2& a, const Obb2& b, const PairPose& p, double seps[8]) {
  const double ac = std::abs(p.c), as = std::abs(p.s);
  const double rb0 = b.half.x() * ac + b.half.y() * as, rb1 = b.half.x() * as + b.half.y() * ac;
  const double ra0 = a.half.x() * ac + a.half.y() * as, ra1 = a.half.x() * as + a.half.y() * ac;
  seps[0] = p.ta[0] - a.half.x() - rb0;
  seps[1] = p.ta[1] - a.half.y() - rb1;
  seps[2] = -p.ta[0] - a.half.x() - rb0;
  seps[3] = -p.ta[1] - a.half.y() - rb1;
  seps[4] = p.tb[0] - b.half.x() - ra0;
  seps[5] = p.tb[1] - b.half.y() - ra1;
  seps[6] = -p.tb[0] - b.half.x() - ra0;
  seps[7] = -p.tb[1] - b.half.y() - ra1;
}

double margin(const ManifoldSettings& s, double separation) {
  // For penetration (< 0) this is Box2D 2.1's k_relativeTol * sepA + k_absoluteTol rearranged;
  // written with |separation| so that it also asks for a positive margin when apart.
  return (1.0 - s.relative_tolerance) * std::abs(separation) + s.absolute_tolerance;
}

// A face (index) and its separation or dot product (value).
struct Indexed {
  int index;
  double value;
};

// The first of two with the largest value: `later` only where strictly larger.
Indexed firstLargest(Indexed earlier, Indexed later) {
  return later.value > earlier.value ? later : earlier;
}

// The first of two with the smallest value: `later` only where strictly smaller.
Indexed firstSmallest(Indexed earlier, Indexed later) {
  return later.value < earlier.value ? later : earlier;
}

// The first of faces k .. k + 3 with the largest separation, as pairs and then the pairs' winners,
// each carrying its value: what a scan in face order finds, without a chain of loads through the
// index.
Indexed firstLargestOfFour(const double seps[8], int k) {
  return firstLargest(firstLargest({k, seps[k]}, {k + 1, seps[k + 1]}),
                      firstLargest({k + 2, seps[k + 2]}, {k + 3, seps[k + 3]}));
}

// The reference face: A's best face unless B's is clearly better, or the previous face while it
// stays within the margin of the best, so that nearly equal faces do not flip-flop.
int chooseReference(const double seps[8], const ManifoldSettings& settings, int previous) {
  const Indexed best_a = firstLargestOfFour(seps, 0), best_b = firstLargestOfFour(seps, 4);
  const double best = best_b.value > best_a.value ? best_b.value : best_a.value;
  if (previous >= 0 && previous < 8 && seps[previous] >= best - margin(settings, best)) {
    return previous;
  }
  if (best_b.value > best_a.value + margin(settings, best_a.value)) {
    return best_b.index;
  }
  return best_a.index;
}

struct ClipVertex {
  double p[2];  // in the reference box's frame
  int id;       // incident corner 0-3, or 4/5 for a point cut by a side plane
};

// Sutherland-Hodgman for the segment against the half-plane sign * p[axis] <= offset; false when
// nothing is left.
bool clipSegment(ClipVertex seg[2], int axis, double sign, double offset, int clip_id) {
  const double d0 = sign * seg[0].p[axis] - offset;
  const double d1 = sign * seg[1].p[axis] - offset;
  if (d0 > 0.0 && d1 > 0.0) return false;
  if (d0 <= 0.0 && d1 <= 0.0) return true;
  const double r = d0 / (d0 - d1);
  const ClipVertex cut{{seg[0].p[0] + r * (seg[1].p[0] - seg[0].p[0]),
                        seg[0].p[1] + r * (seg[1].p[1] - seg[0].p[1])},
                       clip_id};
  seg[d0 > 0.0 ? 0 : 1] = cut;
  return true;
}

}  // namespace

Manifold2 manifoldObb2(const Obb2& a, const Obb2& b, const ManifoldSettings& settings,
                       int previous_reference_face) {
  assert(inDomain(a) && inDomain(b));
  const PairPose pose = pairPose(a, b);
  double seps[8];
  faceSeparations(a, b, pose, seps);
  // The largest separation as a tree of maxima, three deep instead of a chain of seven: the early
  // out waits on it. Separations are finite (the domain), so only a zero's sign can differ from a
  // scan's, and the comparison below does not see it.
  const auto larger = [](double x, double y) { return x > y ? x : y; };
  const double sat = larger(larger(larger(seps[0], seps[1]), larger(seps[2], seps[3])),
                            larger(larger(seps[4], seps[5]), larger(seps[6], seps[7])));
  Manifold2 m;
  if (sat > settings.max_separation) return m;

  const int face = chooseReference(seps, settings, previous_reference_face);
  const bool flip = face >= 4;
  const Obb2& rbox = flip ? b : a;
  const Obb2& ibox = flip ? a : b;
  // The incident box in the reference box's frame: centre t, axes u and v.
  const double* t = flip ? pose.tb : pose.ta;
  const double s = flip ? -pose.s : pose.s;
  const double u[2] = {pose.c, s}, v[2] = {-s, pose.c};
  const int k = face & 3;
  const int axis = axisOf(k), other_axis = 1 - axis;
  const double sign = signOf(k);

  // Incident face: the incident box's face whose normal (u, v, -u, -v) is most anti-parallel to
  // the reference normal; its dot product with that normal is sign times one coordinate.
  // The first smallest of the four, as pairs and then the pairs' winners (chooseReference's
  // reason).
  const double du = sign * u[axis], dv = sign * v[axis];
  const int j =
      firstSmallest(firstSmallest({0, du}, {1, dv}), firstSmallest({2, -du}, {3, -dv})).index;
  // Its two corners in Obb2::corners() order (face j joins corners j and j+1): corner i is
  // t + sx ex + sy ey with (sx, sy) = (+,-), (+,+), (-,+), (-,-).
  const double ex[2] = {u[0] * ibox.half.x(), u[1] * ibox.half.x()};
  const double ey[2] = {v[0] * ibox.half.y(), v[1] * ibox.half.y()};
  ClipVertex seg[2];
  for (int e = 0; e < 2; ++e) {
    const int corner = (j + e) & 3;
    const double sx = corner < 2 ? 1.0 : -1.0, sy = corner == 0 || corner == 3 ? -1.0 : 1.0;
    seg[e] = {{t[0] + sx * ex[0] + sy * ey[0], t[1] + sx * ex[1] + sy * ey[1]}, corner};
  }

  // Side planes: the reference face runs along its tangent (-n.y, n.x) between the reference
  // box's extents on that axis.
  const double tangent_sign = axis == 0 ? sign : -sign;
  const double side = other_axis == 0 ? rbox.half.x() : rbox.half.y();
  if (!clipSegment(seg, other_axis, -tangent_sign, side, 4) ||
      !clipSegment(seg, other_axis, tangent_sign, side, 5)) {
    return m;
  }

  const double offset = axis == 0 ? rbox.half.x() : rbox.half.y();
  const Eigen::Vector2d& ru = rbox.axis;
  const Eigen::Vector2d rv = rbox.perp();
  const Eigen::Vector2d n_world = sign * (axis == 0 ? ru : rv);
  m.normal = flip ? Eigen::Vector2d(-n_world) : n_world;
  m.reference_face = face;
  for (const ClipVertex& cv : seg) {
    const double sep = sign * cv.p[axis] - offset;
    if (sep > settings.max_separation) continue;
    // Points lie on B's surface: on the incident edge when B is incident, else projected onto B's
    // reference face.
    double q[2] = {cv.p[0], cv.p[1]};
    if (flip) q[axis] -= sep * sign;
    m.points[static_cast<std::size_t>(m.count)] = {rbox.center + ru * q[0] + rv * q[1], sep,
                                                   8 * face + cv.id};
    ++m.count;
  }
  assert(m.normal.allFinite() && (m.count < 1 || m.points[0].point.allFinite()) &&
         (m.count < 2 || m.points[1].point.allFinite()));
  return m;
}

}  // namespace cardemo
