#include "play/best_scores.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/printable.hpp"

namespace cardemo {
namespace {

constexpr const char* kFormat = "cardemo-best/1";
constexpr std::uintmax_t kMaxFileBytes = 1u << 20;

std::string envOrEmpty(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
}

// One entry; false when a field is missing, of the wrong type or out of range.
bool readScore(const nlohmann::json& j, ParkingScore& out) {
  if (!j.is_object()) return false;
  const auto frames = j.find("frames");
  const auto seconds = j.find("seconds");
  const auto damage = j.find("damage");
  const auto stars = j.find("stars");
  if (frames == j.end() || seconds == j.end() || damage == j.end() || stars == j.end()) {
    return false;
  }
  if (!frames->is_number_integer() || !seconds->is_number() || !damage->is_number_integer() ||
      !stars->is_number_integer()) {
    return false;
  }
  out.frames = frames->get<std::int64_t>();
  out.seconds = seconds->get<double>();
  out.damage = damage->get<int>();
  out.stars = stars->get<int>();
  return out.frames >= 0 && std::isfinite(out.seconds) && out.seconds >= 0.0 && out.damage >= 0 &&
         out.stars >= 1 && out.stars <= kMaxStars;
}

// One bay chain entry; false when a field is missing, of the wrong type or out of range.
bool readChain(const nlohmann::json& j, ChainScore& out) {
  if (!j.is_object()) return false;
  const auto count = j.find("count");
  const auto frames = j.find("frames");
  const auto seconds = j.find("seconds");
  if (count == j.end() || frames == j.end() || seconds == j.end()) return false;
  if (!count->is_number_integer() || !frames->is_number_integer() || !seconds->is_number()) {
    return false;
  }
  out.count = count->get<int>();
  out.frames = frames->get<std::int64_t>();
  out.seconds = seconds->get<double>();
  return out.count >= 1 && out.frames >= 0 && std::isfinite(out.seconds) && out.seconds >= 0.0;
}

}  // namespace

bool BestScores::offerChain(const std::string& scene, const ChainScore& score) {
  const auto it = chains.find(scene);
  if (it != chains.end() && !score.betterThan(it->second)) return false;
  chains[scene] = score;
  return true;
}

const ChainScore* BestScores::findChain(const std::string& scene) const {
  const auto it = chains.find(scene);
  return it == chains.end() ? nullptr : &it->second;
}

bool BestScores::offer(const std::string& scene, const ParkingScore& score) {
  const auto it = by_scene.find(scene);
  if (it != by_scene.end() && !score.betterThan(it->second)) return false;
  by_scene[scene] = score;
  return true;
}

const ParkingScore* BestScores::find(const std::string& scene) const {
  const auto it = by_scene.find(scene);
  return it == by_scene.end() ? nullptr : &it->second;
}

std::string bestScoresPath() {
  namespace fs = std::filesystem;
  const std::string xdg = envOrEmpty("XDG_DATA_HOME");
  fs::path base;
  if (!xdg.empty() && fs::path(xdg).is_absolute()) {
    base = xdg;
  } else {
    const std::string home = envOrEmpty("HOME");
    if (home.empty()) return {};
    base = fs::path(home) / ".local" / "share";
  }
  return (base / "cardemo" / "best-scores.json").string();
}

BestScores loadBestScores(const std::string& path, std::string& warning) {
  namespace fs = std::filesystem;
  warning.clear();
  BestScores scores;
  std::error_code ec;
  if (path.empty() || !fs::exists(path, ec)) return scores;
  const auto warn = [&](const std::string& why) {
    warning = path + ": " + why + "; best scores ignored";
    return BestScores{};
  };
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return warn("cannot read (" + ec.message() + ")");
  if (size > kMaxFileBytes) return warn("larger than 1 MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) return warn("cannot read");
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return warn("not valid JSON");
  if (!j.is_object() || j.value("format", std::string()) != kFormat || !j.contains("scenes") ||
      !j["scenes"].is_object()) {
    return warn(std::string("not a ") + kFormat + " file");
  }
  for (const auto& [name, entry] : j["scenes"].items()) {
    ParkingScore score;
    if (!readScore(entry, score)) return warn("bad entry for scene " + inQuotes(name));
    scores.by_scene[name] = score;
  }
  // Optional: files written before free drive had its bay chain have none.
  if (const auto chains = j.find("bay_chains"); chains != j.end()) {
    if (!chains->is_object()) return warn("bay_chains is not an object");
    for (const auto& [name, entry] : chains->items()) {
      ChainScore chain;
      if (!readChain(entry, chain)) return warn("bad bay chain for scene " + inQuotes(name));
      scores.chains[name] = chain;
    }
  }
  return scores;
}

std::string bestScoresText(const BestScores& scores) {
  nlohmann::json by_scene = nlohmann::json::object();
  for (const auto& [name, s] : scores.by_scene) {
    by_scene[name] = {
        {"frames", s.frames}, {"seconds", s.seconds}, {"damage", s.damage}, {"stars", s.stars}};
  }
  nlohmann::json j{{"format", kFormat}, {"scenes", by_scene}};
  if (!scores.chains.empty()) {
    nlohmann::json chains = nlohmann::json::object();
    for (const auto& [name, c] : scores.chains) {
      chains[name] = {{"count", c.count}, {"frames", c.frames}, {"seconds", c.seconds}};
    }
    j["bay_chains"] = chains;
  }
  return j.dump(2) + "\n";
}

std::string saveBestScores(const std::string& path, const BestScores& scores) {
  namespace fs = std::filesystem;
  if (path.empty()) return "no folder for best scores (HOME and XDG_DATA_HOME are unset)";
  std::error_code ec;
  const fs::path folder = fs::path(path).parent_path();
  if (!folder.empty()) {
    fs::create_directories(folder, ec);
    if (ec) return folder.string() + ": cannot create folder (" + ec.message() + ")";
  }
  return writeFileAtomically(path, bestScoresText(scores));
}

}  // namespace cardemo
