#include "io/scene_json_fast.hpp"

#include <simdjson.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "io/json_with_lines.hpp"
#include "io/scene_json.hpp"
#include "io/scene_rules.hpp"
#include "sim/gate_course.hpp"
#include "sim/parking_goal.hpp"

namespace cardemo {
namespace {

namespace od = simdjson::ondemand;
using namespace scene_rules;

static_assert(PaddedText::kPadding >= simdjson::SIMDJSON_PADDING,
              "simdjson reads this far past the text");

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// Keys of each object, the five of a pose first wherever an object has one.
template <std::size_t N>
using Keys = std::array<std::string_view, N>;
constexpr Keys<9> kRootKeys = {"format",    "name", "bounds", "player",  "parked",
                               "obstacles", "goal", "level",  "markings"};
enum RootKey {
  kFormatKey,
  kNameKey,
  kBoundsKey,
  kPlayerKey,
  kParkedKey,
  kObstaclesKey,
  kGoalKey,
  kLevelKey,
  kMarkingsKey
};
constexpr Keys<8> kPlayerKeys = {"x",     "y",      "heading_deg", "length",
                                 "width", "health", "speed",       "max_speed"};
enum PlayerKey { kHealthKey = 5, kSpeedKey, kMaxSpeedKey };
constexpr Keys<6> kCarKeys = {"x", "y", "heading_deg", "length", "width", "id"};
constexpr Keys<5> kPoseKeys = {"x", "y", "heading_deg", "length", "width"};
enum PoseKey { kXKey, kYKey, kHeadingKey, kLengthKey, kWidthKey };
constexpr Keys<2> kBoundsKeys = {"min", "max"};
constexpr Keys<2> kObstacleKeys = {"id", "points"};
constexpr Keys<10> kGoalKeys = {"bay",
                                "position_tolerance",
                                "heading_tolerance_deg",
                                "either_direction",
                                "max_speed",
                                "hold_time",
                                "par_time",
                                "time_limit",
                                "gates",
                                "next_bays"};
enum GoalKey {
  kBayKey,
  kPositionToleranceKey,
  kHeadingToleranceKey,
  kEitherDirectionKey,
  kGoalMaxSpeedKey,
  kHoldTimeKey,
  kParTimeKey,
  kTimeLimitKey,
  kGatesKey,
  kNextBaysKey
};
constexpr Keys<4> kGateKeys = {"name", "line", "box", "direction_deg"};
enum GateKey { kGateNameKey, kGateLineKey, kGateBoxKey, kGateDirectionKey };
constexpr Keys<3> kLevelKeys = {"order", "title", "task"};
constexpr Keys<4> kMarkingKeys = {"type", "from", "to", "width"};

constexpr std::uint32_t firstBits(int n) {
  return (std::uint32_t{1} << n) - 1;
}
constexpr std::uint32_t kPoseBits = firstBits(5);

// A member's key. Keys are short and almost never escaped, so the raw text (inside the input,
// validated by simdjson's first stage) is the key itself unless it holds a backslash.
bool readKey(od::field& field, std::string_view& out) {
  const char* raw = field.key().raw();
  std::size_t n = 0;
  while (raw[n] != '"' && raw[n] != '\\') ++n;
  if (raw[n] == '"') {
    out = std::string_view(raw, n);
    return true;
  }
  return field.unescaped_key().get(out) == simdjson::SUCCESS;
}

// The JSON number at the start of `token` (which may go on with whitespace only): its length, its
// digit counts, and whether it is written as an integer. False when it is not a number.
struct NumberToken {
  std::size_t length = 0;
  int mantissa_digits = 0;
  int exponent_digits = 0;
  bool integer = true;
};

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

bool scanNumber(std::string_view token, NumberToken& out) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < token.size() && isDigit(token[i])) ++i;
    return static_cast<int>(i - from);
  };
  if (i < token.size() && token[i] == '-') ++i;
  if (i == token.size() || !isDigit(token[i])) return false;
  if (token[i] == '0') {
    ++i;
    out.mantissa_digits = 1;
  } else {
    out.mantissa_digits = digits();
  }
  if (i < token.size() && token[i] == '.') {
    ++i;
    const int fraction = digits();
    if (fraction == 0) return false;
    out.mantissa_digits += fraction;
    out.integer = false;
  }
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    out.exponent_digits = digits();
    if (out.exponent_digits == 0) return false;
    out.integer = false;
  }
  out.length = i;
  return token.find_first_not_of(" \t\r\n", i) == std::string_view::npos;
}

