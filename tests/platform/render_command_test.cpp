// `cardemo render` golden tests by property (size, colours where the cars are, frames differ), not
// exact pixels, which vary across SDL versions. CommandResult with no DISPLAY to prove none is
// needed.

#include <SDL.h>
#include <SDL_image.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "../support/cli_run.hpp"
#include "io/scene_json.hpp"
#include "render/draw_world.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

const std::string kSource = CARDEMO_SOURCE_DIR;
const std::string kLot = kSource + "/assets/scenes/parking-lot.json";
const std::string kHeadOn = kSource + "/assets/replays/head-on.replay";

// A file in the test's own scratch folder, so tests run in parallel (ctest -j) share no files.
fs::path scratch(const std::string& name) {
  return test::scratchDir() / name;
}

using CommandResult = test::CliResult;

// Runs `cardemo render ARGS` with no display in the environment.
CommandResult render(const std::string& args) {
  return test::runCardemo("render " + args, "",
                          "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER");
}

using Surface = std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)>;

Surface loadRgba(const fs::path& path) {
  Surface loaded(IMG_Load(path.c_str()), &SDL_FreeSurface);
  if (!loaded) return {nullptr, &SDL_FreeSurface};
  return {SDL_ConvertSurfaceFormat(loaded.get(), SDL_PIXELFORMAT_RGBA32, 0), &SDL_FreeSurface};
}

Rgba pixel(const SDL_Surface& s, int x, int y) {
  const auto* p = static_cast<const std::uint8_t*>(s.pixels) + y * s.pitch + x * 4;
  return {p[0], p[1], p[2], p[3]};
}

