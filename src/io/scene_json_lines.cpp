#include "io/scene_json_lines.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "io/json_with_lines.hpp"
#include "io/scene_json.hpp"
#include "io/scene_rules.hpp"
#include "sim/gate_course.hpp"
#include "sim/parking_goal.hpp"

namespace cardemo {
namespace {

using json_lines::Node;
using json_lines::printable;
using Kind = Node::Kind;

using namespace scene_rules;

enum class Rule { kCoordinate, kSize, kSpeed };

// Walks the line-annotated tree, keeps the first error, and fills a Scene.
class SceneReader {
 public:
  explicit SceneReader(const std::string& file) : file_(file) {}

  std::optional<InputError> error;

  bool readRoot(const Node& root, Scene& scene) {
    if (root.kind != Kind::kObject) {
      return fail(root.line, std::string("a scene must be a JSON object, found ") +
                                 json_lines::kindName(root.kind));
    }
    if (!onlyKeys(root,
                  {"format", "name", "bounds", "player", "parked", "obstacles", "goal", "level",
                   "markings"},
                  "")) {
      return false;
    }
    const Node* format = required(root, "format", "");
    if (format == nullptr || !isKind(*format, Kind::kString, "format")) return false;
    if (format->text != kFormat) {
      return fail(format->line, "format: expected \"" + std::string(kFormat) + "\", found \"" +
                                    printable(format->text) + "\"");
    }
    if (const Node* name = root.find("name")) {
      if (!isKind(*name, Kind::kString, "name")) return false;
      scene.name = name->text;
    }
    if (const Node* bounds = root.find("bounds")) {
      Aabb2 box;
      if (!readBounds(*bounds, box)) return false;
      scene.bounds = box;
    }
    const Node* player = required(root, "player", "");
    if (player == nullptr || !readPlayer(*player, scene.player)) return false;
    const Node* parked = required(root, "parked", "");
    if (parked == nullptr || !readParked(*parked, scene.parked)) return false;
    if (const Node* obstacles = root.find("obstacles")) {
      if (!readObstacles(*obstacles, scene.obstacles)) return false;
    }
    if (const Node* goal = root.find("goal")) {
      Goal g;
      if (!readGoal(*goal, g)) return false;
      scene.goal = g;
    }
    if (const Node* level = root.find("level")) {
      LevelInfo info;
      if (!readLevel(*level, info)) return false;
      scene.level = std::move(info);
    }
    if (const Node* markings = root.find("markings")) {
      if (!readMarkings(*markings, scene.markings)) return false;
    }
    return true;
  }

 private:
  bool fail(int line, std::string message) {
    if (!error) error = InputError{file_, line, std::move(message)};
    return false;
  }

  static std::string join(const std::string& parent, std::string_view key) {
    return parent.empty() ? std::string(key) : parent + "." + std::string(key);
  }

  bool isKind(const Node& n, Kind kind, const std::string& path) {
    if (n.kind == kind) return true;
    return fail(n.line, path + ": expected " + json_lines::kindName(kind) + ", found " +
                            json_lines::kindName(n.kind));
  }

  bool onlyKeys(const Node& obj, std::initializer_list<std::string_view> allowed,
                const std::string& path) {
    for (const json_lines::Member& m : obj.members) {
      if (std::find(allowed.begin(), allowed.end(), m.key) == allowed.end()) {
        return fail(m.line, "unknown key \"" + printable(m.key) + "\" in " +
                                (path.empty() ? std::string("scene") : path));
      }
    }
    return true;
  }

  const Node* required(const Node& obj, std::string_view key, const std::string& path) {
    const Node* n = obj.find(key);
    if (n == nullptr) {
      fail(obj.line,
           (path.empty() ? std::string("scene") : path) + ": missing \"" + std::string(key) + "\"");
    }
    return n;
  }

  // Fails with `path: why` when `why` is set.
  bool check(const Node& n, const std::string& path, const char* why) {
    return why == nullptr || fail(n.line, path + ": " + why);
  }

  bool number(const Node& n, const std::string& path, Rule rule, double& out) {
    if (!isKind(n, Kind::kNumber, path)) return false;
    const double v = n.number;
    const char* why = nullptr;
    switch (rule) {
      case Rule::kCoordinate:
        why = coordinateProblem(v);
        break;
      case Rule::kSize:
        why = sizeProblem(v);
        break;
      case Rule::kSpeed:
        why = speedProblem(v);
        break;
    }
    if (!check(n, path, why)) return false;
    out = v;
    return true;
  }

