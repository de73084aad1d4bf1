#include "web/web_app.hpp"

#include <emscripten/emscripten.h>

#include <filesystem>
#include <utility>

#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "io/scene_json.hpp"
#include "play/level_list.hpp"
#include "render/scene_picker_view.hpp"

// clang-format off
EM_JS(void, cardemo_page_status, (const char* text), {
  Module.page.setStatus(UTF8ToString(text));
});
EM_JS(void, cardemo_page_outcome, (const char* text), {
  Module.page.setOutcome(UTF8ToString(text));
});
EM_JS(void, cardemo_page_log, (const char* text), {
  Module.page.log(UTF8ToString(text));
});
EM_JS(void, cardemo_page_offer, (const char* path, const char* scene), {
  Module.page.offerRecording(UTF8ToString(path), UTF8ToString(scene));
});
EM_JS(void, cardemo_page_save_best, (const char* path), {
  Module.page.saveBestScores(UTF8ToString(path));
});
// clang-format on

namespace cardemo {
namespace {

std::vector<LevelEntry> levels(const std::string& assets, std::vector<std::string>& warnings) {
  return listLevels(assets, warnings);
}

std::string worldStatus(const World& world) {
  return "frame " + std::to_string(world.frame()) + " hash " + hashHex(world.stateHash());
}

}  // namespace

WebApp::WebApp(WebPaths paths) : paths_(std::move(paths)), flow_({}, 1) {
  std::vector<std::string> warnings;
  flow_ = PickerFlow(levels(paths_.assets, warnings), 1);
  say(warnings);
  std::error_code ignored;
  std::filesystem::create_directories(std::filesystem::path(paths_.recording).parent_path(),
                                      ignored);
  base_.best_scores_path = paths_.best_scores;
  base_.session.record_path = paths_.recording;
  showPicker();
}

void WebApp::watch(const std::string& path, bool to_the_end) {
  Parsed<Replay> replay = loadReplay(path);
  Parsed<Scene> scene =
      replay.ok() ? loadReplayScene(replay.value(), path, "") : Parsed<Scene>(replay.error());
  if (!scene.ok()) {
    showError(scene.error().toString());
    return;
  }
  if (screen_) leaveLevel();
  picker_.reset();
  PlayScreenConfig config = base_;
  config.session.scene = std::move(scene).value();
  config.session.scene_path = replay.value().scene_resolved;
  config.session.settings = settingsForReplay(replay.value());
  config.session.playback = std::move(replay).value().runs;
  config.session.record_path.clear();  // watching records nothing, as `play --replay` alone
  config.replay_path = path;
  config.muted = muted_;
  config.viewport = canvas_.size();
  to_the_end_ = to_the_end;
  error_.clear();
  screen_ = std::make_unique<PlayScreen>(std::move(config));
  was_over_ = false;
  showWorld(screen_->session().world());
}

void WebApp::key(GameKey key, bool down, bool repeat) {
  if (picker_) {
    const std::optional<PickerAction> action = down ? pickerActionOf(key, repeat) : std::nullopt;
    // A page cannot be left with Esc: the picker stays.
    if (action && *action != PickerAction::kBack) picker_actions_.push_back(*action);
    return;
  }
  if (down) {
    keyDownActions(key, repeat, actions_);
  } else {
    keyUpActions(key, actions_);
  }
}

void WebApp::blur() {
  if (screen_) actions_.push_back({PlayActionKind::kReleaseAll});
}

void WebApp::frame(double elapsed_seconds) {
  parts_ = {};
  canvas_.resize();
  if (screen_) {
    levelFrame(elapsed_seconds);
  } else if (picker_) {
    pickerFrame();
  } else {
    startLevel();
  }
  const double flush_start = emscripten_get_now();
  canvas_.flush();
  parts_.flush = emscripten_get_now() - flush_start;
}

void WebApp::showPicker() {
  picker_ = std::make_unique<PickerScreen>(flow_.entries(), loadBest(), flow_.selected());
  picker_actions_.clear();
  outcome_ = "picker";
  cardemo_page_outcome(outcome_.c_str());
}

void WebApp::pickerFrame() {
  for (const PickerAction action : std::exchange(picker_actions_, {})) {
    if (!picker_->act(action)) continue;
    flow_.picked(picker_->choice());
    picker_.reset();
    startLevel();
    return;
  }
  const int row = picker_->selected();
  if (!error_.empty() && row == error_row_) {
    drawScenePicker(canvas_, picker_->rows(), picker_->selected(), picker_->progress());
    return;
  }
  error_.clear();
  auto found = picker_status_.find(row);
  if (found == picker_status_.end()) {
    // The status names the selected scene's frame 0, so it is never stale.
    const auto& entries = flow_.entries();
    std::string status;
    if (row >= 0 && row < static_cast<int>(entries.size())) {
      Parsed<Scene> scene = loadScene(entries[static_cast<std::size_t>(row)].path);
      status = scene.ok() ? worldStatus(World(std::move(scene).value())) : scene.error().toString();
    }
    found = picker_status_.emplace(row, std::move(status)).first;
  }
  if (found->second != status_) {
    status_ = found->second;
    cardemo_page_status(status_.c_str());
  }
  drawScenePicker(canvas_, picker_->rows(), picker_->selected(), picker_->progress());
}

void WebApp::startLevel() {
  if (flow_.done() || flow_.picking()) {
    if (flow_.done()) flow_ = PickerFlow(flow_.entries(), 1);
    showPicker();
    return;
  }
  PlayScreenConfig base = base_;
  base.muted = muted_;
  base.viewport = canvas_.size();
  Parsed<PlayScreenConfig> config = flow_.levelConfig(base);
  if (!config.ok()) {
    flow_.levelEnded({2, LevelExit::kPicker, 1});
    showPicker();
    showError(config.error().toString());
    return;
  }
  to_the_end_ = false;
  error_.clear();
  actions_.clear();
  screen_ = std::make_unique<PlayScreen>(std::move(config).value());
  was_over_ = false;
  say(screen_->takeMessages());
  if (!screen_->ready()) {
    flow_.levelEnded(screen_->outcome());
    screen_.reset();
    showPicker();
  }
}

void WebApp::levelFrame(double elapsed_seconds) {
  const std::vector<PlayAction> actions = std::exchange(actions_, {});
  PlayInput input{actions, {}, elapsed_seconds, canvas_.size()};
  const double update_start = emscripten_get_now();
  const PlayFrame* frame = &screen_->frame(input);
  if (to_the_end_) {
    // As fast as the page can: whole frames of the most steps each, for at most 50 ms a frame.
    const double hz = screen_->session().world().settings().hz;
    const double start = emscripten_get_now();
    while (frame->exit == LevelExit::kStay && screen_->session().playingBack() &&
           !screen_->session().ended() && emscripten_get_now() - start < 50.0) {
      frame = &screen_->frame({{}, {}, PlayScreen::kMaxStepsPerFrame / hz, canvas_.size()});
    }
    if (!screen_->session().playingBack() || screen_->session().ended()) to_the_end_ = false;
  }
  parts_.update = emscripten_get_now() - update_start;
  say(screen_->takeMessages());
  offerRecordings();
  if (frame->exit != LevelExit::kStay) {
    leaveLevel();
    startLevel();
    return;
  }
  muted_ = frame->muted;
  audio_.apply(frame->sound, frame->muted);
  if (frame->chime) audio_.playChime(frame->muted);
  const double draw_start = emscripten_get_now();
  drawPlayFrame(canvas_, *frame);
  parts_.draw = emscripten_get_now() - draw_start;
  showWorld(*frame->world);
  showOutcome();
}

void WebApp::leaveLevel() {
  const GameOutcome outcome = screen_->finish();
  say(screen_->takeMessages());
  offerRecordings();
  cardemo_page_save_best(paths_.best_scores.c_str());
  audio_.silence();
  screen_.reset();
  picker_status_.clear();  // the picker shows the new best scores
  flow_.levelEnded(outcome);
}

void WebApp::say(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) cardemo_page_log(line.c_str());
}

