#pragma once
/// Random byte-level edits of a valid input, shared by the tests that throw mutated files at the
/// readers (tests/io/mutation_test.cpp, tests/io/scene_json_fast_test.cpp).

#include <cstddef>
#include <random>
#include <string>
#include <string_view>

namespace cardemo::test {

/// How mutateText edits a text.
struct TextMutation {
  std::string_view interesting;    ///< Bytes inserted or written half the time (else any byte).
  int max_edits = 3;               ///< Each call makes 1 to max_edits edits.
  std::size_t max_duplicate = 16;  ///< Longest byte run duplicated in place.
  bool change_digits = false;      ///< Also replace a digit (mostly a valid input, another value).
};

/// `s` after random edits: replace, insert, delete or duplicate a byte range, change a digit
/// (when asked), or truncate.
inline std::string mutateText(std::string s, std::mt19937_64& rng, const TextMutation& how) {
  const int edits = 1 + static_cast<int>(rng() % static_cast<unsigned>(how.max_edits));
  for (int i = 0; i < edits && !s.empty(); ++i) {
    const std::size_t at = rng() % s.size();
    const char c = (rng() % 2) ? how.interesting[rng() % how.interesting.size()]
                               : static_cast<char>(rng() % 256);
    switch (rng() % (how.change_digits ? 6 : 5)) {
      case 0:
        s[at] = c;
        break;
      case 1:
        s.insert(at, 1, c);
        break;
      case 2:
        s.erase(at, 1 + rng() % 8);
        break;
      case 3:
        s.insert(at, s.substr(at, 1 + rng() % how.max_duplicate));
        break;
      case 4:
        if (how.change_digits) {
          if (const auto d = s.find_first_of("0123456789", at); d != std::string::npos) {
            s[d] = static_cast<char>('0' + rng() % 10);
          }
          break;
        }
        s.resize(at);
        break;
      default:
        s.resize(at);
        break;
    }
  }
  return s;
}

}  // namespace cardemo::test
