#pragma once
/// The page's game: the scene picker and the levels it opens, or a replay being watched, one
/// drawn frame at a time. It only carries out what PickerScreen and PlayScreen decide.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "play/key_map.hpp"
#include "play/picker_flow.hpp"
#include "play/picker_screen.hpp"
#include "play/play_screen.hpp"
#include "web/web_audio.hpp"
#include "web/web_canvas.hpp"

namespace cardemo {

/// Where the page keeps its files in the wasm file system (the bundled scenes are preloaded).
struct WebPaths {
  std::string assets = "/assets";  ///< Holds scenes/ (and replays/, where recordings go).
  std::string best_scores = "/home/web_user/best-scores.json";  ///< Synced with localStorage.
  std::string recording = "/assets/replays/web.replay";         ///< First attempt's recording.
};

/// Where the last frame's time went, in milliseconds (for the page's benchmark).
struct FrameParts {
  double update = 0.0;  ///< PlayScreen's step: input, simulation, camera, effects, sound.
  double draw = 0.0;    ///< Building the frame's canvas commands (C++).
  double flush = 0.0;   ///< The page replaying them on the 2D context (JavaScript).
};

/// The game in the page.
class WebApp {
 public:
  /// Lists the levels and shows the picker.
  explicit WebApp(WebPaths paths);

  /// Watches the replay at `path` (its scene resolved relative to it); `to_the_end` runs it to
  /// its end at once. A bad file shows its `FILE:LINE: ...` in the status and the picker stays.
  void watch(const std::string& path, bool to_the_end);
  /// A key went down (`repeat`: the keyboard's auto-repeat) or up.
  void key(GameKey key, bool down, bool repeat);
  /// The page lost the keyboard focus: no key is held any more.
  void blur();
  /// One drawn frame, `elapsed_seconds` after the previous one.
  void frame(double elapsed_seconds);
  /// Where the last frame's time went.
  [[nodiscard]] const FrameParts& lastFrameParts() const { return parts_; }

 private:
  void showPicker();
  void pickerFrame();
  void startLevel();
  void levelFrame(double elapsed_seconds);
  void leaveLevel();
  void say(const std::vector<std::string>& lines);
  void showError(std::string error);
  void showWorld(const World& world);
  void showOutcome();
  void offerRecordings();
  [[nodiscard]] BestScores loadBest();

  WebPaths paths_;
  WebCanvas canvas_;
  WebAudio audio_;
  PickerFlow flow_;
  PlayScreenConfig base_;
  std::unique_ptr<PickerScreen> picker_;
  std::unique_ptr<PlayScreen> screen_;
  std::vector<PlayAction> actions_;
  std::vector<PickerAction> picker_actions_;
  std::map<int, std::string> picker_status_;  // row -> status of its scene at frame 0
  std::string status_;
  std::string error_;  // a bad file's FILE:LINE text, shown until the picker's selection moves
  int error_row_ = 0;
  std::string outcome_;
  bool to_the_end_ = false;
  bool muted_ = false;
  bool was_over_ = false;
  FrameParts parts_;
};

}  // namespace cardemo