bool near(const Rgba& a, const Rgba& b, int tol = 3) {
  return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

std::string str(const Rgba& c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + ")";
}

// A parked car of the bundled lot and the pixel of the default 1280x720 render at its centre.
struct ParkedPixel {
  std::string id;
  Rgba color;
};

// The centre pixel of every parked car of the bundled lot that lies clear of the HUD panels, with
// the camera `cardemo render` uses by default (following the player at 12 m).
std::vector<ParkedPixel> parkedCarPixels(const SDL_Surface& img) {
  const Parsed<Scene> scene = loadScene(kLot);
  EXPECT_TRUE(scene.ok());
  std::vector<ParkedPixel> pixels;
  if (!scene.ok()) return pixels;
  const Obb2 player =
      Obb2::fromDegrees(scene.value().player.position, scene.value().player.heading_deg,
                        scene.value().player.length, scene.value().player.width);
  const Camera camera = followCamera(player, 12.0, {1280, 720});
  for (const ParkedCar& car : scene.value().parked) {
    const Eigen::Vector2f s = camera.toScreen(car.box.center);
    if (s.x() < 320 || s.x() > 1100 || s.y() < 160 || s.y() > 640) continue;
    pixels.push_back({car.id, pixel(img, static_cast<int>(s.x()), static_cast<int>(s.y()))});
  }
  return pixels;
}

bool samePixels(const SDL_Surface& a, const SDL_Surface& b) {
  if (a.w != b.w || a.h != b.h) return false;
  for (int y = 0; y < a.h; ++y) {
    if (std::memcmp(static_cast<const char*>(a.pixels) + y * a.pitch,
                    static_cast<const char*>(b.pixels) + y * b.pitch,
                    static_cast<std::size_t>(a.w) * 4) != 0) {
      return false;
    }
  }
  return true;
}

TEST(RenderCommand, SceneFrameZeroHasThePlayerAtTheCentreAndParkedCarsInTheirColours) {
  const fs::path out = scratch("lot.png");
  const CommandResult run = render("'" + kLot + "' --out '" + out.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface img = loadRgba(out);
  ASSERT_TRUE(img) << IMG_GetError();
  EXPECT_EQ(img->w, 1280);
  EXPECT_EQ(img->h, 720);
  const Palette palette;
  EXPECT_TRUE(near(pixel(*img, 640, 360), palette.player)) << str(pixel(*img, 640, 360));

  // Every parked car whose centre is clear of the HUD panels shows the parked colour there.
  const std::vector<ParkedPixel> parked = parkedCarPixels(*img);
  for (const auto& [id, c] : parked) EXPECT_TRUE(near(c, parkedColor(id))) << id << " " << str(c);
  EXPECT_GE(parked.size(), 5u);
  EXPECT_FALSE(fs::exists(out.string() + ".tmp"));
}

TEST(RenderCommand, SizeAndZoomOptions) {
  const fs::path out = scratch("small.png");
  const CommandResult run =
      render("'" + kLot + "' --width 320 --height 240 --zoom 30 --out '" + out.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface img = loadRgba(out);
  ASSERT_TRUE(img);
  EXPECT_EQ(img->w, 320);
  EXPECT_EQ(img->h, 240);
  // 240 px, the smallest height the HUD is laid out for: at 200 its panel reaches the centre.
  EXPECT_TRUE(near(pixel(*img, 160, 120), Palette{}.player)) << str(pixel(*img, 160, 120));
}

TEST(RenderCommand, ReplayFramesDifferAndThePlayerStaysAtTheCentre) {
  const fs::path first = scratch("head-on-0.png");
  const fs::path mid = scratch("head-on-800.png");
  const fs::path last = scratch("head-on-last.png");
  ASSERT_EQ(render("'" + kHeadOn + "' --frame 0 --out '" + first.string() + "'").status, 0);
  ASSERT_EQ(render("'" + kHeadOn + "' --frame 800 --out '" + mid.string() + "'").status, 0);
  const CommandResult run = render("'" + kHeadOn + "' --out '" + last.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface a = loadRgba(first);
  const Surface b = loadRgba(mid);
  const Surface c = loadRgba(last);
  ASSERT_TRUE(a && b && c);
  EXPECT_FALSE(samePixels(*a, *b));
  EXPECT_FALSE(samePixels(*b, *c));
  for (const Surface* s : {&a, &b, &c}) {
    EXPECT_TRUE(near(pixel(**s, 640, 360), Palette{}.player)) << str(pixel(**s, 640, 360));
  }
}

TEST(RenderCommand, DebugOverlayChangesTheImage) {
  const fs::path plain = scratch("plain.png");
  const fs::path debug = scratch("debug.png");
  ASSERT_EQ(render("'" + kHeadOn + "' --frame 849 --out '" + plain.string() + "'").status, 0);
  const CommandResult run =
      render("'" + kHeadOn + "' --frame 849 --debug --out '" + debug.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface a = loadRgba(plain);
  const Surface b = loadRgba(debug);
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(samePixels(*a, *b));
}

TEST(RenderCommand, BayChainHighlightsTheLotsFirstFreeBay) {
  // The lot's first free bay (x = -40, y = 8, 5.5 m along y) centred at 12 px/m: its heading
  // arrows (either way round counts) are yellow 23 px above and below the centre.
  const fs::path plain = scratch("lot-plain.png");
  const fs::path chain = scratch("lot-chain.png");
  const std::string at = " --center -40 8 --zoom 12 --out '";
  ASSERT_EQ(render("'" + kLot + "'" + at + plain.string() + "'").status, 0);
  const CommandResult run = render("'" + kLot + "' --bay-chain" + at + chain.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface a = loadRgba(plain);
  const Surface b = loadRgba(chain);
  ASSERT_TRUE(a && b);
  const Rgba arrow{255, 214, 70};
  for (const int y : {337, 383}) {
    EXPECT_TRUE(near(pixel(*b, 640, y), arrow)) << y << " " << str(pixel(*b, 640, y));
    EXPECT_FALSE(near(pixel(*a, 640, y), arrow)) << y << " " << str(pixel(*a, 640, y));
  }
}

TEST(RenderCommand, MissingInputIsExit2WithTheFileName) {
  const CommandResult run = render("/no/such/scene.json --out '" + scratch("x.png").string() + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("/no/such/scene.json"), std::string::npos) << run.err;
}

TEST(RenderCommand, FrameBeyondTheEndOfAReplayIsExit2) {
  const fs::path out = scratch("beyond.png");
  fs::remove(out);
  const CommandResult run = render("'" + kHeadOn + "' --frame 1741 --out '" + out.string() + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("beyond the end"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(render("'" + kHeadOn + "' --frame 1740 --out '" + out.string() + "'").status, 0);
}

TEST(RenderCommand, BadSceneIsExit2WithFileAndLine) {
  const fs::path bad = scratch("bad.json");
  std::ofstream(bad) << "{\n  \"format\": \"cardemo-scene/1\",\n  \"colour\": 3\n}\n";
  const CommandResult run =
      render("'" + bad.string() + "' --out '" + scratch("bad.png").string() + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err.rfind(bad.string() + ":", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

TEST(RenderCommand, BadReplayLineIsExit2WithFileAndLine) {
  const fs::path bad = scratch("bad.replay");
  std::ofstream(bad) << "cardemo-replay 1\nscene " << kLot << "\n10 X\n";
  const CommandResult run =
      render("'" + bad.string() + "' --out '" + scratch("bad.png").string() + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err.rfind(bad.string() + ":3:", 0), 0u) << run.err;
}

TEST(RenderCommand, UnwritableOutputIsExit2) {
  const CommandResult run = render("'" + kLot + "' --out /no/such/dir/out.png");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("/no/such/dir/out.png"), std::string::npos) << run.err;
}

TEST(RenderCommand, MissingOutIsAUsageError) {
  EXPECT_EQ(render("'" + kLot + "'").status, 2);
}

}  // namespace
}  // namespace cardemo

namespace cardemo {
namespace {

TEST(RenderCommand, SpritesChangeTheImageAndTintTheParkedCars) {
  const fs::path plain = scratch("plain.png");
  const fs::path sprites = scratch("sprites.png");
  ASSERT_EQ(render("'" + kLot + "' --out '" + plain.string() + "'").status, 0);
  const CommandResult run = render("'" + kLot + "' --sprites --out '" + sprites.string() + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const Surface a = loadRgba(plain);
  const Surface b = loadRgba(sprites);
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(samePixels(*a, *b));
  // The light-grey body sprite, tinted: a parked car's middle is darker than its paint but of the
  // same hue (its largest channel stays the largest).
  const std::vector<ParkedPixel> parked = parkedCarPixels(*b);
  for (const auto& [id, c] : parked) {
    const Rgba paint = parkedColor(id);
    EXPECT_LE(c.r, paint.r + 3) << id << " " << str(c);
    EXPECT_LE(c.g, paint.g + 3) << id << " " << str(c);
    EXPECT_LE(c.b, paint.b + 3) << id << " " << str(c);
    EXPECT_GE(c.r + c.g + c.b, (paint.r + paint.g + paint.b) * 7 / 10) << id << " " << str(c);
  }
  EXPECT_GE(parked.size(), 5u);
}

// A copy of cardemo outside the repository has no assets/ next to it or above it: the sprites
// come from CARDEMO_ASSETS or not at all (nothing is baked in at compile time), and the font falls
// back to the system's DejaVu.
TEST(RenderCommand, MissingSpritesAreExit2WithTheReason) {
  const fs::path bin = scratch("bin");
  fs::create_directories(bin);
  const fs::path copy = bin / "cardemo";
  fs::copy_file(CARDEMO_BINARY, copy, fs::copy_options::overwrite_existing);
  const fs::path out = scratch("none.png");
  const std::string args = "render '" + kLot + "' --sprites --out '" + out.string() + "'";
  const auto run = [&](const std::string& assets) {
    const fs::path err = scratch("stderr");
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY CARDEMO_ASSETS='" + assets +
                                "' '" + copy.string() + "' " + args + " >/dev/null 2>'" +
                                err.string() + "'";
    const int raw = std::system(command.c_str());
    return CommandResult{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, "", test::slurp(err)};
  };
  const CommandResult found = run(kSource + "/assets");
  EXPECT_EQ(found.status, 0) << found.err;
  const CommandResult missing = run("/no/such/dir");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err.rfind("sprites/car.png: not found", 0), 0u) << missing.err;
  EXPECT_NE(missing.err.find("/no/such/dir"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find((bin / "assets").string()), std::string::npos) << missing.err;
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  const fs::path err = scratch("stderr");
  const int raw =
      std::system(("env -u DISPLAY CARDEMO_ASSETS=/no/such/dir '" + copy.string() + "' render '" +
                   kLot + "' --out '" + out.string() + "' 2>'" + err.string() + "'")
                      .c_str());
  EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, 0)
      << "without --sprites only the font is needed, and the system's serves: " << test::slurp(err);
}

TEST(RenderCommand, RigKeepsThePictureInsideTheWalls) {
  // The player starts 15 m from the west wall of the lot: the follow camera shows the void beyond
  // it, the rig does not.
  const fs::path follow = scratch("follow.png");
  const fs::path rig = scratch("rig.png");
  ASSERT_EQ(render("'" + kLot + "' --zoom 20 --out '" + follow.string() + "'").status, 0);
  ASSERT_EQ(render("'" + kLot + "' --zoom 20 --rig --out '" + rig.string() + "'").status, 0);
  const Surface a = loadRgba(follow);
  const Surface b = loadRgba(rig);
  ASSERT_TRUE(a && b);
  const Rgba outside = Palette{}.outside;
  // Left edge, below the HUD panel.
  EXPECT_TRUE(near(pixel(*a, 2, 400), outside, 0)) << str(pixel(*a, 2, 400));
  EXPECT_FALSE(near(pixel(*b, 2, 400), outside, 0)) << str(pixel(*b, 2, 400));
  EXPECT_EQ(render("'" + kLot + "' --rig --center 0 0 --out '" + rig.string() + "'").status, 2);
}

}  // namespace
}  // namespace cardemo