// A long number as nlohmann converts it: an integer through strtoll or strtoull when it fits,
// anything else with strtod, the decimal point spelled as the locale spells it.
bool convertAsTheLineReader(std::string_view number, bool integer, double& out) {
  if (integer) {
    const char* end = number.data() + number.size();
    std::int64_t i = 0;
    std::uint64_t u = 0;
    if (number.front() == '-' ? std::from_chars(number.data(), end, i).ec == std::errc()
                              : std::from_chars(number.data(), end, u).ec == std::errc()) {
      out = number.front() == '-' ? static_cast<double>(i) : static_cast<double>(u);
      return true;
    }
  }
  std::string text(number);
  std::replace(text.begin(), text.end(), '.', *std::localeconv()->decimal_point);
  out = std::strtod(text.c_str(), nullptr);
  return std::isfinite(out);
}

// A number as the line-tracking reader converts it: an integer through a 64-bit integer when it
// fits (so `-0` is +0.0), anything else correctly rounded. simdjson 3.0.1's On-Demand parser
// gets some numbers of more than 19 digits wrong (0.30000000000000004440 reads as 0.1155...: its
// overflow check counts the leading zeros of "0.000..." instead of the digits after them) and
// refuses exponents of 20 digits, so such rare numbers are converted as the line reader does.
bool readNumber(od::value& v, double& out) {
  const std::string_view token = v.raw_json_token();
  NumberToken number;
  if (!scanNumber(token, number)) return false;
  if (number.integer) {
    // A failed conversion leaves the value unread (the next read skips it), and one beyond 64
    // bits goes on below.
    std::int64_t i = 0;
    std::uint64_t u = 0;
    if (token.front() == '-' ? v.get_int64().get(i) == simdjson::SUCCESS
                             : v.get_uint64().get(u) == simdjson::SUCCESS) {
      out = token.front() == '-' ? static_cast<double>(i) : static_cast<double>(u);
      return true;
    }
  } else if (number.mantissa_digits <= 19 && number.exponent_digits <= 18) {
    return v.get_double().get(out) == simdjson::SUCCESS;
  }
  return convertAsTheLineReader(token.substr(0, number.length), number.integer, out);
}

// A string. One without a backslash is its raw text (validated by simdjson's first stage), read in
// place and left unread (the next read skips it); one with escapes is decoded by simdjson. Ids
// rarely have escapes, and decoding 100,000 of them would fill a megabyte of parser memory.
bool readString(od::value& v, std::string_view& out) {
  const std::string_view token = v.raw_json_token();
  if (token.empty() || token.front() != '"') return false;
  const std::size_t end = token.find_first_of("\"\\", 1);
  if (end != std::string_view::npos && token[end] == '"') {
    out = token.substr(1, end - 1);
    return true;
  }
  return v.get_string().get(out) == simdjson::SUCCESS;
}

struct Pose {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double heading_deg = 0.0;
  double length = 0.0;
  double width = 0.0;
};

// Reads a scene, keeping nothing but the values: any problem is a plain `false`.
class FastSceneReader {
 public:
  explicit FastSceneReader(Scene& scene) : scene_(scene) {}

