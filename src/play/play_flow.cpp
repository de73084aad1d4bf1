#include "play/play_flow.hpp"

#include <algorithm>

namespace cardemo {

LevelExit escapeExit(const LevelLinks& links) {
  return links.from_picker ? LevelExit::kPicker : LevelExit::kQuit;
}

std::string endPanelKeys(const LevelLinks& links, bool parked) {
  std::string keys = "Enter retry";
  if (parked && links.has_next) keys += "    N next level";
  keys += links.from_picker ? "    Esc levels" : "    Esc quit";
  return keys;
}

LevelExit PlayFlow::next(bool parked, const LevelLinks& links) {
  if (parked) return links.has_next ? LevelExit::kNextLevel : LevelExit::kStay;
  stepOnce();
  return LevelExit::kStay;
}

void PlayFlow::faster() {
  speed_ = std::min(kMaxSpeed, speed_ * 2.0);
}

void PlayFlow::slower() {
  speed_ = std::max(kMinSpeed, speed_ * 0.5);
}

void PlayFlow::update(bool playing_back, bool ended) {
  playing_back_ = playing_back;
  if (was_playing_back_ && !playing_back && !ended) {
    // A replay just ran out: stop here until the player acts, so the keyboard never takes over
    // unannounced, and never at the replay's speed.
    your_turn_ = true;
    speed_ = 1.0;
  }
  was_playing_back_ = playing_back;
}

bool PlayFlow::confirm(bool ended) {
  your_turn_ = false;
  return ended;
}

void PlayFlow::restarted() {
  your_turn_ = false;
  was_playing_back_ = false;
  step_once_ = false;
}

int PlayFlow::stepsToRun(int clock_steps) {
  const bool once = step_once_;
  step_once_ = false;
  if (help_ || your_turn_) return 0;
  if (paused_) return once ? 1 : 0;
  return clock_steps;
}

}  // namespace cardemo
