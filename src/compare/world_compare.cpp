// A b2World (zero gravity, static parked cars and obstacles, a dynamic player box) driven by our
// car's velocity, step for step, and what it reports compared with our hits.

#include "compare/world_compare.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <variant>

#include "compare/box2d/box2d_shapes.hpp"
#include "geometry/angle.hpp"
#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"

namespace cardemo::compare {
namespace {

constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
constexpr std::uintptr_t kPlayerTag = 0;  // static bodies carry collider index + 1

// Records BeginContact events; a contact always pairs the player with one static body.
class BeginListener : public b2ContactListener {
 public:
  std::vector<std::uint32_t> begun;  ///< Collider indices of this step's events.

  void BeginContact(b2Contact* contact) override {
    for (b2Fixture* f : {contact->GetFixtureA(), contact->GetFixtureB()}) {
      const std::uintptr_t tag = f->GetBody()->GetUserData().pointer;
      if (tag != kPlayerTag) begun.push_back(static_cast<std::uint32_t>(tag - 1));
    }
  }
};

float angleOf(const Obb2& box) {
  return static_cast<float>(std::atan2(box.axis.y(), box.axis.x()));
}

b2Body* addStatic(b2World& b2, const StaticShape& shape, std::uint32_t index) {
  b2BodyDef def;
  def.type = b2_staticBody;
  def.userData.pointer = static_cast<std::uintptr_t>(index) + 1;
  b2PolygonShape polygon;
  if (const auto* box = std::get_if<Obb2>(&shape)) {
    def.position.Set(static_cast<float>(box->center.x()), static_cast<float>(box->center.y()));
    def.angle = angleOf(*box);
    polygon.SetAsBox(static_cast<float>(box->half.x()), static_cast<float>(box->half.y()));
  } else {
    polygon = box2dPolygon(std::get<ConvexPolygon>(shape), kBox2dDefaultSkin).shape;
  }
  b2Body* body = b2.CreateBody(&def);
  body->CreateFixture(&polygon, 0.0f);
  return body;
}

b2Body* addPlayer(b2World& b2, const Obb2& box) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.userData.pointer = kPlayerTag;
  def.position.Set(static_cast<float>(box.center.x()), static_cast<float>(box.center.y()));
  def.angle = angleOf(box);
  b2Body* body = b2.CreateBody(&def);
  b2PolygonShape polygon;
  polygon.SetAsBox(static_cast<float>(box.half.x()), static_cast<float>(box.half.y()));
  body->CreateFixture(&polygon, 1.0f);
  return body;
}

// Core polygon distance (skins not counted); 0 when the cores overlap.
double coreGap(const b2Body& a, const b2Body& b) {
  b2DistanceInput in;
  in.proxyA.Set(a.GetFixtureList()->GetShape(), 0);
  in.proxyB.Set(b.GetFixtureList()->GetShape(), 0);
  in.transformA = a.GetTransform();
  in.transformB = b.GetTransform();
  in.useRadii = false;
  b2SimplexCache cache;
  cache.count = 0;
  b2DistanceOutput out;
  b2Distance(&out, &cache, &in);
  return out.distance;
}

double offsetOf(const b2Body& body, const World& world) {
  const b2Vec2 p = body.GetPosition();
  return std::hypot(p.x - world.car().position.x(), p.y - world.car().position.y());
}

// Static pairs whose shapes touch within Box2D's skins: a b2World never reports any of them.
std::int64_t touchingStaticPairs(const std::vector<b2Body*>& bodies) {
  std::vector<b2AABB> boxes;
  for (const b2Body* b : bodies) {
    b2AABB aabb;
    b->GetFixtureList()->GetShape()->ComputeAABB(&aabb, b->GetTransform(), 0);
    boxes.push_back(aabb);
  }
  std::int64_t count = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
      if (b2TestOverlap(boxes[i], boxes[j]) &&
          b2TestOverlap(bodies[i]->GetFixtureList()->GetShape(), 0,
                        bodies[j]->GetFixtureList()->GetShape(), 0, bodies[i]->GetTransform(),
                        bodies[j]->GetTransform()))
        ++count;
  return count;
}

}  // namespace