  bool readRoot(od::document& doc) {
    od::object root;
    if (doc.get_object().get(root) != simdjson::SUCCESS) return false;
    const std::uint32_t required = (1u << kFormatKey) | (1u << kPlayerKey) | (1u << kParkedKey);
    const bool ok = readMembers(root, kRootKeys, required, [this](int key, od::value& v) {
      switch (key) {
        case kFormatKey: {
          std::string_view format;
          return readString(v, format) && format == kFormat;
        }
        case kNameKey: {
          std::string_view name;
          if (!readString(v, name)) return false;
          scene_.name.assign(name);
          return true;
        }
        case kBoundsKey:
          return readBounds(v);
        case kPlayerKey:
          return readPlayer(v);
        case kParkedKey:
          return readParked(v);
        case kObstaclesKey:
          return readObstacles(v);
        case kGoalKey:
          return readGoal(v);
        case kLevelKey:
          return readLevel(v);
        default:
          return readMarkings(v);
      }
    });
    // Nothing may follow the root object: current_location() is past the end only then.
    const char* trailing = nullptr;
    return ok && doc.current_location().get(trailing) == simdjson::OUT_OF_BOUNDS &&
           values_ <= json_lines::kMaxValues && idsAreUnique();
  }

 private:
  // Calls on_field(key index, value) for each member; every key must be in `keys`, none twice,
  // and all of `required` (bits by key index) present.
  template <std::size_t N, class OnField>
  bool readMembers(od::object& object, const Keys<N>& keys, std::uint32_t required,
                   OnField&& on_field) {
    std::uint32_t seen = 0;
    for (auto member : object) {
      od::field field;
      if (std::move(member).get(field) != simdjson::SUCCESS) return false;
      std::string_view name;
      if (!readKey(field, name)) return false;
      const auto at = std::find(keys.begin(), keys.end(), name);
      if (at == keys.end()) return false;
      const auto key = static_cast<int>(at - keys.begin());
      const std::uint32_t bit = std::uint32_t{1} << key;
      if ((seen & bit) != 0) return false;
      seen |= bit;
      ++values_;
      if (!on_field(key, field.value())) return false;
    }
    return (seen & required) == required;
  }

  template <std::size_t N, class OnField>
  bool readObject(od::value& v, const Keys<N>& keys, std::uint32_t required, OnField&& on_field) {
    od::object object;
    return v.get_object().get(object) == simdjson::SUCCESS &&
           readMembers(object, keys, required, std::forward<OnField>(on_field));
  }

  // Calls on_count(number of elements) (which may say no, or reserve room), then on_item(value)
  // for each element.
  template <class OnCount, class OnItem>
  bool readArray(od::value& v, OnCount&& on_count, OnItem&& on_item) {
    od::array array;
    std::size_t count = 0;
    if (v.get_array().get(array) != simdjson::SUCCESS ||
        array.count_elements().get(count) != simdjson::SUCCESS || !on_count(count)) {
      return false;
    }
    for (auto element : array) {
      od::value item;
      if (std::move(element).get(item) != simdjson::SUCCESS) return false;
      ++values_;
      if (!on_item(item)) return false;
    }
    return true;
  }

  bool readPoint(od::value& v, Eigen::Vector2d& out) {
    Eigen::Index k = 0;
    return readArray(
        v, [](std::size_t count) { return count == 2; },
        [&](od::value& item) {
          double c = 0.0;
          if (!readNumber(item, c) || coordinateProblem(c) != nullptr) return false;
          out[k++] = c;
          return true;
        });
  }

  static bool readPoseField(int key, od::value& v, Pose& pose) {
    double x = 0.0;
    if (!readNumber(v, x)) return false;
    switch (key) {
      case kXKey:
        pose.center.x() = x;
        return coordinateProblem(x) == nullptr;
      case kYKey:
        pose.center.y() = x;
        return coordinateProblem(x) == nullptr;
      case kHeadingKey:
        pose.heading_deg = x;
        return coordinateProblem(x) == nullptr;
      case kLengthKey:
        pose.length = x;
        return sizeProblem(x) == nullptr;
      default:
        pose.width = x;
        return sizeProblem(x) == nullptr;
    }
  }