  bool field(const Node& obj, std::string_view key, const std::string& path, Rule rule,
             double& out) {
    const Node* n = required(obj, key, path);
    return n != nullptr && number(*n, join(path, key), rule, out);
  }

  bool point(const Node& n, const std::string& path, Eigen::Vector2d& out) {
    if (!isKind(n, Kind::kArray, path)) return false;
    if (n.items.size() != 2) {
      return fail(n.line,
                  path + ": expected [x, y], found " + std::to_string(n.items.size()) + " values");
    }
    return number(n.items[0], path + "[0]", Rule::kCoordinate, out.x()) &&
           number(n.items[1], path + "[1]", Rule::kCoordinate, out.y());
  }

  bool readBounds(const Node& n, Aabb2& box) {
    if (!isKind(n, Kind::kObject, "bounds") || !onlyKeys(n, {"min", "max"}, "bounds")) return false;
    const Node* min = required(n, "min", "bounds");
    if (min == nullptr || !point(*min, "bounds.min", box.min)) return false;
    const Node* max = required(n, "max", "bounds");
    if (max == nullptr || !point(*max, "bounds.max", box.max)) return false;
    if (!(box.min.x() < box.max.x() && box.min.y() < box.max.y())) {
      return fail(n.line, "bounds: min must be less than max on both axes");
    }
    return true;
  }

  bool readPose(const Node& n, const std::string& path, Eigen::Vector2d& center, double& heading,
                double& length, double& width) {
    return field(n, "x", path, Rule::kCoordinate, center.x()) &&
           field(n, "y", path, Rule::kCoordinate, center.y()) &&
           field(n, "heading_deg", path, Rule::kCoordinate, heading) &&
           field(n, "length", path, Rule::kSize, length) &&
           field(n, "width", path, Rule::kSize, width);
  }

  bool readPlayer(const Node& n, PlayerStart& p) {
    const std::string path = "player";
    if (!isKind(n, Kind::kObject, path) ||
        !onlyKeys(n, {"x", "y", "heading_deg", "length", "width", "health", "speed", "max_speed"},
                  path) ||
        !readPose(n, path, p.position, p.heading_deg, p.length, p.width)) {
      return false;
    }
    if (const Node* h = n.find("health")) {
      if (!isKind(*h, Kind::kNumber, "player.health") ||
          !check(*h, "player.health", healthProblem(h->number))) {
        return false;
      }
      p.health = static_cast<int>(h->number);
    }
    if (const Node* s = n.find("speed")) {
      if (!number(*s, "player.speed", Rule::kSpeed, p.speed)) return false;
    }
    if (const Node* s = n.find("max_speed")) {
      if (!isKind(*s, Kind::kNumber, "player.max_speed") ||
          !check(*s, "player.max_speed", maxSpeedProblem(s->number))) {
        return false;
      }
      p.max_speed = s->number;
    }
    return true;
  }

  // Ids end up in line-based files (replay expectations), so they must survive trimming.
  bool readId(const Node& obj, const std::string& path, std::string& out) {
    const Node* n = required(obj, "id", path);
    const std::string id_path = path + ".id";
    if (n == nullptr || !isKind(*n, Kind::kString, id_path)) return false;
    const std::string& id = n->text;
    if (!check(*n, id_path, idProblem(id))) return false;
    const auto [it, inserted] = ids_.emplace(id, path);
    if (!inserted) {
      return fail(n->line,
                  id_path + ": duplicate id \"" + printable(id) + "\" (also " + it->second + ")");
    }
    out = id;
    return true;
  }

  bool readParked(const Node& n, std::vector<ParkedCar>& cars) {
    if (!isKind(n, Kind::kArray, "parked")) return false;
    cars.reserve(n.items.size());
    for (std::size_t i = 0; i < n.items.size(); ++i) {
      const Node& car = n.items[i];
      const std::string path = "parked[" + std::to_string(i) + "]";
      ParkedCar out;
      Eigen::Vector2d center;
      double length = 0.0;
      double width = 0.0;
      if (!isKind(car, Kind::kObject, path) ||
          !onlyKeys(car, {"id", "x", "y", "heading_deg", "length", "width"}, path) ||
          !readId(car, path, out.id) ||
          !readPose(car, path, center, out.heading_deg, length, width)) {
        return false;
      }
      out.box = Obb2::fromDegrees(center, out.heading_deg, length, width);
      cars.push_back(std::move(out));
    }
    return true;
  }

