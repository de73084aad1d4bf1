#include "platform/scene_picker.hpp"

#include <SDL.h>

#include <cstdio>
#include <memory>

#include "platform/sdl_canvas.hpp"
#include "render/goal_overlay.hpp"
#include "render/scene_picker_view.hpp"

namespace cardemo {
namespace {

struct SdlDeleter {
  void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
  void operator()(SDL_Renderer* r) const { SDL_DestroyRenderer(r); }
};

std::vector<PickerRow> pickerRows(const std::vector<LevelEntry>& entries, const BestScores& best) {
  std::vector<PickerRow> rows;
  for (const LevelEntry& e : entries) {
    if (e.free_drive) {
      rows.push_back({e.title, "no goal"});
      continue;
    }
    const ParkingScore* score = best.find(e.scene_name);
    rows.push_back({std::to_string(e.order) + "   " + e.title,
                    score == nullptr
                        ? std::string("not parked yet")
                        : secondsText(score->seconds) + "  " + starsText(score->stars)});
  }
  return rows;
}

}  // namespace

std::optional<std::string> runScenePicker(const std::vector<LevelEntry>& entries,
                                          const BestScores& best, int& status) {
  status = 0;
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr, "cardemo play: cannot open a display (%s)\n", SDL_GetError());
    status = 1;
    return std::nullopt;
  }
  std::unique_ptr<SDL_Window, SdlDeleter> window(
      SDL_CreateWindow("cardemo \xE2\x80\x94 choose a scene", SDL_WINDOWPOS_CENTERED,
                       SDL_WINDOWPOS_CENTERED, 1280, 720, SDL_WINDOW_RESIZABLE));
  std::unique_ptr<SDL_Renderer, SdlDeleter> renderer;
  if (window) renderer.reset(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_PRESENTVSYNC));
  if (window && !renderer) {
    renderer.reset(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_SOFTWARE));
  }
  if (!renderer) {
    std::fprintf(stderr, "cardemo play: cannot open a window (%s)\n", SDL_GetError());
    renderer.reset();
    window.reset();
    SDL_Quit();
    status = 1;
    return std::nullopt;
  }
  const std::vector<PickerRow> rows = pickerRows(entries, best);
  const int count = static_cast<int>(rows.size());
  std::optional<std::string> chosen;
  {
    SdlCanvas canvas(renderer.get());
    int selected = 0;
    bool done = false;
    while (!done) {
      SDL_Event e;
      while (SDL_PollEvent(&e) != 0) {
        if (e.type == SDL_QUIT) done = true;
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
            if (count > 0 && e.key.repeat == 0) {
              chosen = entries[static_cast<std::size_t>(selected)].path;
              done = true;
            }
            break;
          case SDLK_ESCAPE:
            done = true;
            break;
          default:
            break;
        }
      }
      drawScenePicker(canvas, rows, selected);
      SDL_RenderPresent(renderer.get());
      SDL_Delay(15);
    }
  }
  renderer.reset();
  window.reset();
  // With a scene chosen SDL stays initialised for the game window (runGameWindow's SDL_Init only
  // counts up, and its SDL_Quit ends both): quitting X11 video and starting it again in the same
  // process sometimes left the game window off the display under Xvfb on a loaded machine (the game
  // ran, xdotool saw only the root window).
  if (!chosen) SDL_Quit();
  return chosen;
}

}  // namespace cardemo