  bool readPose(od::value& v, Pose& pose) {
    return readObject(v, kPoseKeys, kPoseBits,
                      [&pose](int key, od::value& f) { return readPoseField(key, f, pose); });
  }

  bool readBounds(od::value& v) {
    Aabb2 box;
    if (!readObject(v, kBoundsKeys, firstBits(2), [&](int key, od::value& f) {
          return readPoint(f, key == 0 ? box.min : box.max);
        })) {
      return false;
    }
    if (!(box.min.x() < box.max.x() && box.min.y() < box.max.y())) return false;
    scene_.bounds = box;
    return true;
  }

  bool readPlayer(od::value& v) {
    PlayerStart& p = scene_.player;
    Pose pose;
    if (!readObject(v, kPlayerKeys, kPoseBits, [&](int key, od::value& f) {
          if (key < kHealthKey) return readPoseField(key, f, pose);
          double x = 0.0;
          if (!readNumber(f, x)) return false;
          switch (key) {
            case kHealthKey:
              if (healthProblem(x) != nullptr) return false;
              p.health = static_cast<int>(x);
              return true;
            case kSpeedKey:
              p.speed = x;
              return speedProblem(x) == nullptr;
            default:
              p.max_speed = x;
              return maxSpeedProblem(x) == nullptr;
          }
        })) {
      return false;
    }
    p.position = pose.center;
    p.heading_deg = pose.heading_deg;
    p.length = pose.length;
    p.width = pose.width;
    return true;
  }

  bool readId(od::value& v, std::string& out) {
    std::string_view id;
    if (!readString(v, id) || idProblem(id) != nullptr) return false;
    out.assign(id);
    return true;
  }

  bool readParked(od::value& v) {
    const auto reserve = [this](std::size_t count) {
      scene_.parked.reserve(count);
      return true;
    };
    return readArray(v, reserve, [&](od::value& item) {
      ParkedCar car;
      Pose pose;
      if (!readObject(item, kCarKeys, firstBits(6), [&](int key, od::value& f) {
            return key == 5 ? readId(f, car.id) : readPoseField(key, f, pose);
          })) {
        return false;
      }
      car.heading_deg = pose.heading_deg;
      car.box = Obb2::fromDegrees(pose.center, pose.heading_deg, pose.length, pose.width);
      scene_.parked.push_back(std::move(car));
      return true;
    });
  }

  bool readObstacles(od::value& v) {
    const auto reserve = [this](std::size_t count) {
      scene_.obstacles.reserve(count);
      return true;
    };
    return readArray(v, reserve, [&](od::value& item) {
      Obstacle obstacle;
      std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> points;
      std::size_t n = 0;
      if (!readObject(item, kObstacleKeys, firstBits(2), [&](int key, od::value& f) {
            if (key == 0) return readId(f, obstacle.id);
            const auto polygonSized = [&n](std::size_t count) {
              n = count;
              return count >= 3 && count <= static_cast<std::size_t>(ConvexPolygon::kMaxVertices);
            };
            std::size_t k = 0;
            return readArray(f, polygonSized,
                             [&](od::value& point) { return readPoint(point, points[k++]); });
          })) {
        return false;
      }
      std::optional<ConvexPolygon> polygon =
          ConvexPolygon::fromPoints(std::span<const Eigen::Vector2d>(points.data(), n));
      if (!polygon) return false;
      obstacle.polygon = *polygon;
      scene_.obstacles.push_back(std::move(obstacle));
      return true;
    });
  }