  bool readObstacles(const Node& n, std::vector<Obstacle>& obstacles) {
    if (!isKind(n, Kind::kArray, "obstacles")) return false;
    obstacles.reserve(n.items.size());
    for (std::size_t i = 0; i < n.items.size(); ++i) {
      const Node& ob = n.items[i];
      const std::string path = "obstacles[" + std::to_string(i) + "]";
      Obstacle out;
      if (!isKind(ob, Kind::kObject, path) || !onlyKeys(ob, {"id", "points"}, path) ||
          !readId(ob, path, out.id)) {
        return false;
      }
      const std::string points_path = path + ".points";
      const Node* points = required(ob, "points", path);
      if (points == nullptr || !isKind(*points, Kind::kArray, points_path)) return false;
      const std::size_t count = points->items.size();
      if (count < 3 || count > static_cast<std::size_t>(ConvexPolygon::kMaxVertices)) {
        return fail(points->line, points_path + ": expected 3 to " +
                                      std::to_string(ConvexPolygon::kMaxVertices) +
                                      " points, found " + std::to_string(count));
      }
      std::vector<Eigen::Vector2d> pts(count);
      for (std::size_t k = 0; k < count; ++k) {
        if (!point(points->items[k], points_path + "[" + std::to_string(k) + "]", pts[k])) {
          return false;
        }
      }
      std::string why;
      std::optional<ConvexPolygon> polygon = ConvexPolygon::fromPoints(pts, &why);
      if (!polygon) {
        return fail(points->line,
                    points_path + ": " + (why.empty() ? std::string("not a convex polygon") : why));
      }
      out.polygon = *polygon;
      obstacles.push_back(std::move(out));
    }
    return true;
  }

  // A number in (0, max]; `what` completes "must be finite, > 0 and at most ...".
  bool positive(const Node& n, const std::string& path, double max, const char* what, double& out) {
    if (!isKind(n, Kind::kNumber, path)) return false;
    const double v = n.number;
    if (!inPositiveRange(v, max)) {
      return fail(n.line, path + ": must be finite, > 0 and at most " + what);
    }
    out = v;
    return true;
  }

  bool optionalPositive(const Node& obj, std::string_view key, const std::string& path, double max,
                        const char* what, double& out) {
    const Node* n = obj.find(key);
    return n == nullptr || positive(*n, join(path, key), max, what, out);
  }

  bool readGoal(const Node& n, Goal& goal) {
    const std::string path = "goal";
    if (!isKind(n, Kind::kObject, path) ||
        !onlyKeys(n,
                  {"bay", "position_tolerance", "heading_tolerance_deg", "either_direction",
                   "max_speed", "hold_time", "par_time", "time_limit", "gates", "next_bays"},
                  path)) {
      return false;
    }
    const Node* bay = required(n, "bay", path);
    if (bay == nullptr || !isKind(*bay, Kind::kObject, "goal.bay") ||
        !onlyKeys(*bay, {"x", "y", "heading_deg", "length", "width"}, "goal.bay") ||
        !readPose(*bay, "goal.bay", goal.bay.center, goal.bay.heading_deg, goal.bay.length,
                  goal.bay.width)) {
      return false;
    }
    if (!optionalPositive(n, "position_tolerance", path, kMaxCarSize, "10000 m",
                          goal.position_tolerance) ||
        !optionalPositive(n, "heading_tolerance_deg", path, kMaxHeadingTolerance, "180 degrees",
                          goal.heading_tolerance_deg) ||
        !optionalPositive(n, "max_speed", path, kMaxSpeed, "1000 m/s", goal.max_speed)) {
      return false;
    }
    if (const Node* e = n.find("either_direction")) {
      if (!isKind(*e, Kind::kBool, "goal.either_direction")) return false;
      goal.either_direction = e->boolean;
    }
    for (const auto& [key, slot] :
         {std::pair{"par_time", &goal.par_time}, std::pair{"time_limit", &goal.time_limit}}) {
      double seconds = 0.0;
      const Node* t = n.find(key);
      if (t == nullptr) continue;
      if (!positive(*t, join(path, key), kMaxGoalTime, "100000 s", seconds)) return false;
      *slot = seconds;
    }
    if (goal.par_time && goal.time_limit && *goal.par_time > *goal.time_limit) {
      return fail(n.find("par_time")->line, "goal.par_time: must not exceed goal.time_limit");
    }
    if (const Node* h = n.find("hold_time")) {
      if (!isKind(*h, Kind::kNumber, "goal.hold_time") ||
          !check(*h, "goal.hold_time", holdTimeProblem(h->number))) {
        return false;
      }
      goal.hold_time = h->number;
      if (goal.time_limit && goal.hold_time >= *goal.time_limit) {
        return fail(h->line, "goal.hold_time: must be less than goal.time_limit");
      }
    }
    if (const Node* gates = n.find("gates")) {
      if (!readGates(*gates, goal.gates)) return false;
    }
    if (const Node* bays = n.find("next_bays")) {
      if (!readNextBays(*bays, goal.next_bays)) return false;
    }
    return true;
  }

