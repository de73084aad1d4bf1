#include "io/scene_rules.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "geometry/angle.hpp"

namespace cardemo::scene_rules {
namespace {

bool isControl(char c) {
  return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
}

bool hasControl(std::string_view text) {
  return std::any_of(text.begin(), text.end(), isControl);
}

// A directed line gate must be crossable: its direction at least 10 degrees off the line
// (sin 10 deg), or "towards one side" means nothing.
constexpr double kMinGateCrossingSine = 0.17364817766693033;

}  // namespace

// `name` is optional: a scene without one is named after its file (stem), which is what a user
// sees in the file browser anyway; standard input gets "scene".
std::string defaultSceneName(const std::string& filename) {
  const std::string stem = std::filesystem::path(filename).stem().string();
  return stem.empty() || stem == "-" ? std::string("scene") : stem;
}

const char* coordinateProblem(double v) {
  if (!std::isfinite(v) || std::abs(v) > kMaxCoordinate) {
    return "must be finite with |value| <= 1e9";
  }
  return nullptr;
}

const char* sizeProblem(double v) {
  if (!std::isfinite(v) || !(v > 0.0)) return "must be finite and > 0";
  if (v > kMaxCarSize) return "must be at most 10000 m";
  return nullptr;
}

const char* speedProblem(double v) {
  if (!std::isfinite(v) || std::abs(v) > kMaxSpeed) {
    return "must be finite with |speed| <= 1000 m/s";
  }
  return nullptr;
}

const char* maxSpeedProblem(double v) {
  if (const char* why = speedProblem(v)) return why;
  if (!(v > 0.0)) return "must be > 0";
  return nullptr;
}

const char* healthProblem(double v) {
  if (std::floor(v) != v) return "must be an integer";
  if (!(v > 0)) return "must be > 0";
  if (v > kMaxHealth) return "must be at most 1000000";
  return nullptr;
}

const char* idProblem(std::string_view id) {
  if (id.empty()) return "must not be empty";
  if (hasControl(id)) return "must not contain control characters";
  if (id.front() == ' ' || id.back() == ' ') return "must not start or end with a space";
  return nullptr;
}

bool inPositiveRange(double v, double max) {
  return std::isfinite(v) && v > 0.0 && v <= max;
}

const char* holdTimeProblem(double v) {
  if (!std::isfinite(v) || !(v >= 0.0) || v > kMaxHoldTime) {
    return "must be finite, >= 0 and at most 60 s";
  }
  return nullptr;
}

const char* levelOrderProblem(double v) {
  if (std::floor(v) != v || !(v >= 1) || v > kMaxLevelOrder) {
    return "must be an integer from 1 to 10000";
  }
  return nullptr;
}

const char* levelTitleProblem(std::string_view title) {
  if (title.empty() || title.size() > kMaxTitleBytes || hasControl(title)) {
    return "must be 1 to 64 bytes without control characters";
  }
  return nullptr;
}

const char* levelTaskProblem(std::string_view task) {
  if (task.empty() || task.size() > kMaxTaskBytes || hasControl(task)) {
    return "must be 1 to 100 bytes without control characters";
  }
  return nullptr;
}

const char* gateNameProblem(std::string_view name) {
  if (name.empty() || name.size() > kMaxGateNameBytes || hasControl(name)) {
    return "must be 1 to 40 bytes without control characters";
  }
  return nullptr;
}

void setLineGate(Gate& gate, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  gate.kind = Gate::Kind::kLine;
  gate.from = from;
  gate.to = to;
  gate.center = 0.5 * (from + to);
}

void setBoxGate(Gate& gate, const Eigen::Vector2d& center, double heading_deg, double length,
                double width) {
  gate.kind = Gate::Kind::kBox;
  gate.center = center;
  gate.corners = Obb2::fromDegrees(center, heading_deg, length, width).corners();
}

const char* setGateDirection(Gate& gate, double direction_deg) {
  const Eigen::Vector2d dir = unitFromDegrees(direction_deg);
  gate.direction = dir;
  if (gate.kind != Gate::Kind::kLine) return nullptr;
  const Eigen::Vector2d along = (gate.to - gate.from).normalized();
  const double sine = along.x() * dir.y() - along.y() * dir.x();
  if (!(std::abs(sine) >= kMinGateCrossingSine)) {
    return "must cross the line (at least 10 degrees off it)";
  }
  gate.side = sine > 0.0 ? 1 : -1;
  return nullptr;
}

}  // namespace cardemo::scene_rules
