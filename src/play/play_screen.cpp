#include "play/play_screen.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/summary_json.hpp"
#include "play/status_line.hpp"

namespace cardemo {

PlayScreen::PlayScreen(PlayScreenConfig config)
    : config_(std::move(config)),
      // A replay being watched shows the best score but never sets one: the player did not drive.
      keeps_best_(config_.session.playback.empty()),
      clock_(1.0 / config_.session.settings.hz, kMaxStepsPerFrame),
      session_(std::move(config_.session)),
      effects_(session_.world()),
      rig_(session_.world(), config_.viewport),
      level_(session_.world(), config_.best_scores_path, keeps_best_),
      chain_(session_.world(), config_.best_scores_path, keeps_best_),
      muted_(config_.muted) {
  if (!session_.recordError().empty()) {
    say(session_.recordError());
    status_ = 2;
    ready_ = false;
    return;
  }
  // No sound is not an error: say so once, unless the player asked for silence (then on M).
  if (!muted_ && !config_.sound.problem.empty() && !config_.sound.problem_reported) {
    config_.sound.problem_reported = true;
    say("cardemo play: " + config_.sound.problem);
  }
}

const PlayFrame& PlayScreen::frame(const PlayInput& input) {
  assert(ready_);
  out_.exit = LevelExit::kStay;
  out_.steps = 0;
  out_.chime = false;
  out_.screenshot = false;
  out_.toggle_fullscreen = false;
  Requests requests;
  for (const PlayAction& action : input.actions) apply(action, requests);
  if (requests.quit) return leave(LevelExit::kQuit);
  if (requests.escape) return leave(escapeExit(config_.links));
  if (requests.next) {
    const bool parked = level_.challenge() != nullptr && level_.challenge()->parkedFrame();
    if (flow_.next(parked, config_.links) == LevelExit::kNextLevel) {
      return leave(LevelExit::kNextLevel);
    }
  }
  measureFps(input.elapsed_seconds);
  // GAME OVER, or a level's PARKED / TIME UP: Enter or Space starts the next attempt.
  if (requests.confirm && flow_.confirm(ended())) requests.restart = true;
  if (requests.restart) restart();
  if (requests.toggle_mute) toggleMute();
  const PadState& pad = input.pad;
  if (pad.throttle > 0.0 || pad.brake > 0.0 || pad.steer != 0.0 || pad.handbrake) {
    flow_.driveKeyPressed();
  }
  flow_.update(session_.playingBack(), ended());
  const int steps =
      flow_.stepsToRun(flow_.holding() ? 0 : clock_.advance(input.elapsed_seconds, flow_.speed()));
  runSteps(steps, pad);
  if (ended()) effects_.idle(steps);
  reportAfterSteps();
  // Once the run is over the engine idles: no throttle from a key still held at the end.
  out_.sound =
      sound_.update(session_.world(), ended() ? InputFrame{} : last_input_, flow_.holding());
  compose(input.viewport);
  return out_;
}

GameOutcome PlayScreen::finish() {
  if (std::string why = publishRecording(); !why.empty()) {
    if (!record_error_reported_) say(std::move(why));
    status_ = 2;
  }
  writeSummary();
  return outcome();
}

GameOutcome PlayScreen::outcome() const {
  return {status_, exit_, session_.attempt()};
}

std::vector<std::string> PlayScreen::takeMessages() {
  return std::exchange(messages_, {});
}

std::vector<std::string> PlayScreen::takePublished() {
  return std::exchange(published_, {});
}

void PlayScreen::apply(const PlayAction& action, Requests& requests) {
  switch (action.kind) {
    case PlayActionKind::kDrivePress:
      latch_.press(action.key);
      flow_.driveKeyPressed();
      break;
    case PlayActionKind::kDriveRelease:
      latch_.release(action.key);
      break;
    case PlayActionKind::kReleaseAll:
      latch_.releaseAll();
      break;
    case PlayActionKind::kPause:
      flow_.togglePause();
      break;
    case PlayActionKind::kHelp:
      flow_.toggleHelp();
      break;
    case PlayActionKind::kRestart:
      requests.restart = true;
      break;
    case PlayActionKind::kConfirm:
      requests.confirm = true;
      break;
    case PlayActionKind::kEscape:
      requests.escape = true;
      break;
    case PlayActionKind::kNext:
      requests.next = true;
      break;
    case PlayActionKind::kZoomIn:
      zoom_ = std::min(kMaxZoom, zoom_ * 1.25);
      break;
    case PlayActionKind::kZoomOut:
      zoom_ = std::max(kMinZoom, zoom_ / 1.25);
      break;
    case PlayActionKind::kSlower:
      flow_.slower();
      break;
    case PlayActionKind::kFaster:
      flow_.faster();
      break;
    case PlayActionKind::kDebugOverlay:
      out_.draw.debug_overlay = !out_.draw.debug_overlay;
      break;
    case PlayActionKind::kToggleMute:
      requests.toggle_mute = true;
      break;
    case PlayActionKind::kScreenshot:
      out_.screenshot = true;
      break;
    case PlayActionKind::kFullscreen:
      out_.toggle_fullscreen = !out_.toggle_fullscreen;  // twice in one frame: no change
      break;
    case PlayActionKind::kQuit:
      requests.quit = true;
      break;
  }
}

const PlayFrame& PlayScreen::leave(LevelExit exit) {
  exit_ = exit;
  out_.exit = exit;
  return out_;
}

void PlayScreen::measureFps(double elapsed_seconds) {
  // The first frame measures no drawn frame (a few microseconds after start-up): skip it, or a
  // game opened from the picker starts with an FPS in the tens of thousands.
  if (elapsed_seconds > 0.0 && drawn_frames_++ > 0) {
    fps_ = fps_ == 0.0 ? 1.0 / elapsed_seconds : 0.95 * fps_ + 0.05 / elapsed_seconds;
  }
}

void PlayScreen::restart() {
  // The attempt that ends here is published under its own name before the next one starts.
  if (std::string why = publishRecording(); !why.empty() && !record_error_reported_) {
    say(std::move(why));
    status_ = 2;
  }
  session_.restart();
  effects_.reset(session_.world());
  rig_.reset(session_.world());
  level_.restart(session_.world());
  chain_.restart(session_.world());
  latch_.releaseAll();
  analog_.reset();
  flow_.restarted();
  over_reported_ = false;
  record_error_reported_ = false;
  note_ = "attempt " + std::to_string(session_.sceneAttempt());
  reportRecordError();
}

void PlayScreen::toggleMute() {
  muted_ = !muted_;
  if (!config_.sound.available && !config_.sound.problem_reported) {
    config_.sound.problem_reported = true;
    say("cardemo play: " + config_.sound.problem);
  }
  note_ = !config_.sound.available ? "no sound: see the terminal"
          : muted_                 ? "sound off"
                                   : "sound on";
}

void PlayScreen::runSteps(int steps, const PadState& pad) {
  for (int i = 0; i < steps && !ended(); ++i) {
    const bool was_recording = session_.recording();
    last_input_ =
        session_.step(mergeInputs(latch_.sample(), analog_.sample(pad, session_.world())));
    notePublished(was_recording);  // GAME OVER publishes the recording at once
    ++out_.steps;
    effects_.observe(session_.world());
    rig_.step(session_.world());
    if (level_.observe(session_.world()) && level_.over()) {
      writeSummary();
      if (level_.challenge()->parkedFrame()) out_.chime = true;
      // Nothing more is simulated: publish this attempt's recording now, as GAME OVER does.
      (void)publishRecording();
    }
    const int bays_before = chain_.chain() != nullptr ? chain_.chain()->count() : 0;
    if (chain_.observe(session_.world())) {
      writeSummary();
      (void)publishRecording();
    }
    // Each bay of the chain parked chimes, as a level's bay does.
    if (chain_.chain() != nullptr && chain_.chain()->count() > bays_before) out_.chime = true;
    if (config_.on_step) config_.on_step(session_.world().frame());
    // A replay that runs out mid-frame hands over at once, not after the frame's other steps.
    flow_.update(session_.playingBack(), ended());
    if (flow_.holding()) break;
  }
}

void PlayScreen::reportAfterSteps() {
  if (std::string warning = level_.takeWarning(); !warning.empty()) say(std::move(warning));
  if (std::string warning = chain_.takeWarning(); !warning.empty()) say(std::move(warning));
  reportRecordError();
  if (session_.world().gameOver() && !over_reported_) {
    over_reported_ = true;
    writeSummary();
    reportRecordError();
  }
}

void PlayScreen::compose(const Eigen::Vector2i& viewport) {
  const World& world = session_.world();
  const bool frozen = flow_.holding() || world.gameOver() || level_.over();
  const double alpha = frozen ? 1.0 : clock_.alpha();
  out_.world = &world;
  out_.player_box = session_.blendedBox(alpha);
  out_.camera = rig_.camera(viewport, alpha, zoom_ / kDefaultZoom, effects_.shake());
  out_.muted = muted_;
  DrawOptions& draw = out_.draw;
  // After the end nothing runs anyway: the end panel, not PAUSED, says what is going on.
  draw.paused = (flow_.paused() && !ended()) || flow_.help();
  draw.help = flow_.help();
  draw.banner = flow_.yourTurn() ? kYourTurn : "";
  draw.fps = fps_;
  draw.playback_speed = session_.playingBack() && !ended() ? flow_.chosenSpeed() : 0.0;
  draw.status = statusLine(session_, config_.replay_path, note_, ended());
  draw.run_over = ended();
  draw.game_over_keys = endPanelKeys(config_.links, false);
  draw.effects = &effects_;
  draw.sprites = true;
  draw.goal = nullptr;
  if (const ParkingChallenge* challenge = level_.challenge()) {
    goal_view_ = GoalView{};
    goal_view_.challenge = challenge;
    goal_view_.best = level_.best();
    goal_view_.new_best = level_.newBest();
    goal_view_.keys = endPanelKeys(config_.links, challenge->parkedFrame().has_value());
    draw.game_over_rows = runSummaryRows(world, goal_view_);
    draw.goal = &goal_view_;
  } else if (const BayChain* chain = chain_.chain()) {
    goal_view_ = GoalView{};
    goal_view_.challenge = &chain->challenge();
    goal_view_.new_best = chain_.newBest();
    goal_view_.keys = endPanelKeys(config_.links, false);
    goal_view_.chain = chain;
    goal_view_.chain_best = chain_.best();
    draw.game_over_rows = chainSummaryRows(world, goal_view_);
    draw.goal = &goal_view_;
  }
}

std::string PlayScreen::publishRecording() {
  const bool was_recording = session_.recording();
  std::string why = session_.finishRecording();
  notePublished(was_recording);
  return why;
}

void PlayScreen::notePublished(bool was_recording) {
  if (was_recording && !session_.recording() && session_.recordError().empty()) {
    published_.push_back(session_.recordPath());
  }
}

void PlayScreen::writeSummary() {
  if (config_.json_path.empty()) return;
  const std::string text = summary().dump(2) + "\n";
  if (std::string why = writeFileAtomically(config_.json_path, text); !why.empty()) {
    say(std::move(why));
    status_ = 2;
  }
}

nlohmann::json PlayScreen::summary() const {
  nlohmann::json j = summaryJson(session_.world(), level_.challenge());
  if (const BayChain* chain = chain_.chain()) {
    nlohmann::json& c = j["bay_chain"] = bayChainJson(*chain);
    // The best as the end panel shows it: this chain's when it was just saved as the best.
    const std::optional<ChainScore> best = chain_.newBest() ? chain->score() : chain_.best();
    c["best"] = best ? nlohmann::json(best->count) : nlohmann::json(nullptr);
    c["new_best"] = chain_.newBest();
  }
  return j;
}

void PlayScreen::reportRecordError() {
  // Once per attempt: a failed write is said at once, and the game goes on.
  if (record_error_reported_ || session_.recordError().empty()) return;
  record_error_reported_ = true;
  say(session_.recordError());
  note_ = "recording failed: see the terminal";
  status_ = 2;
}

}  // namespace cardemo