  bool readGoal(od::value& v) {
    Goal goal;
    bool has_hold_time = false;
    const auto positive = [](od::value& f, double max, double& out) {
      return readNumber(f, out) && inPositiveRange(out, max);
    };
    if (!readObject(v, kGoalKeys, 1u << kBayKey, [&](int key, od::value& f) {
          double x = 0.0;
          switch (key) {
            case kBayKey: {
              Pose pose;
              if (!readPose(f, pose)) return false;
              goal.bay = ParkingBay{pose.center, pose.heading_deg, pose.length, pose.width};
              return true;
            }
            case kPositionToleranceKey:
              return positive(f, kMaxCarSize, goal.position_tolerance);
            case kHeadingToleranceKey:
              return positive(f, kMaxHeadingTolerance, goal.heading_tolerance_deg);
            case kEitherDirectionKey:
              return f.get_bool().get(goal.either_direction) == simdjson::SUCCESS;
            case kGoalMaxSpeedKey:
              return positive(f, kMaxSpeed, goal.max_speed);
            case kHoldTimeKey:
              has_hold_time = true;
              return readNumber(f, goal.hold_time) && holdTimeProblem(goal.hold_time) == nullptr;
            case kParTimeKey:
              if (!positive(f, kMaxGoalTime, x)) return false;
              goal.par_time = x;
              return true;
            case kGatesKey:
              return readGates(f, goal.gates);
            case kNextBaysKey:
              return readNextBays(f, goal.next_bays);
            default:
              if (!positive(f, kMaxGoalTime, x)) return false;
              goal.time_limit = x;
              return true;
          }
        })) {
      return false;
    }
    if (goal.par_time && goal.time_limit && *goal.par_time > *goal.time_limit) return false;
    if (has_hold_time && goal.time_limit && goal.hold_time >= *goal.time_limit) return false;
    scene_.goal = goal;
    return true;
  }

  bool readGates(od::value& v, std::vector<Gate>& gates) {
    const auto reserve = [&gates](std::size_t count) {
      gates.reserve(count);
      return count <= kMaxGates;
    };
    return readArray(v, reserve, [&](od::value& item) {
      Gate gate;
      std::optional<double> direction_deg;
      Eigen::Vector2d from;
      Eigen::Vector2d to;
      Pose box;
      // The direction is checked against the line, which may come after it.
      const std::uint32_t seen_line = 1u << kGateLineKey;
      std::uint32_t shape = 0;
      if (!readObject(item, kGateKeys, 1u << kGateNameKey, [&](int key, od::value& f) {
            switch (key) {
              case kGateNameKey: {
                std::string_view name;
                if (!readString(f, name)) return false;
                gate.name.assign(name);
                return gateNameProblem(name) == nullptr;
              }
              case kGateLineKey: {
                shape |= seen_line;
                std::size_t k = 0;
                return readArray(
                    f, [](std::size_t count) { return count == 2; },
                    [&](od::value& point) { return readPoint(point, k++ == 0 ? from : to); });
              }
              case kGateBoxKey:
                shape |= 1u << kGateBoxKey;
                return readPose(f, box);
              default: {
                double degrees = 0.0;
                if (!readNumber(f, degrees) || coordinateProblem(degrees) != nullptr) return false;
                direction_deg = degrees;
                return true;
              }
            }
          })) {
        return false;
      }
      if (shape == seen_line) {
        if (from == to) return false;
        setLineGate(gate, from, to);
      } else if (shape == 1u << kGateBoxKey) {
        setBoxGate(gate, box.center, box.heading_deg, box.length, box.width);
      } else {
        return false;
      }
      if (direction_deg && setGateDirection(gate, *direction_deg) != nullptr) return false;
      gates.push_back(std::move(gate));
      return true;
    });
  }

  bool readNextBays(od::value& v, std::vector<ParkingBay>& bays) {
    const auto reserve = [&bays](std::size_t count) {
      bays.reserve(count);
      return count <= kMaxNextBays;
    };
    return readArray(v, reserve, [&](od::value& item) {
      Pose pose;
      if (!readPose(item, pose)) return false;
      bays.push_back(ParkingBay{pose.center, pose.heading_deg, pose.length, pose.width});
      return true;
    });
  }

