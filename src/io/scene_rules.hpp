#pragma once
/// The value rules of a scene file, shared by its two readers (private to io/): each check returns
/// what is wrong, the text after `FIELD: ` in the error message, or nullptr when the value is good.

#include <cstddef>
#include <string>
#include <string_view>

#include "sim/scene.hpp"

namespace cardemo::scene_rules {

/// The exact `format` of a scene file.
inline constexpr std::string_view kFormat = "cardemo-scene/1";
/// Largest |coordinate| or |heading| in degrees.
inline constexpr double kMaxCoordinate = 1e9;
/// Largest car or bay length or width, metres.
inline constexpr double kMaxCarSize = 1e4;
/// Largest |speed|, m/s.
inline constexpr double kMaxSpeed = 1000.0;
/// Largest starting health.
inline constexpr double kMaxHealth = 1e6;
/// Largest goal par time or time limit, seconds.
inline constexpr double kMaxGoalTime = 1e5;
/// Largest goal hold time, seconds.
inline constexpr double kMaxHoldTime = 60.0;
/// Largest level order.
inline constexpr double kMaxLevelOrder = 1e4;
/// Longest level title, bytes.
inline constexpr std::size_t kMaxTitleBytes = 64;
/// Longest level task, bytes.
inline constexpr std::size_t kMaxTaskBytes = 100;
/// Widest painted marking, metres.
inline constexpr double kMaxMarkingWidth = 10.0;
/// Largest goal heading tolerance, degrees.
inline constexpr double kMaxHeadingTolerance = 180.0;
/// Longest gate name, bytes.
inline constexpr std::size_t kMaxGateNameBytes = 40;

/// The name of a scene file without one: its file's stem, or "scene" for standard input.
[[nodiscard]] std::string defaultSceneName(const std::string& filename);

/// A position or heading: finite, |v| <= 1e9.
[[nodiscard]] const char* coordinateProblem(double v);
/// A car's or bay's length or width: finite, > 0, at most 1e4 m.
[[nodiscard]] const char* sizeProblem(double v);
/// A speed: finite, |v| <= 1000 m/s.
[[nodiscard]] const char* speedProblem(double v);
/// The player's speed cap: a speed, and > 0.
[[nodiscard]] const char* maxSpeedProblem(double v);
/// The player's health: an integer from 1 to 1e6.
[[nodiscard]] const char* healthProblem(double v);
/// A collider id: not empty, no control characters, no space at either end (uniqueness apart).
[[nodiscard]] const char* idProblem(std::string_view id);
/// True when `v` is finite and in (0, max] (the optional goal and marking numbers).
[[nodiscard]] bool inPositiveRange(double v, double max);
/// The goal's hold time: finite, from 0 to 60 s.
[[nodiscard]] const char* holdTimeProblem(double v);
/// A level's order: an integer from 1 to 1e4.
[[nodiscard]] const char* levelOrderProblem(double v);
/// A level's title: 1 to 64 bytes, no control characters.
[[nodiscard]] const char* levelTitleProblem(std::string_view title);
/// A level's task: 1 to 100 bytes, no control characters.
[[nodiscard]] const char* levelTaskProblem(std::string_view task);
/// A gate's name: 1 to 40 bytes, no control characters.
[[nodiscard]] const char* gateNameProblem(std::string_view name);
/// Makes `gate` a line gate from `from` to `to` (which must differ).
void setLineGate(Gate& gate, const Eigen::Vector2d& from, const Eigen::Vector2d& to);
/// Makes `gate` a box gate: centre, heading in degrees, length along it and width across.
void setBoxGate(Gate& gate, const Eigen::Vector2d& center, double heading_deg, double length,
                double width);
/// Sets the direction of travel of a line or box gate (set first); for a line gate, what is wrong
/// when the direction runs within 10 degrees of the line.
[[nodiscard]] const char* setGateDirection(Gate& gate, double direction_deg);

}  // namespace cardemo::scene_rules
