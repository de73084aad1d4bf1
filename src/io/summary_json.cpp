#include "io/summary_json.hpp"

#include "geometry/angle.hpp"
#include "sim/parking_readout.hpp"

namespace cardemo {
namespace {

// Integral rates print as integers, as the contract shows them.
nlohmann::json hzJson(double hz) {
  if (hz == static_cast<double>(static_cast<std::int64_t>(hz)))
    return static_cast<std::int64_t>(hz);
  return hz;
}

}  // namespace

nlohmann::json bayChainJson(const BayChain& chain) {
  nlohmann::json bay = nullptr;
  if (const std::optional<std::size_t> current = chain.current()) bay = chain.bays()[*current].id;
  return {{"count", chain.count()},
          {"bay", bay},
          {"bays", chain.bays().size()},
          {"clock_frames", chain.clockFrames()},
          {"over", chain.over()}};
}

nlohmann::json scoreJson(const ParkingScore& score) {
  return {{"frames", score.frames},
          {"seconds", score.seconds},
          {"damage", score.damage},
          {"stars", score.stars}};
}

nlohmann::json gatesJson(const GateCourse& course) {
  nlohmann::json names = nlohmann::json::array();
  for (std::size_t i = 0; i < course.passed(); ++i) names.push_back(course.gates()[i].name);
  nlohmann::json next = nullptr;
  if (const Gate* gate = course.nextGate()) next = gate->name;
  return {{"total", course.size()},
          {"passed", course.passed()},
          {"names", names},
          {"next", next},
          {"misses", course.misses()}};
}

nlohmann::json baysJson(const ParkingChallenge& challenge) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t i = 0; i < challenge.baysParked(); ++i) {
    frames.push_back(*challenge.bayParkedFrame(i));
  }
  return {
      {"total", challenge.bays().size()}, {"parked", challenge.baysParked()}, {"frames", frames}};
}

nlohmann::json summaryJson(const World& world, const ParkingChallenge* challenge) {
  nlohmann::json hits = nlohmann::json::array();
  for (const HitEvent& h : world.hits()) {
    hits.push_back({{"frame", h.frame},
                    {"id", h.id},
                    {"speed", h.speed},
                    {"damage", h.damage},
                    {"crash", h.crash}});
  }
  const CarState& car = world.car();
  const WorldStats& s = world.stats();
  nlohmann::json parked = nullptr;
  nlohmann::json score = nullptr;
  nlohmann::json clock_start = nullptr;
  nlohmann::json not_parked = nullptr;
  nlohmann::json gates = nullptr;
  nlohmann::json bays = nullptr;
  if (challenge != nullptr) {
    gates = gatesJson(challenge->gates());
    bays = baysJson(*challenge);
    if (challenge->parkedFrame()) {
      parked = *challenge->parkedFrame();
      score = scoreJson(*challenge->score());
    }
    if (challenge->clockStart()) clock_start = *challenge->clockStart();
    not_parked = notParkedReasons(*challenge);
  }
  return {
      {"scene", world.scene().name},
      {"hz", hzJson(world.settings().hz)},
      {"frames", world.frame()},
      {"health", world.health()},
      {"game_over", world.gameOver()},
      {"hits", hits},
      {"crashes", world.crashes()},
      {"scrape_damage", world.scrapeDamage()},
      {"final",
       {{"x", car.position.x()},
        {"y", car.position.y()},
        {"heading_deg", degreesOf(car.direction)},
        {"speed", car.speed},
        {"gear", std::string(1, gearLetter(world.gear()))}}},
      {"hash", hashHex(world.stateHash())},
      {"stats",
       {{"broadphase_queries", s.broadphase_queries},
        {"broadphase_candidates", s.broadphase_candidates},
        {"narrowphase_tests", s.narrowphase_tests},
        {"skipped_tests", s.skipped_tests},
        {"contacts", s.contacts},
        {"skipped_queries", s.skipped_queries},
        {"reused_queries", s.reused_queries},
        {"substeps", s.substeps},
        {"sweeps", s.sweeps},
        {"broadphase_builds", s.broadphase_builds}}},
      {"goal", challenge != nullptr},
      {"parked", parked},
      {"score", score},
      {"timed_out", challenge != nullptr && challenge->timedOut()},
      {"clock_start", clock_start},
      {"not_parked", not_parked},
      {"gates", gates},
      {"bays", bays},
  };
}

}  // namespace cardemo
