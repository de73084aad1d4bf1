// Padded text (io/padded_text, built with simdjson): the file's bytes exactly, zero bytes after
// them, and readInputFile's errors word for word.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "../support/temp_dir.hpp"
#include "io/input_error.hpp"

#if CARDEMO_WITH_SIMDJSON
#include "io/padded_text.hpp"
#endif

namespace cardemo {
namespace padded_text_test {
namespace {

#if CARDEMO_WITH_SIMDJSON

::testing::AssertionResult paddedWithZeros(const PaddedText& text) {
  const char* past_end = text.view().data() + text.view().size();
  for (std::size_t i = 0; i < PaddedText::kPadding; ++i) {
    if (past_end[i] != 0) return ::testing::AssertionFailure() << "byte " << i << " past the end";
  }
  return ::testing::AssertionSuccess();
}

class PaddedFiles : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::freshTempDir("padded_text"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& contents) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << contents;
    return p.string();
  }

  std::filesystem::path dir_;
};

TEST_F(PaddedFiles, ReadsEveryByteOfSmallAndLargeFiles) {
  std::mt19937_64 rng(3);
  // Sizes around the page and the huge page, where the padding crosses into the next one.
  for (const std::size_t size :
       {std::size_t{1}, std::size_t{63}, std::size_t{4096 - 64}, std::size_t{4096 - 1},
        std::size_t{4096}, std::size_t{(2u << 20) - 64}, std::size_t{(2u << 20) + 5},
        std::size_t{5u << 20}}) {
    std::string bytes(size, '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    const std::string path = write("f" + std::to_string(size), bytes);
    const Parsed<PaddedText> text = readPaddedFile(path, 64u << 20);
    ASSERT_TRUE(text.ok()) << text.error().toString();
    EXPECT_EQ(text.value().view(), bytes) << size;
    EXPECT_TRUE(paddedWithZeros(text.value())) << size;
  }
}

TEST_F(PaddedFiles, EmptyFileIsEmptyAndPadded) {
  const Parsed<PaddedText> text = readPaddedFile(write("empty", ""), 100);
  ASSERT_TRUE(text.ok());
  EXPECT_TRUE(text.value().view().empty());
  EXPECT_TRUE(paddedWithZeros(text.value()));
  EXPECT_TRUE(paddedWithZeros(PaddedText()));
}

TEST_F(PaddedFiles, ErrorsAreReadInputFilesErrors) {
  const std::string big = write("big", std::string(101, 'a'));
  for (const std::string& path :
       {(dir_ / "missing").string(), dir_.string(), big, std::string("/dev/zero")}) {
    const Parsed<PaddedText> padded = readPaddedFile(path, 100);
    const Parsed<std::string> plain = readInputFile(path, 100);
    ASSERT_FALSE(padded.ok()) << path;
    ASSERT_FALSE(plain.ok()) << path;
    EXPECT_EQ(padded.error().toString(), plain.error().toString());
  }
  const Parsed<PaddedText> at_limit = readPaddedFile(write("ok", std::string(100, 'a')), 100);
  ASSERT_TRUE(at_limit.ok());
  EXPECT_EQ(at_limit.value().view(), std::string(100, 'a'));
}

TEST(PaddedText, CopiesAndMoves) {
  PaddedText a = PaddedText::copyOf(std::string("scene\0text", 10));
  EXPECT_EQ(a.view(), std::string("scene\0text", 10));
  EXPECT_TRUE(paddedWithZeros(a));
  PaddedText b = std::move(a);
  EXPECT_EQ(b.view(), std::string("scene\0text", 10));
  EXPECT_TRUE(a.view().empty());  // NOLINT(bugprone-use-after-move): moved-from is empty
  EXPECT_TRUE(paddedWithZeros(a));
  b = PaddedText::copyOf("other");
  EXPECT_EQ(b.view(), "other");
}

#else

TEST(PaddedText, NotBuiltWithoutSimdjson) {
  GTEST_SKIP() << "CARDEMO_WITH_SIMDJSON is OFF";
}

#endif

}  // namespace
}  // namespace padded_text_test
}  // namespace cardemo