  bool readNextBays(const Node& n, std::vector<ParkingBay>& bays) {
    if (!isKind(n, Kind::kArray, "goal.next_bays")) return false;
    if (n.items.size() > kMaxNextBays) {
      return fail(n.line, "goal.next_bays: at most " + std::to_string(kMaxNextBays) +
                              " bays, found " + std::to_string(n.items.size()));
    }
    bays.reserve(n.items.size());
    for (std::size_t i = 0; i < n.items.size(); ++i) {
      const Node& item = n.items[i];
      const std::string path = "goal.next_bays[" + std::to_string(i) + "]";
      ParkingBay bay;
      if (!isKind(item, Kind::kObject, path) ||
          !onlyKeys(item, {"x", "y", "heading_deg", "length", "width"}, path) ||
          !readPose(item, path, bay.center, bay.heading_deg, bay.length, bay.width)) {
        return false;
      }
      bays.push_back(bay);
    }
    return true;
  }

  bool readGates(const Node& n, std::vector<Gate>& gates) {
    if (!isKind(n, Kind::kArray, "goal.gates")) return false;
    if (n.items.size() > kMaxGates) {
      return fail(n.line, "goal.gates: at most " + std::to_string(kMaxGates) + " gates, found " +
                              std::to_string(n.items.size()));
    }
    gates.reserve(n.items.size());
    for (std::size_t i = 0; i < n.items.size(); ++i) {
      Gate gate;
      if (!readGate(n.items[i], "goal.gates[" + std::to_string(i) + "]", gate)) return false;
      gates.push_back(std::move(gate));
    }
    return true;
  }

  bool readGate(const Node& n, const std::string& path, Gate& gate) {
    if (!isKind(n, Kind::kObject, path) ||
        !onlyKeys(n, {"name", "line", "box", "direction_deg"}, path)) {
      return false;
    }
    const Node* name = required(n, "name", path);
    if (name == nullptr || !isKind(*name, Kind::kString, path + ".name") ||
        !check(*name, path + ".name", gateNameProblem(name->text))) {
      return false;
    }
    gate.name = name->text;
    const Node* line = n.find("line");
    const Node* box = n.find("box");
    if ((line == nullptr) == (box == nullptr)) {
      return fail(n.line, path + ": needs exactly one of \"line\" and \"box\"");
    }
    if (line != nullptr) {
      const std::string line_path = path + ".line";
      if (!isKind(*line, Kind::kArray, line_path)) return false;
      if (line->items.size() != 2) {
        return fail(line->line, line_path + ": expected [[x, y], [x, y]], found " +
                                    std::to_string(line->items.size()) + " points");
      }
      Eigen::Vector2d from;
      Eigen::Vector2d to;
      if (!point(line->items[0], line_path + "[0]", from) ||
          !point(line->items[1], line_path + "[1]", to)) {
        return false;
      }
      if (from == to) return fail(line->line, line_path + ": the two ends must differ");
      setLineGate(gate, from, to);
    } else {
      const std::string box_path = path + ".box";
      Eigen::Vector2d center;
      double heading = 0.0;
      double length = 0.0;
      double width = 0.0;
      if (!isKind(*box, Kind::kObject, box_path) ||
          !onlyKeys(*box, {"x", "y", "heading_deg", "length", "width"}, box_path) ||
          !readPose(*box, box_path, center, heading, length, width)) {
        return false;
      }
      setBoxGate(gate, center, heading, length, width);
    }
    if (const Node* d = n.find("direction_deg")) {
      const std::string direction_path = path + ".direction_deg";
      double degrees = 0.0;
      if (!number(*d, direction_path, Rule::kCoordinate, degrees) ||
          !check(*d, direction_path, setGateDirection(gate, degrees))) {
        return false;
      }
    }
    return true;
  }