Parsed<WorldComparison> compareWorld(const std::string& replay_path,
                                     const std::string& scene_override) {
  Parsed<Replay> replay = loadReplay(replay_path);
  if (!replay.ok()) return replay.error();
  Parsed<Scene> scene = loadReplayScene(replay.value(), replay_path, scene_override);
  if (!scene.ok()) return scene.error();
  World world(std::move(scene).value(), settingsForReplay(replay.value()));

  WorldComparison out;
  out.scene_name = world.scene().name;
  out.hz = world.settings().hz;
  out.colliders = world.colliders().size();
  out.speed_limit = b2_maxTranslation * out.hz;
  const float dt = static_cast<float>(1.0 / out.hz);

  b2World b2(b2Vec2(0.0f, 0.0f));
  b2.SetAllowSleeping(false);
  BeginListener listener;
  b2.SetContactListener(&listener);
  std::vector<b2Body*> statics;
  for (std::uint32_t i = 0; i < world.colliders().size(); ++i)
    statics.push_back(addStatic(b2, world.colliders().shape(i), i));
  out.touching_static_pairs = touchingStaticPairs(statics);
  b2Body* player = addPlayer(b2, world.carBox());
  std::vector<std::optional<double>> min_gap(statics.size());
  std::vector<std::int64_t> gap_frames(statics.size(), 0);
  double heading = world.car().heading;
  Eigen::Vector2d position = world.car().position;
  std::size_t hits_seen = 0;

  runReplayInputs(world, replay.value(), [&](const World& w) {
    // Our pose change over the step, not speed * direction: pushes out of contact and wall
    // responses are part of the motion, so before any contact the b2World body tracks our car.
    const Eigen::Vector2d v = (w.car().position - position) / static_cast<double>(dt);
    position = w.car().position;
    player->SetLinearVelocity(b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())));
    player->SetAngularVelocity(static_cast<float>(wrapRadians(w.car().heading - heading) / dt));
    heading = w.car().heading;
    listener.begun.clear();
    b2.Step(dt, kVelocityIterations, kPositionIterations);

    const double offset = offsetOf(*player, w);
    out.max_offset = std::max(out.max_offset, offset);
    for (; hits_seen < w.hits().size(); ++hits_seen) {
      const HitEvent& h = w.hits()[hits_seen];
      out.ours.push_back({h.frame, h.collider, h.id, offset});
    }
    for (std::uint32_t c : listener.begun) {
      out.b2.push_back({w.frame(), c, w.colliderId(c), offset});
      if (!min_gap[c]) min_gap[c] = coreGap(*player, *statics[c]);
    }
    for (std::size_t c = 0; c < statics.size(); ++c) {
      if (!min_gap[c]) continue;
      min_gap[c] = std::min(*min_gap[c], coreGap(*player, *statics[c]));
      ++gap_frames[c];
    }
    const double theirs = player->GetLinearVelocity().Length();
    if (w.frame() == 1) {
      out.our_speed_step1 = w.car().velocity().norm();
      out.b2_speed_step1 = theirs;
    }
    if (theirs < 0.99 * v.norm()) ++out.clamped_steps;
  });
  out.frames = world.frame();
  out.end_offset = offsetOf(*player, world);
  for (std::size_t c = 0; c < statics.size(); ++c)
    if (min_gap[c])
      out.gaps.push_back(
          {world.colliderId(static_cast<std::uint32_t>(c)), *min_gap[c], gap_frames[c]});
  return out;
}

std::string worldComparisonText(const WorldComparison& c) {
  std::string s;
  char line[512];
  auto add = [&](const char* fmt, auto... args) {
    std::snprintf(line, sizeof line, fmt, args...);
    s += line;
  };
  add("scene %s: %lld steps at %g Hz, %zu static colliders; b2World step(dt, %d, %d)\n",
      c.scene_name.c_str(), static_cast<long long>(c.frames), c.hz, c.colliders,
      kVelocityIterations, kPositionIterations);
  add("\n%-10s %-12s %8s %10s %8s %14s\n", "collider", "verdict", "frame", "b2 frame", "lag",
      "b2 offset m");
  // Each of our hits takes the nearest unused BeginContact on the same collider.
  std::vector<bool> used(c.b2.size(), false);
  for (const WorldContact& h : c.ours) {
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < c.b2.size(); ++k)
      if (!used[k] && c.b2[k].collider == h.collider &&
          (!best || std::llabs(c.b2[k].frame - h.frame) < std::llabs(c.b2[*best].frame - h.frame)))
        best = k;
    if (!best) {
      add("%-10s %-12s %8lld %10s %8s %14.4f\n", h.id.c_str(), "ours",
          static_cast<long long>(h.frame), "none", "-", h.b2_offset);
      continue;
    }
    used[*best] = true;
    add("%-10s %-12s %8lld %10lld %8lld %14.4f\n", h.id.c_str(), "ours",
        static_cast<long long>(h.frame), static_cast<long long>(c.b2[*best].frame),
        static_cast<long long>(c.b2[*best].frame - h.frame), h.b2_offset);
  }
  for (std::size_t k = 0; k < c.b2.size(); ++k)
    if (!used[k])
      add("%-10s %-12s %8s %10lld %8s %14.4f\n", c.b2[k].id.c_str(), "b2World only", "none",
          static_cast<long long>(c.b2[k].frame), "-", c.b2[k].b2_offset);
  add("\nlag = b2World BeginContact frame - our hit frame. b2World raises BeginContact in the "
      "Step\n"
      "after the one that made the touch (+1), while its two %.2f m skins make it touch early\n"
      "(-1 or more); \"none\" on a repeat hit: b2World never separated beyond the skins, so it\n"
      "has no new event. b2 offset = |b2World body centre - our car centre| at that frame.\n",
      b2_polygonRadius);
  add("\nb2World body vs our car centre: %.4f m at the end, %.4f m at most\n", c.end_offset,
      c.max_offset);
  for (const WorldGap& g : c.gaps)
    add("min gap b2World left against %s: %.4f m over %lld frames (skins %.3f m + %.3f m, "
        "linear slop %.3f m: contact is solved at %.3f m)\n",
        g.id.c_str(), g.min_gap, static_cast<long long>(g.frames), b2_polygonRadius,
        b2_polygonRadius, b2_linearSlop, 2 * b2_polygonRadius - b2_linearSlop);
  add("\nspeed clamp: b2_maxTranslation %.1f m per step = %.1f m/s at %g Hz; after step 1 ours "
      "%.3f m/s, b2World %.3f m/s; %lld steps where b2World's body ended > 1%% slower than driven "
      "(clamp or solver)\n",
      b2_maxTranslation, c.speed_limit, c.hz, c.our_speed_step1, c.b2_speed_step1,
      static_cast<long long>(c.clamped_steps));
  add("static-static: %lld pairs of parked cars/obstacles touch within the skin; b2World reports "
      "none (contacts need a dynamic body)\n",
      static_cast<long long>(c.touching_static_pairs));
  return s;
}

}  // namespace cardemo::compare
