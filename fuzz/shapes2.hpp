#pragma once
/// Decodes fuzz bytes into 2D SAT pairs: boxes and convex polygons, placed apart, touching or
/// overlapping. In-domain pairs are what the accuracy contract covers (sizes 1 cm to 100 m,
/// coordinates up to 1e7 m); "wild" pairs are anything the parsers accept (up to 1e9 m, any
/// positive size), for which only finiteness is promised.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "byte_reader.hpp"
#include "geometry/angle.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"

namespace cardemo::fuzz {

/// One side of a 2D pair: a box or a convex polygon.
struct Shape2 {
  bool is_box = true;     ///< Which member is used.
  Obb2 box;               ///< The box, when is_box.
  ConvexPolygon poly;     ///< The polygon, when !is_box.
  bool in_domain = true;  ///< Inside the accuracy contract's domain.

  /// The shape as a polygon (a box's corners, rounded to double).
  [[nodiscard]] ConvexPolygon asPolygon() const {
    return is_box ? ConvexPolygon::fromObb(box) : poly;
  }
  /// Its vertices.
  [[nodiscard]] std::vector<Eigen::Vector2d> points() const {
    const ConvexPolygon p = asPolygon();
    return {p.vertices.begin(), p.vertices.begin() + p.count};
  }
  /// A point of the shape to measure from (box centre, first vertex).
  [[nodiscard]] Eigen::Vector2d anchor() const { return is_box ? box.center : poly.vertex(0); }
  /// Moves the shape by `t`, metres.
  void translate(const Eigen::Vector2d& t) {
    if (is_box) {
      box.center += t;
    } else {
      for (int i = 0; i < poly.count; ++i) poly.vertices[static_cast<std::size_t>(i)] += t;
    }
  }
  /// Rebuilds a polygon from its (moved) vertices: false when rounding made it invalid.
  [[nodiscard]] bool revalidate() {
    if (is_box) return true;
    const std::vector<Eigen::Vector2d> p = points();
    auto rebuilt = ConvexPolygon::fromPoints(p);
    if (!rebuilt) return false;
    poly = *rebuilt;
    return true;
  }
  /// Outward unit normals of its edges (a box: its four face normals).
  [[nodiscard]] std::vector<Eigen::Vector2d> edgeNormals() const {
    if (is_box) return {box.axis, box.perp(), -box.axis, -box.perp()};
    std::vector<Eigen::Vector2d> normals;
    for (int i = 0; i < poly.count; ++i) {
      const Eigen::Vector2d e = poly.vertex((i + 1) % poly.count) - poly.vertex(i);
      normals.emplace_back(Eigen::Vector2d(e.y(), -e.x()).normalized());
    }
    return normals;
  }
  /// Full precision description for failure messages (paste into a test to reproduce).
  [[nodiscard]] std::string describe() const {
    std::ostringstream out;
    out.precision(17);
    if (is_box) {
      out << "box center (" << box.center.x() << ", " << box.center.y() << ") axis ("
          << box.axis.x() << ", " << box.axis.y() << ") half (" << box.half.x() << ", "
          << box.half.y() << ")";
    } else {
      out << "polygon";
      for (int i = 0; i < poly.count; ++i) {
        out << " (" << poly.vertex(i).x() << ", " << poly.vertex(i).y() << ")";
      }
    }
    return out.str();
  }
};

/// Largest (p - from) . d over the points.
inline double maxAlong(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& d,
                       const Eigen::Vector2d& from) {
  double best = -INFINITY;
  for (const Eigen::Vector2d& p : points) best = std::max(best, (p - from).dot(d));
  return best;
}

/// Signed gap from A to B along `d` (min of B minus max of A), measured from `ref`.
inline double gapAlong(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b,
                       const Eigen::Vector2d& d, const Eigen::Vector2d& ref) {
  return -maxAlong(b, -d, ref) - maxAlong(a, d, ref);
}

/// Smallest width of a convex polygon (min over edges of the farthest vertex from the edge line;
/// the minimum width is always attained flush with an edge), metres.
inline double minWidth(const ConvexPolygon& p) {
  double width = INFINITY;
  for (int i = 0; i < p.count; ++i) {
    const Eigen::Vector2d e = p.vertex((i + 1) % p.count) - p.vertex(i);
    const Eigen::Vector2d n = Eigen::Vector2d(e.y(), -e.x()).normalized();
    double farthest = 0.0;
    for (int j = 0; j < p.count; ++j)
      farthest = std::max(farthest, -(p.vertex(j) - p.vertex(i)).dot(n));
    width = std::min(width, farthest);
  }
  return width;
}

/// Decodes shapes and pairs from fuzz bytes.
class ShapeDecoder2 {
 public:
  /// Decodes from `in`; `wild` selects the parser-accepted domain instead of the contract's.
  ShapeDecoder2(ByteReader& in, bool wild) : in_(in), wild_(wild) {}

  /// A centre near the origin, anywhere up to 1e7 m, or on a dyadic grid far out (exact sums).
  Eigen::Vector2d center() {
    if (wild_) return {wildCoordinate(), wildCoordinate()};
    switch (in_.pick(3)) {
      case 0:
        return {in_.range(-100.0, 100.0), in_.range(-100.0, 100.0)};
      case 1: {
        const Eigen::Vector2d direction =
            unitFromRadians(in_.range(-std::numbers::pi, std::numbers::pi));
        return direction * in_.logRange(1.0, 1e7);
      }
      default:
        return {in_.dyadic(4e6, 8e6), in_.dyadic(4e6, 8e6)};
    }
  }

