// SDL2_mixer is loaded at run time, not linked: on a machine that builds the game (the mixer is a
// build dependency) it loads, with every function the game calls, and a second call returns the
// same table.
#include "platform/mixer_library.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cardemo {
namespace {

TEST(MixerLibrary, LoadsWithEveryFunction) {
  std::string why;
  const MixerLibrary* mix = mixerLibrary(why);
  ASSERT_NE(mix, nullptr) << why;
  EXPECT_TRUE(why.empty());
  EXPECT_NE(mix->OpenAudio, nullptr);
  EXPECT_NE(mix->LoadWAV, nullptr);
  EXPECT_NE(mix->PlayChannel, nullptr);
  EXPECT_NE(mix->HaltChannel, nullptr);
  // Without a device the mixer reports it is closed (0), as the GameAudio destructor expects.
  EXPECT_EQ(mix->QuerySpec(nullptr, nullptr, nullptr), 0);
  std::string again;
  EXPECT_EQ(mixerLibrary(again), mix);
}

}  // namespace
}  // namespace cardemo
