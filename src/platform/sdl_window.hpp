#pragma once
/// SDL video, one window and its renderer: the scene picker and every game it opens share them, so
/// X11 video is started once per `cardemo play`.

#include <SDL.h>

#include <memory>
#include <string>

namespace cardemo {

/// Owns SDL's video (and controller) subsystem, the window and its renderer; SDL_Quit on close.
class SdlWindow {
 public:
  /// Initialises SDL and opens a 1280x720 resizable window titled `title`; nullptr (with the
  /// reason in `error`) when there is no display or no renderer.
  static std::unique_ptr<SdlWindow> open(const std::string& title, std::string& error);
  ~SdlWindow();
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  /// The window.
  [[nodiscard]] SDL_Window* window() const { return window_; }
  /// Its renderer (vsync, else software).
  [[nodiscard]] SDL_Renderer* renderer() const { return renderer_; }
  /// Sets the title ("cardemo — NAME"; tests find the window by it).
  void setTitle(const std::string& title);

 private:
  SdlWindow() = default;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
};

/// "cardemo — " followed by `name`.
[[nodiscard]] std::string windowTitle(const std::string& name);

}  // namespace cardemo
