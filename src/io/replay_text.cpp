#include "io/replay_text.hpp"

#include <charconv>
#include <filesystem>
#include <utility>

#include "io/printable.hpp"
#include "io/text_lines.hpp"

// Syntax (docs/replay.md): after the header `cardemo-replay 1`, each line is one of
//   scene PATH | hz N | COUNT KEYS (`.` or letters of U D L R H) | expect health H | expect hits N
//   | expect hit FRAME ID | expect frames N | expect hash HEX16 | expect parked FRAME|never
// `#` starts a comment at the start of a line or after a space or tab (so ids and paths may hold
// '#'). Trailing spaces and a UTF-8 byte order mark before the header are tolerated (editors on
// Windows add one).

namespace cardemo {
namespace {

using text::trim;

/// Replay files larger than this are refused (about 8 million key changes).
constexpr std::size_t kMaxReplayBytes = 64u << 20;
constexpr std::string_view kHeader = "cardemo-replay 1";
constexpr std::int64_t kMaxExpectedHealth = 1'000'000;

// Strict non-negative decimal: digits only, no sign, no spaces; false when empty, malformed or
// above `max`.
bool parseWhole(std::string_view s, std::int64_t max, std::int64_t& out, bool& too_large) {
  too_large = false;
  if (s.empty()) return false;
  for (const char c : s) {
    if (c < '0' || c > '9') return false;
  }
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && v > max)) {
    too_large = true;
    return false;
  }
  if (ec != std::errc() || end != s.data() + s.size()) return false;
  out = v;
  return true;
}

// Splits off the first whitespace-separated word of `s` (already trimmed).
std::string_view firstWord(std::string_view& s) {
  std::size_t end = 0;
  while (end < s.size() && !text::isBlank(s[end])) ++end;
  const std::string_view word = s.substr(0, end);
  s = trim(s.substr(end));
  return word;
}

// One line of the file as a single pass over its bytes finds it: where it ends, its first control
// byte and where its comment starts (`#` at the start or after a blank).
struct ScannedLine {
  std::string_view text;                         // without '\n' and one trailing '\r'
  std::size_t control = std::string_view::npos;  // first control byte (not tab), or npos
  std::size_t comment = std::string_view::npos;  // first `#` that starts a comment, or npos
};

// Scans the line starting at `pos` and moves `pos` past its '\n'; false at the end of `src`.
bool scanLine(std::string_view src, std::size_t& pos, ScannedLine& out) {
  if (pos >= src.size()) return false;
  const char* const begin = src.data() + pos;
  const char* const end = src.data() + src.size();
  const char* p = begin;
  std::size_t control = std::string_view::npos;
  std::size_t comment = std::string_view::npos;
  for (; p != end; ++p) {
    const auto u = static_cast<unsigned char>(*p);
    if (u >= 0x20 && u != 0x7f) {
      if (u == '#' && comment == std::string_view::npos && (p == begin || text::isBlank(p[-1]))) {
        comment = static_cast<std::size_t>(p - begin);
      }
      continue;
    }
    if (u == '\n') break;
    if (u != '\t' && control == std::string_view::npos) {
      control = static_cast<std::size_t>(p - begin);
    }
  }
  std::size_t size = static_cast<std::size_t>(p - begin);
  pos += size + 1;
  // One '\r' before the '\n' (or the end) belongs to the line break, not to the line.
  if (size > 0 && begin[size - 1] == '\r') {
    --size;
    if (control == size) control = std::string_view::npos;
  }
  out = {std::string_view(begin, size), control, comment};
  return true;
}

bool parseKeys(std::string_view s, InputFrame& keys, std::string& why) {
  keys = {};
  if (s == ".") return true;
  for (const char c : s) {
    bool* key = nullptr;
    switch (c) {
      case 'U':
        key = &keys.up;
        break;
      case 'D':
        key = &keys.down;
        break;
      case 'L':
        key = &keys.left;
        break;
      case 'R':
        key = &keys.right;
        break;
      case 'H':
        key = &keys.handbrake;
        break;
      case 'u':
      case 'd':
      case 'l':
      case 'r':
      case 'h':
        why = "keys " + inQuotes(s) + ": use upper-case U, D, L, R, H";
        return false;
      case '.':
        why = "keys " + inQuotes(s) + ": \".\" means no keys and cannot be combined with letters";
        return false;
      default:
        why = "keys " + inQuotes(s) + ": unknown key " + inQuotes(std::string_view(&c, 1)) +
              " (expected U, D, L, R, H or \".\")";
        return false;
    }
    if (*key) {
      why = "keys " + inQuotes(s) + ": key " + std::string(1, c) + " repeated";
      return false;
    }
    *key = true;
  }
  return true;
}