  bool readLevel(const Node& n, LevelInfo& level) {
    const std::string path = "level";
    if (!isKind(n, Kind::kObject, path) || !onlyKeys(n, {"order", "title", "task"}, path)) {
      return false;
    }
    const Node* order = required(n, "order", path);
    if (order == nullptr || !isKind(*order, Kind::kNumber, "level.order") ||
        !check(*order, "level.order", levelOrderProblem(order->number))) {
      return false;
    }
    level.order = static_cast<int>(order->number);
    const Node* title = required(n, "title", path);
    if (title == nullptr || !isKind(*title, Kind::kString, "level.title") ||
        !check(*title, "level.title", levelTitleProblem(title->text))) {
      return false;
    }
    level.title = title->text;
    if (const Node* task = n.find("task")) {
      if (!isKind(*task, Kind::kString, "level.task") ||
          !check(*task, "level.task", levelTaskProblem(task->text))) {
        return false;
      }
      level.task = task->text;
    }
    return true;
  }

  bool readMarkings(const Node& n, std::vector<Marking>& markings) {
    if (!isKind(n, Kind::kArray, "markings")) return false;
    markings.reserve(n.items.size());
    for (std::size_t i = 0; i < n.items.size(); ++i) {
      const Node& m = n.items[i];
      const std::string path = "markings[" + std::to_string(i) + "]";
      Marking out;
      if (!isKind(m, Kind::kObject, path) || !onlyKeys(m, {"type", "from", "to", "width"}, path)) {
        return false;
      }
      const Node* type = required(m, "type", path);
      if (type == nullptr || !isKind(*type, Kind::kString, path + ".type")) return false;
      if (type->text == "line") {
        out.kind = Marking::Kind::kLine;
      } else if (type->text == "arrow") {
        out.kind = Marking::Kind::kArrow;
      } else {
        return fail(type->line, path + ".type: expected \"line\" or \"arrow\", found \"" +
                                    printable(type->text) + "\"");
      }
      const Node* from = required(m, "from", path);
      if (from == nullptr || !point(*from, path + ".from", out.from)) return false;
      const Node* to = required(m, "to", path);
      if (to == nullptr || !point(*to, path + ".to", out.to)) return false;
      if (out.from == out.to) return fail(m.line, path + ": from and to must differ");
      if (!optionalPositive(m, "width", path, kMaxMarkingWidth, "10 m", out.width)) return false;
      markings.push_back(out);
    }
    return true;
  }

  const std::string& file_;
  std::unordered_map<std::string, std::string> ids_;  // id -> field path of its first use
};

}  // namespace

Parsed<Scene> parseSceneWithLines(std::string_view text, const std::string& filename) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return InputError{filename, 1, "empty scene file"};
  }
  if (text.size() > kMaxSceneBytes) {
    return InputError{filename, 1,
                      "scene file larger than " + std::to_string(kMaxSceneBytes) + " bytes"};
  }
  try {
    auto parsed = json_lines::parse(text);
    if (const auto* err = std::get_if<json_lines::SyntaxError>(&parsed)) {
      return InputError{filename, err->line, err->message};
    }
    Scene scene;
    scene.name = defaultSceneName(filename);
    SceneReader reader(filename);
    if (!reader.readRoot(std::get<Node>(parsed), scene)) {
      return reader.error.value_or(InputError{filename, 1, "invalid scene"});
    }
    return scene;
  } catch (const std::exception& e) {
    return InputError{filename, 1, std::string("cannot read scene: ") + e.what()};
  }
}

}  // namespace cardemo
