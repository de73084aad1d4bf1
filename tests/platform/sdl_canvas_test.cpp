// The SDL canvas on a software renderer (no display): polygons, lines and text land where asked,
// and PNGs are saved atomically.

#include "platform/sdl_canvas.hpp"

#include <SDL.h>
#include <SDL_image.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "platform/font_path.hpp"
#include "platform/png_save.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

struct Target {
  std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)> surface{
      SDL_CreateRGBSurfaceWithFormat(0, 200, 100, 32, SDL_PIXELFORMAT_RGBA32), &SDL_FreeSurface};
  std::unique_ptr<SDL_Renderer, decltype(&SDL_DestroyRenderer)> renderer{
      SDL_CreateSoftwareRenderer(surface.get()), &SDL_DestroyRenderer};

  [[nodiscard]] Rgba at(int x, int y) const {
    const auto* p = static_cast<const std::uint8_t*>(surface->pixels) + y * surface->pitch + x * 4;
    return {p[0], p[1], p[2], p[3]};
  }
};

TEST(SdlCanvas, FillsConvexPolygonsAndThickLines) {
  Target t;
  ASSERT_TRUE(t.renderer) << SDL_GetError();
  {
    SdlCanvas canvas(t.renderer.get());
    EXPECT_EQ(canvas.size(), Eigen::Vector2i(200, 100));
    canvas.clear({10, 20, 30, 255});
    const std::array<Eigen::Vector2f, 4> quad{
        {{20.0f, 20.0f}, {60.0f, 20.0f}, {60.0f, 60.0f}, {20.0f, 60.0f}}};
    canvas.fillConvex(quad, {200, 50, 40, 255});
    canvas.line({100.0f, 50.0f}, {190.0f, 50.0f}, 6.0f, {40, 220, 60, 255});
    SDL_RenderPresent(t.renderer.get());
  }
  EXPECT_EQ(t.at(5, 5), (Rgba{10, 20, 30, 255}));
  EXPECT_EQ(t.at(40, 40), (Rgba{200, 50, 40, 255}));
  EXPECT_EQ(t.at(150, 50), (Rgba{40, 220, 60, 255}));
  EXPECT_EQ(t.at(150, 60), (Rgba{10, 20, 30, 255}));
}

TEST(SdlCanvas, DrawsTextWithTheDejaVuFont) {
  ASSERT_TRUE(findFontPath().has_value());
  Target t;
  SdlCanvas canvas(t.renderer.get());
  ASSERT_EQ(canvas.error(), "");
  const Eigen::Vector2f size = canvas.textSize("Speed 42 km/h", 16);
  EXPECT_GT(size.x(), 60.0f);
  EXPECT_GT(size.y(), 12.0f);
  EXPECT_LT(size.y(), 30.0f);
  EXPECT_GT(canvas.textSize("Speed 42 km/h, and more", 16).x(), size.x());
  canvas.clear({0, 0, 0, 255});
  canvas.text({10.0f, 10.0f}, "HHHH", 24, {255, 255, 255, 255});
  canvas.text({10.0f, 10.0f}, "HHHH", 24, {255, 255, 255, 255});  // the cached texture
  SDL_RenderPresent(t.renderer.get());
  int lit = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 200; ++x) lit += t.at(x, y).r > 128 ? 1 : 0;
  }
  EXPECT_GT(lit, 50);
}

// The font shipped in assets/fonts comes before any system one.
TEST(FontPath, TheBundledFontComesFirst) {
  const char* old = std::getenv("CARDEMO_ASSETS");
  const std::string saved = old ? old : "";
  const std::string assets = std::string(CARDEMO_SOURCE_DIR) + "/assets";
  ::setenv("CARDEMO_ASSETS", assets.c_str(), 1);
  EXPECT_EQ(findFontPath(),
            std::filesystem::path(assets + "/fonts/DejaVuSans.ttf").lexically_normal().string());
  if (old) {
    ::setenv("CARDEMO_ASSETS", saved.c_str(), 1);
  } else {
    ::unsetenv("CARDEMO_ASSETS");
  }
}

// CARDEMO_ASSETS is searched first, not only: a folder without the font falls through to the
// next folders (next to the executable, then the system's DejaVu).
TEST(FontPath, AnAssetsFolderWithoutTheFontFallsThrough) {
  const char* old = std::getenv("CARDEMO_ASSETS");
  const std::string saved = old ? old : "";
  ::setenv("CARDEMO_ASSETS", "/no/such/dir", 1);
  std::string why;
  const std::optional<std::string> found = findFontPath(&why);
  ASSERT_TRUE(found.has_value()) << why;
  EXPECT_TRUE(fs::exists(*found)) << *found;
  EXPECT_EQ(found->find("/no/such/dir"), std::string::npos) << *found;
  if (old) {
    ::setenv("CARDEMO_ASSETS", saved.c_str(), 1);
  } else {
    ::unsetenv("CARDEMO_ASSETS");
  }
}

TEST(SavePng, WritesAtomicallyAndReportsUnwritablePaths) {
  Target t;
  const fs::path dir = fs::path(::testing::TempDir()) / "cardemo-save-png";
  fs::create_directories(dir);
  const fs::path out = dir / "shot.png";
  EXPECT_EQ(savePng(t.surface.get(), out.string()), "");
  std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)> back(IMG_Load(out.c_str()),
                                                                &SDL_FreeSurface);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->w, 200);
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename(), "shot.png");  // no temporary file left behind
  }
  const std::string why = savePng(t.surface.get(), "/no/such/dir/shot.png");
  EXPECT_NE(why.find("/no/such/dir/shot.png"), std::string::npos) << why;
  EXPECT_EQ(saveRendererPng(t.renderer.get(), out.string()), "");
}

}  // namespace
}  // namespace cardemo