bool isHash(std::string_view s) {
  if (s.size() != 16) return false;
  for (const char c : s) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

std::string resolveScene(const std::string& scene, const std::string& replay_file) {
  namespace fs = std::filesystem;
  const fs::path p(scene);
  if (scene.empty() || p.is_absolute() || replay_file == "-") return scene;
  const fs::path dir = fs::path(replay_file).parent_path();
  return dir.empty() ? scene : (dir / p).string();
}

// Parses one replay line at a time and keeps what the line-to-line checks need.
class ReplayParser {
 public:
  explicit ReplayParser(const std::string& file) : file_(file) {}

  std::optional<InputError> parse(std::string_view src, Replay& r) {
    std::size_t pos = 0;
    ScannedLine scanned;
    bool header = false;
    while (scanLine(src, pos, scanned)) {
      ++line_;
      std::string_view line = scanned.text;
      if (line.size() > kMaxLineBytes) {
        return error("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
      }
      if (!header) {
        // Line 1 (the header) may start with a byte order mark, which is not part of the line.
        if (line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
        if (const std::size_t at = text::findControl(line); at != std::string_view::npos) {
          return error("control character " + inQuotes(line.substr(at, 1)) + " in line");
        }
        if (auto e = parseHeader(src, line)) return e;
        header = true;
        continue;
      }
      if (scanned.control != std::string_view::npos) {
        return error("control character " + inQuotes(line.substr(scanned.control, 1)) + " in line");
      }
      line = trim(line.substr(0, scanned.comment));
      if (line.empty()) continue;
      if (auto e = parseLine(line, r)) return e;
    }
    if (!header) {
      line_ = 1;
      return error("empty replay file");
    }
    if (r.expect.hit_count && r.expect.hits &&
        static_cast<std::size_t>(*r.expect.hit_count) != r.expect.hits->size()) {
      line_ = hits_line_;
      return error("expect hits " + std::to_string(*r.expect.hit_count) + " but " +
                   std::to_string(r.expect.hits->size()) + " \"expect hit\" lines");
    }
    return std::nullopt;
  }

 private:
  InputError error(std::string message) const {
    return InputError{file_, line_, std::move(message)};
  }

  std::optional<InputError> parseHeader(std::string_view src, std::string_view line) {
    line = trim(line);
    if (line == kHeader) return std::nullopt;
    if (src.find_first_not_of(" \t\r\n") == std::string_view::npos)
      return error("empty replay file");
    if (line.starts_with("cardemo-replay")) {
      return error("unsupported replay version " + inQuotes(line) +
                   " (expected \"cardemo-replay 1\")");
    }
    return error("not a replay file: line 1 must be \"cardemo-replay 1\", found " + inQuotes(line));
  }

  std::optional<InputError> parseLine(std::string_view line, Replay& r) {
    std::string_view rest = line;
    const std::string_view word = firstWord(rest);
    // Input lines first: all but a handful of a replay's lines are COUNT KEYS.
    if (word.front() >= '0' && word.front() <= '9') return parseInput(word, rest, r);
    if (word == "scene") {
      if (scene_line_ != 0) return duplicate("scene", scene_line_);
      if (rest.empty()) return error("scene: missing path");
      scene_line_ = line_;
      r.scene_line = line_;
      r.scene = std::string(rest);
      r.scene_resolved = resolveScene(r.scene, file_);
      return std::nullopt;
    }
    if (word == "hz") {
      if (hz_line_ != 0) return duplicate("hz", hz_line_);
      std::int64_t hz = 0;
      bool too_large = false;
      if (!parseWhole(rest, 10000, hz, too_large) || hz < 1) {
        return error("hz: expected a whole number from 1 to 10000, found " + inQuotes(rest));
      }
      hz_line_ = line_;
      r.hz = static_cast<int>(hz);
      return std::nullopt;
    }
    if (word == "expect") return parseExpect(rest, r.expect);
    if (word.front() == '-' || word.front() == '+') {
      return error("count: expected a whole number >= 1, found " + inQuotes(word));
    }
    return error("unknown directive " + inQuotes(word) +
                 " (expected scene, hz, expect or a COUNT KEYS line)");
  }

  std::optional<InputError> parseInput(std::string_view count_text, std::string_view rest,
                                       Replay& r) {
    std::int64_t count = 0;
    bool too_large = false;
    if (!parseWhole(count_text, kMaxReplayFrames, count, too_large)) {
      if (too_large) {
        return error("count " + inQuotes(count_text) + " exceeds the limit of " +
                     std::to_string(kMaxReplayFrames) + " frames");
      }
      return error("count: expected a whole number >= 1, found " + inQuotes(count_text));
    }
    if (count < 1) return error("count must be >= 1");
    const std::string_view keys_text = firstWord(rest);
    if (keys_text.empty()) return error("expected COUNT KEYS (e.g. \"120 U\"), keys missing");
    if (!rest.empty()) return error("unexpected " + inQuotes(rest) + " after the keys");
    InputRun run;
    run.count = count;
    std::string why;
    if (!parseKeys(keys_text, run.keys, why)) return error(why);
    total_ += count;
    if (total_ > kMaxReplayFrames) {
      return error("replay exceeds the limit of " + std::to_string(kMaxReplayFrames) +
                   " frames in total");
    }
    r.runs.push_back(run);
    return std::nullopt;
  }

  std::optional<InputError> parseExpect(std::string_view rest, ReplayExpectations& e) {
    const std::string_view what = firstWord(rest);
    if (what == "health") {
      if (health_line_ != 0) return duplicate("expect health", health_line_);
      std::int64_t v = 0;
      if (!whole(rest, kMaxExpectedHealth, v))
        return badNumber("expect health", rest, kMaxExpectedHealth);
      health_line_ = line_;
      e.health = static_cast<int>(v);
    } else if (what == "hits") {
      if (hits_line_ != 0) return duplicate("expect hits", hits_line_);
      std::int64_t v = 0;
      if (!whole(rest, kMaxReplayFrames, v))
        return badNumber("expect hits", rest, kMaxReplayFrames);
      hits_line_ = line_;
      e.hit_count = v;
    } else if (what == "hit") {
      const std::string_view frame_text = firstWord(rest);
      ExpectedHit hit;
      if (!whole(frame_text, kMaxReplayFrames, hit.frame)) {
        return badNumber("expect hit: frame", frame_text, kMaxReplayFrames);
      }
      if (rest.empty()) return error("expect hit: missing id (expected \"expect hit FRAME ID\")");
      hit.id = std::string(rest);
      if (!e.hits) e.hits.emplace();
      if (!e.hits->empty() && e.hits->back().frame > hit.frame) {
        return error("expect hit: frame " + std::to_string(hit.frame) + " comes after frame " +
                     std::to_string(e.hits->back().frame) + "; list hits in frame order");
      }
      e.hits->push_back(std::move(hit));
    } else if (what == "hash") {
      if (hash_line_ != 0) return duplicate("expect hash", hash_line_);
      if (!isHash(rest)) {
        return error("expect hash: expected 16 lower-case hex digits, found " + inQuotes(rest));
      }
      hash_line_ = line_;
      e.hash = std::string(rest);
    } else if (what == "frames") {
      if (frames_line_ != 0) return duplicate("expect frames", frames_line_);
      std::int64_t v = 0;
      if (!whole(rest, kMaxReplayFrames, v)) {
        return badNumber("expect frames", rest, kMaxReplayFrames);
      }
      frames_line_ = line_;
      e.frames = v;
    } else if (what == "parked") {
      if (parked_line_ != 0) return duplicate("expect parked", parked_line_);
      std::int64_t v = 0;
      if (rest == "never") {
        e.parked = std::optional<std::int64_t>{};
      } else if (whole(rest, kMaxReplayFrames, v)) {
        e.parked = std::optional<std::int64_t>{v};
      } else {
        return error("expect parked: expected a frame from 0 to " +
                     std::to_string(kMaxReplayFrames) + " or \"never\", found " + inQuotes(rest));
      }
      parked_line_ = line_;
    } else {
      return error("unknown expectation " + inQuotes(what) +
                   " (expected health, hits, hit, frames, hash or parked)");
    }
    return std::nullopt;
  }

  static bool whole(std::string_view s, std::int64_t max, std::int64_t& out) {
    bool too_large = false;
    return parseWhole(s, max, out, too_large);
  }

  InputError badNumber(const std::string& what, std::string_view found, std::int64_t max) const {
    return error(what + ": expected a whole number from 0 to " + std::to_string(max) + ", found " +
                 inQuotes(found));
  }

  InputError duplicate(const std::string& what, int first_line) const {
    return error("duplicate \"" + what + "\" line (first on line " + std::to_string(first_line) +
                 ")");
  }

  const std::string& file_;
  int line_ = 0;
  std::int64_t total_ = 0;
  int scene_line_ = 0, hz_line_ = 0, health_line_ = 0, hits_line_ = 0, hash_line_ = 0,
      frames_line_ = 0, parked_line_ = 0;
};

}  // namespace

std::int64_t Replay::totalFrames() const {
  std::int64_t total = 0;
  for (const InputRun& run : runs) total += run.count;
  return total;
}

Parsed<Replay> parseReplay(std::string_view text, const std::string& filename) {
  try {
    Replay replay;
    ReplayParser parser(filename);
    if (auto e = parser.parse(text, replay)) return *e;
    return replay;
  } catch (const std::exception& e) {
    return InputError{filename, 1, std::string("cannot read replay: ") + e.what()};
  }
}

Parsed<Replay> loadReplay(const std::string& path) {
  Parsed<std::string> text = readInputFile(path, kMaxReplayBytes);
  if (!text.ok()) return text.error();
  return parseReplay(text.value(), path);
}

std::string keysText(const InputFrame& keys) {
  std::string s;
  if (keys.up) s += 'U';
  if (keys.down) s += 'D';
  if (keys.left) s += 'L';
  if (keys.right) s += 'R';
  if (keys.handbrake) s += 'H';
  return s.empty() ? std::string(".") : s;
}

std::string formatExpectations(const ReplayExpectations& e) {
  std::string out;
  if (e.frames) out += "expect frames " + std::to_string(*e.frames) + "\n";
  if (e.health) out += "expect health " + std::to_string(*e.health) + "\n";
  if (e.hit_count) {
    out += "expect hits " + std::to_string(*e.hit_count) + "\n";
  } else if (e.hits && e.hits->empty()) {
    out += "expect hits 0\n";  // an empty list has no `expect hit` line to carry it
  }
  if (e.hits) {
    for (const ExpectedHit& hit : *e.hits) {
      out += "expect hit " + std::to_string(hit.frame) + " " + hit.id + "\n";
    }
  }
  if (e.parked) {
    out +=
        "expect parked " + (*e.parked ? std::to_string(**e.parked) : std::string("never")) + "\n";
  }
  if (e.hash) out += "expect hash " + *e.hash + "\n";
  return out;
}

void appendInputLine(std::string& out, std::int64_t count, const InputFrame& keys) {
  char digits[24];
  const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, count);
  out.append(digits, static_cast<std::size_t>(end - digits));
  out += ' ';
  out += keysText(keys);
  out += '\n';
}

std::string replayHeaderText(const std::string& scene, int hz) {
  std::string out = std::string(kHeader) + "\n";
  if (!scene.empty()) out += "scene " + scene + "\n";
  return out + "hz " + std::to_string(hz) + "\n";
}

std::string formatReplay(const Replay& replay) {
  std::string out = replayHeaderText(replay.scene, replay.hz);
  for (const InputRun& run : replay.runs) appendInputLine(out, run.count, run.keys);
  return out + formatExpectations(replay.expect);
}

}  // namespace cardemo
