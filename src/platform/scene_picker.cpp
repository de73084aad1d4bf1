#include "platform/scene_picker.hpp"

#include <SDL.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "platform/sdl_canvas.hpp"
#include "platform/sdl_keys.hpp"
#include "platform/sdl_window.hpp"
#include "platform/stop_signal.hpp"
#include "play/key_map.hpp"
#include "play/picker_flow.hpp"
#include "play/picker_screen.hpp"
#include "render/scene_picker_view.hpp"

namespace cardemo {
namespace {

constexpr const char* kPickerName = "choose a scene";

}  // namespace

std::optional<int> runScenePicker(SdlWindow& window, const std::vector<LevelEntry>& entries,
                                  const BestScores& best, int selected) {
  window.setTitle(windowTitle(kPickerName));
  PickerScreen picker(entries, best, selected);
  SdlCanvas canvas(window.renderer());
  // Keys held or pressed in the game that opened the picker are not choices made in it.
  SDL_PumpEvents();
  SDL_FlushEvents(SDL_KEYDOWN, SDL_KEYUP);
  while (stopSignal() == 0) {
    SDL_Event e;
    while (SDL_PollEvent(&e) != 0) {
      if (e.type == SDL_QUIT) return std::nullopt;
      if (e.type != SDL_KEYDOWN) continue;
      const std::optional<GameKey> key = gameKeyOf(e.key.keysym);
      const std::optional<PickerAction> action =
          key ? pickerActionOf(*key, e.key.repeat != 0) : std::nullopt;
      if (action && picker.act(*action)) return picker.choice();
    }
    drawScenePicker(canvas, picker.rows(), picker.selected(), picker.progress());
    SDL_RenderPresent(window.renderer());
    SDL_Delay(15);
  }
  return std::nullopt;
}

int runPickerAndLevels(const std::vector<LevelEntry>& entries, const GameWindowOptions& base) {
  std::string error;
  const std::unique_ptr<SdlWindow> window = SdlWindow::open(windowTitle(kPickerName), error);
  if (!window) {
    std::fprintf(stderr, "cardemo play: %s\n", error.c_str());
    return 1;
  }
  installStopSignals();
  const std::string& best_path = base.play.best_scores_path;
  int status = 0;
  PickerFlow flow(entries, base.play.session.first_attempt);
  while (stopSignal() == 0 && !flow.done()) {
    if (flow.picking()) {
      std::string warning;
      const BestScores best = best_path.empty() ? BestScores() : loadBestScores(best_path, warning);
      if (!warning.empty()) std::fprintf(stderr, "%s\n", warning.c_str());
      flow.picked(runScenePicker(*window, entries, best, flow.selected()));
      continue;
    }
    Parsed<PlayScreenConfig> level = flow.levelConfig(base.play);
    if (!level.ok()) {
      std::fprintf(stderr, "%s\n", level.error().toString().c_str());
      return 2;
    }
    GameWindowOptions options = base;
    options.play = std::move(level).value();
    const GameOutcome outcome = runGame(*window, options);
    status = std::max(status, outcome.status);
    flow.levelEnded(outcome);
  }
  if (stopSignal() != 0) std::fprintf(stderr, "cardemo play: stopped by signal %d\n", stopSignal());
  return status;
}

}  // namespace cardemo
