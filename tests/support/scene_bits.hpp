#pragma once
/// Bit-for-bit comparison of two scenes, field by field (tests and fuzz targets).

#include <bit>
#include <cstdint>
#include <string>

#include "sim/scene.hpp"

namespace cardemo::testing {

/// Compares field by field, doubles by their bits (so -0.0 differs from 0.0); the first field that
/// differs, or an empty string when the scenes are identical.
class SceneBits {
 public:
  /// The first difference between `a` and `b`, or "".
  [[nodiscard]] static std::string difference(const Scene& a, const Scene& b) {
    SceneBits d;
    d.compare(a, b);
    return d.first_;
  }

 private:
  void note(bool same, const std::string& field) {
    if (!same && first_.empty()) first_ = field;
  }
  void same(double a, double b, const std::string& field) {
    note(std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b),
         field + " (" + std::to_string(a) + " vs " + std::to_string(b) + ")");
  }
  void same(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& field) {
    same(a.x(), b.x(), field + ".x");
    same(a.y(), b.y(), field + ".y");
  }
  template <class T>
  void same(const std::optional<T>& a, const std::optional<T>& b, const std::string& field) {
    note(a.has_value() == b.has_value(), field + " present");
    if (a && b) same(*a, *b, field);
  }
  void same(const Aabb2& a, const Aabb2& b, const std::string& field) {
    same(a.min, b.min, field + ".min");
    same(a.max, b.max, field + ".max");
  }
  void same(const ParkingBay& a, const ParkingBay& b, const std::string& field) {
    same(a.center, b.center, field + ".center");
    same(a.heading_deg, b.heading_deg, field + ".heading_deg");
    same(a.length, b.length, field + ".length");
    same(a.width, b.width, field + ".width");
  }
  void same(const Goal& a, const Goal& b, const std::string& field) {
    same(a.bay, b.bay, field + ".bay");
    same(a.position_tolerance, b.position_tolerance, field + ".position_tolerance");
    same(a.heading_tolerance_deg, b.heading_tolerance_deg, field + ".heading_tolerance_deg");
    note(a.either_direction == b.either_direction, field + ".either_direction");
    same(a.max_speed, b.max_speed, field + ".max_speed");
    same(a.hold_time, b.hold_time, field + ".hold_time");
    same(a.par_time, b.par_time, field + ".par_time");
    same(a.time_limit, b.time_limit, field + ".time_limit");
    note(a.gates.size() == b.gates.size(), field + ".gates count");
    for (std::size_t i = 0; i < a.gates.size() && i < b.gates.size(); ++i) {
      same(a.gates[i], b.gates[i], field + ".gates[" + std::to_string(i) + "]");
    }
    note(a.next_bays.size() == b.next_bays.size(), field + ".next_bays count");
    for (std::size_t i = 0; i < a.next_bays.size() && i < b.next_bays.size(); ++i) {
      same(a.next_bays[i], b.next_bays[i], field + ".next_bays[" + std::to_string(i) + "]");
    }
  }
  void same(const Gate& a, const Gate& b, const std::string& field) {
    note(a.kind == b.kind, field + ".kind");
    note(a.name == b.name, field + ".name");
    same(a.from, b.from, field + ".from");
    same(a.to, b.to, field + ".to");
    for (std::size_t k = 0; k < a.corners.size(); ++k) {
      same(a.corners[k], b.corners[k], field + ".corners[" + std::to_string(k) + "]");
    }
    same(a.center, b.center, field + ".center");
    same(a.direction, b.direction, field + ".direction");
    note(a.side == b.side, field + ".side");
  }
  void same(const LevelInfo& a, const LevelInfo& b, const std::string& field) {
    note(a.order == b.order, field + ".order");
    note(a.title == b.title, field + ".title");
    note(a.task == b.task, field + ".task");
  }

  void compare(const Scene& a, const Scene& b) {
    note(a.name == b.name, "name (" + a.name + " vs " + b.name + ")");
    same(a.bounds, b.bounds, "bounds");
    const PlayerStart& p = a.player;
    const PlayerStart& q = b.player;
    same(p.position, q.position, "player.position");
    same(p.heading_deg, q.heading_deg, "player.heading_deg");
    same(p.length, q.length, "player.length");
    same(p.width, q.width, "player.width");
    note(p.health == q.health, "player.health");
    same(p.speed, q.speed, "player.speed");
    same(p.max_speed, q.max_speed, "player.max_speed");
    note(a.parked.size() == b.parked.size(), "parked count");
    for (std::size_t i = 0; i < a.parked.size() && i < b.parked.size(); ++i) {
      const std::string at = "parked[" + std::to_string(i) + "]";
      note(a.parked[i].id == b.parked[i].id, at + ".id");
      same(a.parked[i].heading_deg, b.parked[i].heading_deg, at + ".heading_deg");
      same(a.parked[i].box.center, b.parked[i].box.center, at + ".box.center");
      same(a.parked[i].box.axis, b.parked[i].box.axis, at + ".box.axis");
      same(a.parked[i].box.half, b.parked[i].box.half, at + ".box.half");
    }
    note(a.obstacles.size() == b.obstacles.size(), "obstacles count");
    for (std::size_t i = 0; i < a.obstacles.size() && i < b.obstacles.size(); ++i) {
      const std::string at = "obstacles[" + std::to_string(i) + "]";
      note(a.obstacles[i].id == b.obstacles[i].id, at + ".id");
      const ConvexPolygon& s = a.obstacles[i].polygon;
      const ConvexPolygon& t = b.obstacles[i].polygon;
      note(s.count == t.count, at + ".polygon.count");
      for (int k = 0; k < s.count && k < t.count; ++k) {
        same(s.vertex(k), t.vertex(k), at + ".polygon.vertex(" + std::to_string(k) + ")");
      }
    }
    same(a.goal, b.goal, "goal");
    same(a.level, b.level, "level");
    note(a.markings.size() == b.markings.size(), "markings count");
    for (std::size_t i = 0; i < a.markings.size() && i < b.markings.size(); ++i) {
      const std::string at = "markings[" + std::to_string(i) + "]";
      note(a.markings[i].kind == b.markings[i].kind, at + ".kind");
      same(a.markings[i].from, b.markings[i].from, at + ".from");
      same(a.markings[i].to, b.markings[i].to, at + ".to");
      same(a.markings[i].width, b.markings[i].width, at + ".width");
    }
  }

  std::string first_;
};

}  // namespace cardemo::testing