  bool readLevel(od::value& v) {
    LevelInfo level;
    if (!readObject(v, kLevelKeys, firstBits(2), [&](int key, od::value& f) {
          if (key == 0) {
            double order = 0.0;
            if (!readNumber(f, order) || levelOrderProblem(order) != nullptr) return false;
            level.order = static_cast<int>(order);
            return true;
          }
          std::string_view text;
          if (!readString(f, text)) return false;
          if (key == 1) {
            level.title.assign(text);
            return levelTitleProblem(text) == nullptr;
          }
          level.task.assign(text);
          return levelTaskProblem(text) == nullptr;
        })) {
      return false;
    }
    scene_.level = std::move(level);
    return true;
  }

  bool readMarkings(od::value& v) {
    const auto reserve = [this](std::size_t count) {
      scene_.markings.reserve(count);
      return true;
    };
    return readArray(v, reserve, [&](od::value& item) {
      Marking marking;
      if (!readObject(item, kMarkingKeys, firstBits(3), [&](int key, od::value& f) {
            std::string_view type;
            switch (key) {
              case 0:
                if (!readString(f, type)) return false;
                marking.kind = type == "arrow" ? Marking::Kind::kArrow : Marking::Kind::kLine;
                return type == "line" || type == "arrow";
              case 1:
                return readPoint(f, marking.from);
              case 2:
                return readPoint(f, marking.to);
              default:
                return readNumber(f, marking.width) &&
                       inPositiveRange(marking.width, kMaxMarkingWidth);
            }
          })) {
        return false;
      }
      if (marking.from == marking.to) return false;
      scene_.markings.push_back(marking);
      return true;
    });
  }

  // Parked cars and obstacles share one space of ids. Their hashes, sorted, show whether any two
  // might be equal in 8 bytes an id; only then are the ids themselves compared.
  [[nodiscard]] bool idsAreUnique() const {
    std::vector<std::uint64_t> hashes;
    hashes.reserve(scene_.parked.size() + scene_.obstacles.size());
    const std::hash<std::string_view> hash;
    for (const ParkedCar& car : scene_.parked) hashes.push_back(hash(car.id));
    for (const Obstacle& obstacle : scene_.obstacles) hashes.push_back(hash(obstacle.id));
    std::sort(hashes.begin(), hashes.end());
    if (std::adjacent_find(hashes.begin(), hashes.end()) == hashes.end()) return true;
    std::unordered_set<std::string_view> ids;
    for (const ParkedCar& car : scene_.parked) {
      if (!ids.insert(car.id).second) return false;
    }
    for (const Obstacle& obstacle : scene_.obstacles) {
      if (!ids.insert(obstacle.id).second) return false;
    }
    return true;
  }

  Scene& scene_;
  std::size_t values_ = 1;  // JSON values read, the root included (json_lines::kMaxValues)
};

}  // namespace

std::optional<Scene> parseSceneFast(const PaddedText& text, const std::string& filename) {
  std::string_view json = text.view();
  // The line-tracking reader refuses a NUL byte anywhere; simdjson takes one outside strings for
  // the end of the text.
  if (json.size() > kMaxSceneBytes || std::memchr(json.data(), '\0', json.size()) != nullptr) {
    return std::nullopt;
  }
  // nlohmann skips a byte order mark at the very start; simdjson does not.
  if (json.substr(0, kByteOrderMark.size()) == kByteOrderMark) json.remove_prefix(3);
  try {
    od::parser parser;
    od::document doc;
    const simdjson::padded_string_view padded(json.data(), json.size(),
                                              json.size() + PaddedText::kPadding);
    if (parser.iterate(padded).get(doc) != simdjson::SUCCESS) return std::nullopt;
    Scene scene;
    scene.name = defaultSceneName(filename);
    FastSceneReader reader(scene);
    if (!reader.readRoot(doc)) return std::nullopt;
    return scene;
  } catch (const std::exception&) {
    // Out of memory, most likely: the line-tracking reader reports it.
    return std::nullopt;
  }
}

}  // namespace cardemo
