#include "platform/scene_picker.hpp"

#include <SDL.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "io/scene_json.hpp"
#include "platform/sdl_canvas.hpp"
#include "platform/sdl_window.hpp"
#include "platform/stop_signal.hpp"
#include "render/goal_overlay.hpp"
#include "render/scene_picker_view.hpp"

namespace cardemo {
namespace {

std::vector<PickerRow> pickerRows(const std::vector<LevelEntry>& entries, const BestScores& best) {
  std::vector<PickerRow> rows;
  for (const LevelEntry& e : entries) {
    if (e.free_drive) {
      rows.push_back({e.title, "no goal", e.task});
      continue;
    }
    const ParkingScore* score = best.find(e.scene_name);
    rows.push_back({std::to_string(e.order) + "   " + e.title,
                    score == nullptr ? std::string("not parked yet")
                                     : secondsText(score->seconds) + "  " + starsText(score->stars),
                    e.task});
  }
  return rows;
}

constexpr const char* kPickerName = "choose a scene";

}  // namespace

std::optional<int> runScenePicker(SdlWindow& window, const std::vector<LevelEntry>& entries,
                                  const BestScores& best, int selected) {
  window.setTitle(windowTitle(kPickerName));
  const std::vector<PickerRow> rows = pickerRows(entries, best);
  const std::string progress = progressText(levelProgress(entries, best));
  const int count = static_cast<int>(rows.size());
  selected = count > 0 ? std::clamp(selected, 0, count - 1) : 0;
  SdlCanvas canvas(window.renderer());
  // Keys held or pressed in the game that opened the picker are not choices made in it.
  SDL_PumpEvents();
  SDL_FlushEvents(SDL_KEYDOWN, SDL_KEYUP);
  while (stopSignal() == 0) {
    SDL_Event e;
    while (SDL_PollEvent(&e) != 0) {
      if (e.type == SDL_QUIT) return std::nullopt;
      if (e.type != SDL_KEYDOWN) continue;
      switch (e.key.keysym.sym) {
        case SDLK_UP:
        case SDLK_w:
          selected = moveSelection(selected, -1, count);
          break;
        case SDLK_DOWN:
        case SDLK_s:
          selected = moveSelection(selected, 1, count);
          break;
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
          if (count > 0 && e.key.repeat == 0) return selected;
          break;
        case SDLK_ESCAPE:
          if (e.key.repeat == 0) return std::nullopt;
          break;
        default:
          break;
      }
    }
    drawScenePicker(canvas, rows, selected, progress);
    SDL_RenderPresent(window.renderer());
    SDL_Delay(15);
  }
  return std::nullopt;
}

int runPickerAndLevels(const std::vector<LevelEntry>& entries, const GameWindowOptions& base,
                       const std::string& best_path) {
  std::string error;
  const std::unique_ptr<SdlWindow> window = SdlWindow::open(windowTitle(kPickerName), error);
  if (!window) {
    std::fprintf(stderr, "cardemo play: %s\n", error.c_str());
    return 1;
  }
  installStopSignals();
  int status = 0;
  int selected = 0;
  int next_attempt = std::max(1, base.session.first_attempt);
  int play = -1;  // the entry to open without showing the picker (N: next level), or -1
  while (stopSignal() == 0) {
    if (play < 0) {
      std::string warning;
      const BestScores best = best_path.empty() ? BestScores() : loadBestScores(best_path, warning);
      if (!warning.empty()) std::fprintf(stderr, "%s\n", warning.c_str());
      play = runScenePicker(*window, entries, best, selected).value_or(-1);
      if (play < 0) break;
    }
    const auto index = static_cast<std::size_t>(play);
    selected = play;
    const LevelEntry& entry = entries[index];
    Parsed<Scene> scene = loadScene(entry.path);
    if (!scene.ok()) {
      std::fprintf(stderr, "%s\n", scene.error().toString().c_str());
      return 2;
    }
    GameWindowOptions options = base;
    options.session.scene = std::move(scene).value();
    options.session.scene_path = entry.path;
    options.session.first_attempt = next_attempt;
    options.links = {true, nextLevel(entries, index).has_value()};
    const GameOutcome outcome = runGame(*window, options);
    status = std::max(status, outcome.status);
    next_attempt = outcome.last_attempt + 1;
    if (outcome.exit == LevelExit::kNextLevel) {
      play = static_cast<int>(nextLevel(entries, index).value_or(0));
    } else if (outcome.exit == LevelExit::kPicker) {
      play = -1;
    } else {
      break;
    }
  }
  if (stopSignal() != 0) std::fprintf(stderr, "cardemo play: stopped by signal %d\n", stopSignal());
  return status;
}

}  // namespace cardemo
