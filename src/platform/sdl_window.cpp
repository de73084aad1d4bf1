#include "platform/sdl_window.hpp"

namespace cardemo {

std::unique_ptr<SdlWindow> SdlWindow::open(const std::string& title, std::string& error) {
  // Our own handlers finish the recording; SDL's would only post SDL_QUIT.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    error = std::string("cannot open a display (") + SDL_GetError() + ")";
    return nullptr;
  }
  // A controller is optional: without the subsystem the game simply has none.
  (void)SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER);
  std::unique_ptr<SdlWindow> w(new SdlWindow());
  w->window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, 1280,
                                720, SDL_WINDOW_RESIZABLE);
  if (w->window_ == nullptr) {
    error = std::string("cannot open a window (") + SDL_GetError() + ")";
    return nullptr;
  }
  w->renderer_ = SDL_CreateRenderer(w->window_, -1, SDL_RENDERER_PRESENTVSYNC);
  if (w->renderer_ == nullptr)
    w->renderer_ = SDL_CreateRenderer(w->window_, -1, SDL_RENDERER_SOFTWARE);
  if (w->renderer_ == nullptr) {
    error = std::string("cannot create a renderer (") + SDL_GetError() + ")";
    return nullptr;
  }
  return w;
}

SdlWindow::~SdlWindow() {
  if (renderer_ != nullptr) SDL_DestroyRenderer(renderer_);
  if (window_ != nullptr) SDL_DestroyWindow(window_);
  SDL_Quit();
}

void SdlWindow::setTitle(const std::string& title) {
  SDL_SetWindowTitle(window_, title.c_str());
}

std::string windowTitle(const std::string& name) {
  return "cardemo \xE2\x80\x94 " + name;
}

}  // namespace cardemo