void WebApp::showError(std::string error) {
  error_ = std::move(error);
  error_row_ = picker_ ? picker_->selected() : 0;
  status_ = error_;
  cardemo_page_status(status_.c_str());
  cardemo_page_log(status_.c_str());
}

void WebApp::showWorld(const World& world) {
  std::string status = worldStatus(world);
  if (status == status_) return;
  status_ = std::move(status);
  cardemo_page_status(status_.c_str());
}

void WebApp::showOutcome() {
  const World& world = screen_->session().world();
  const ParkingChallenge* challenge = screen_->level().challenge();
  const BayChain* chain = screen_->chain().chain();
  std::string outcome = world.gameOver()                        ? "GAME OVER"
                        : challenge && challenge->parkedFrame() ? "PARKED"
                        : challenge && challenge->timedOut()    ? "TIME UP"
                        : chain && chain->timedOut()            ? "TIME UP"
                        : screen_->session().playingBack()      ? "watching"
                                                                : "driving";
  const bool over = screen_->ended();
  if (over && !was_over_) cardemo_page_save_best(paths_.best_scores.c_str());
  was_over_ = over;
  if (outcome == outcome_) return;
  outcome_ = std::move(outcome);
  cardemo_page_outcome(outcome_.c_str());
}

void WebApp::offerRecordings() {
  if (!screen_) return;
  const std::string& scene = screen_->session().world().scene().name;
  for (const std::string& path : screen_->takePublished()) {
    cardemo_page_offer(path.c_str(), scene.c_str());
  }
}

BestScores WebApp::loadBest() {
  std::string warning;
  BestScores best = loadBestScores(paths_.best_scores, warning);
  if (!warning.empty()) cardemo_page_log(warning.c_str());
  return best;
}

}  // namespace cardemo