  /// A unit heading: exact quarter turns, any angle, or within 1e-15..1e-3 rad of a quarter turn.
  Eigen::Vector2d axis() {
    if (wild_) return unitFromDegrees(in_.signedLog(1e-300, 1e9));
    const int quarter = in_.pick(4);
    switch (in_.pick(3)) {
      case 0:
        return unitFromDegrees(90.0 * quarter);
      case 1:
        return unitFromDegrees(in_.range(-180.0, 180.0));
      default:
        return unitFromRadians(quarter * 0.5 * std::numbers::pi + in_.signedLog(1e-15, 1e-3));
    }
  }

  /// Half extent: 5 mm to 50 m (sizes 1 cm to 100 m), often exactly at an end.
  double half() {
    // Wild: down to the smallest denormal; a parsed size of 5e-324 m halves to exactly 0.
    if (wild_) return in_.pick(16) == 0 ? 0.0 : in_.logRange(4.9406564584124654e-324, 5e8);
    switch (in_.pick(4)) {
      case 0:
        return 0.005;
      case 1:
        return 50.0;
      default:
        return in_.logRange(0.005, 50.0);
    }
  }

  /// A box centred at `c`.
  Shape2 box(const Eigen::Vector2d& c) {
    Shape2 s;
    s.is_box = true;
    s.box.center = c;
    s.box.axis = axis();
    s.box.half = {half(), half()};
    s.in_domain = !wild_;
    return s;
  }

  /// A convex polygon of 3..16 vertices around `c` (an ellipse sampled at random or regular angles,
  /// optionally snapped to a 2^-10 m grid), or nullopt when the points do not make a valid one.
  std::optional<Shape2> polygon(const Eigen::Vector2d& c) {
    const int n = 3 + in_.pick(ConvexPolygon::kMaxVertices - 2);
    const int mode = in_.pick(3);
    const double rx = half(), ry = half();
    const Eigen::Vector2d u = axis();
    std::vector<double> angles(static_cast<std::size_t>(n));
    const double start = in_.range(0.0, 2.0 * std::numbers::pi);
    for (std::size_t i = 0; i < angles.size(); ++i) {
      if (mode == 1) {
        angles[i] = start + 2.0 * std::numbers::pi * static_cast<double>(i) / n;
      } else {
        const double coarse = 2.0 * std::numbers::pi * in_.byte() / 256.0;
        angles[i] = coarse + in_.range(0.0, 0.02);
      }
    }
    std::sort(angles.begin(), angles.end());
    std::vector<Eigen::Vector2d> points;
    for (const double t : angles) {
      const Eigen::Vector2d e{rx * std::cos(t), ry * std::sin(t)};
      Eigen::Vector2d offset(u.x() * e.x() - u.y() * e.y(), u.y() * e.x() + u.x() * e.y());
      if (mode == 2) offset = (offset * 1024.0).array().round() / 1024.0;
      points.push_back(c + offset);
    }
    if ((in_.byte() & 1) != 0) std::reverse(points.begin(), points.end());
    auto poly = ConvexPolygon::fromPoints(points);
    if (!poly) return std::nullopt;
    Shape2 s;
    s.is_box = false;
    s.poly = *poly;
    // The contract's sizes: no thinner than 1 cm, no larger than 100 m.
    const Aabb2 bounds = poly->aabb();
    s.in_domain =
        !wild_ && minWidth(*poly) >= 0.01 && (bounds.max - bounds.min).maxCoeff() <= 100.0;
    return s;
  }

  /// A shape of the requested kind at `c`.
  std::optional<Shape2> shape(bool is_box, const Eigen::Vector2d& c) {
    if (is_box) return box(c);
    return polygon(c);
  }

  /// Moves B (built around the origin) next to A: at random nearby, or at a chosen signed gap
  /// (0, or 1e-12..10 m either way) along one of A's or B's edge normals or any direction, with
  /// a lateral offset.
  void place(const Shape2& a, Shape2& b) {
    const Eigen::Vector2d ref = a.anchor();
    const int mode = in_.pick(4);
    if (mode == 0) {
      b.translate(ref + (wild_ ? Eigen::Vector2d{wildCoordinate(), wildCoordinate()}
                               : Eigen::Vector2d{in_.range(-150, 150), in_.range(-150, 150)}));
      return;
    }
    Eigen::Vector2d d;
    if (mode == 1) {
      const auto normals = a.edgeNormals();
      d = normals[static_cast<std::size_t>(in_.pick(static_cast<int>(normals.size())))];
    } else if (mode == 2) {
      const auto normals = b.edgeNormals();
      d = -normals[static_cast<std::size_t>(in_.pick(static_cast<int>(normals.size())))];
    } else {
      d = unitFromRadians(in_.range(-std::numbers::pi, std::numbers::pi));
    }
    const double gap = in_.pick(4) == 0 ? 0.0 : in_.signedLog(1e-12, 10.0);
    const Eigen::Vector2d lateral{-d.y(), d.x()};
    const auto pa = a.points(), pb = b.points();
    const Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    const double reach = maxAlong(pa, d, ref) + maxAlong(pb, -d, origin);
    const double room = maxAlong(pa, lateral, ref);
    b.translate(ref + d * (reach + gap) + lateral * in_.range(-room, room));
  }

 private:
  // Any magnitude from 1e-300 to 1e9 m, either sign, or exactly zero: what the parsers accept.
  double wildCoordinate() {
    if (in_.pick(8) == 0) return 0.0;
    return in_.signedLog(1e-300, 1e9);
  }

  ByteReader& in_;
  bool wild_;
};

}  // namespace cardemo::fuzz
