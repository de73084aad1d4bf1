// Fuzz target: the scene JSON parser (src/io/scene_json), then a short simulation of what it
// accepts. Properties: no crash, hang, leak or UB; an error names the file and a line inside the
// input, in one printable line; an accepted scene satisfies every documented invariant and can be
// simulated without producing NaN or infinity. With simdjson, the fast reader and the
// line-tracking reader agree: both reject the input, or both accept it with the same Scene bit
// for bit, and parseScene (fast first) gives the line reader's error word for word.

#include "io/scene_json.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>

#include "../tests/support/scene_bits.hpp"
#include "fuzz_check.hpp"
#include "io/scene_json_lines.hpp"
#include "sim/world.hpp"

#if CARDEMO_WITH_SIMDJSON
#include "io/padded_text.hpp"
#include "io/scene_json_fast.hpp"
#endif

namespace cardemo::fuzz {
namespace {

constexpr const char* kFile = "fuzz.json";

bool finiteBox(const Obb2& b) {
  // >= 0: a size of 5e-324 m is > 0 as the contract asks, but halves to 0 (a flat, valid box).
  return b.center.allFinite() && b.axis.allFinite() && b.half.allFinite() && b.half.x() >= 0.0 &&
         b.half.y() >= 0.0 && std::abs(b.axis.norm() - 1.0) <= 1e-12;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

void requireValidScene(const Scene& scene) {
  const PlayerStart& p = scene.player;
  require(p.position.allFinite() && std::isfinite(p.heading_deg) && std::isfinite(p.speed),
          "player pose not finite");
  require(std::isfinite(p.length) && p.length > 0.0 && std::isfinite(p.width) && p.width > 0.0,
          "player size not finite and > 0");
  require(p.health > 0, "player health not > 0");
  if (scene.bounds) {
    require(scene.bounds->min.allFinite() && scene.bounds->max.allFinite(), "bounds not finite");
    require((scene.bounds->min.array() < scene.bounds->max.array()).all(), "bounds min >= max");
  }
  std::set<std::string> ids;
  for (const ParkedCar& car : scene.parked) {
    require(!car.id.empty() && ids.insert(car.id).second, "parked id empty or repeated");
    require(finiteBox(car.box), "parked car box not finite, or bad axis or size");
  }
  for (const Obstacle& o : scene.obstacles) {
    require(!o.id.empty() && ids.insert(o.id).second, "obstacle id empty or repeated");
    const ConvexPolygon& poly = o.polygon;
    require(poly.count >= 3 && poly.count <= ConvexPolygon::kMaxVertices, "obstacle vertex count");
    for (int i = 0; i < poly.count; ++i) {
      const Eigen::Vector2d& a = poly.vertex(i);
      const Eigen::Vector2d& b = poly.vertex((i + 1) % poly.count);
      const Eigen::Vector2d& c = poly.vertex((i + 2) % poly.count);
      require(a.allFinite(), "obstacle vertex not finite");
      require(cross(b - a, c - b) > 0.0, "obstacle not strictly convex and counter-clockwise");
    }
  }
}

// A few steps with keys taken from the input bytes: what the parser accepts, the World must run.
void simulate(Scene scene, std::string_view text) {
  World world(std::move(scene));
  for (std::size_t k = 0; k < 24; ++k) {
    const auto byte = text.empty() ? 0u : static_cast<unsigned char>(text[(k * 131) % text.size()]);
    world.step(InputFrame::fromBits(static_cast<std::uint8_t>(byte & 15u)));
    const CarState& car = world.car();
    require(car.position.allFinite() && std::isfinite(car.heading) && std::isfinite(car.speed) &&
                car.direction.allFinite() && std::isfinite(car.steer),
            "car state not finite after step " + std::to_string(k + 1));
    require(world.health() >= 0, "health below 0");
  }
  static_cast<void>(world.stateHash());
}

// The fast reader against its slow twin, and parseScene against the line reader alone.
void requireReadersAgree(std::string_view text, const Parsed<Scene>& slow) {
#if CARDEMO_WITH_SIMDJSON
  const std::optional<Scene> fast = parseSceneFast(PaddedText::copyOf(text), kFile);
  // The message is built only on a disagreement: slow.error() exists only when slow failed.
  if (fast.has_value() != slow.ok()) {
    require(false,
            fast ? "only the fast reader accepts; the line reader says " + slow.error().toString()
                 : std::string("only the line reader accepts"));
  }
  if (fast) {
    const std::string difference = testing::SceneBits::difference(*fast, slow.value());
    require(difference.empty(), "the readers' scenes differ at " + difference);
  }
  const Parsed<Scene> both = parseScene(text, kFile);
  require(both.ok() == slow.ok(), "parseScene and the line reader disagree");
  if (!slow.ok()) {
    require(both.error().toString() == slow.error().toString(),
            "parseScene says " + both.error().toString() + ", the line reader " +
                slow.error().toString());
  }
#else
  static_cast<void>(text);
  static_cast<void>(slow);
#endif
}

}  // namespace
}  // namespace cardemo::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cardemo;
  const std::string_view text = fuzz::asText(data, size);
  Parsed<Scene> parsed = parseSceneWithLines(text, fuzz::kFile);
  fuzz::requireReadersAgree(text, parsed);
  if (!parsed.ok()) {
    fuzz::requireGoodError(parsed.error(), text, fuzz::kFile);
    return 0;
  }
  fuzz::requireValidScene(parsed.value());
  fuzz::simulate(std::move(parsed).value(), text);
  return 0;
}
