#pragma once
/// Reads mono 16-bit PCM WAV files (the format of assets/sounds) for tests that measure them.

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace cardemo::testing {

/// A mono sound: its sample rate and its samples scaled to [-1, 1).
struct PcmSound {
  int rate = 0;                 ///< Samples per second.
  std::vector<double> samples;  ///< Each 16-bit sample divided by 32768.
};

/// The sound a WAV file holds, or why it could not be read (`error` is empty on success).
struct WavRead {
  PcmSound sound;     ///< Valid only when `error` is empty.
  std::string error;  ///< What is wrong with the file, or empty.
};

/// Parses the bytes of a RIFF/WAVE file with a mono 16-bit PCM `fmt ` chunk and a `data` chunk;
/// any other chunk is skipped.
inline WavRead parseWav(const std::vector<unsigned char>& bytes) {
  const auto u16 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(bytes[at] | (bytes[at + 1] << 8));
  };
  const auto u32 = [&](std::size_t at) { return u16(at) | (u16(at + 2) << 16); };
  const auto tag = [&](std::size_t at) {
    return std::string(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                       bytes.begin() + static_cast<std::ptrdiff_t>(at + 4));
  };
  WavRead out;
  if (bytes.size() < 12 || tag(0) != "RIFF" || tag(8) != "WAVE") {
    out.error = "not a RIFF/WAVE file";
    return out;
  }
  bool have_format = false;
  for (std::size_t at = 12; at + 8 <= bytes.size();) {
    const std::string id = tag(at);
    const std::size_t size = u32(at + 4);
    const std::size_t body = at + 8;
    if (size > bytes.size() - body) {
      out.error = "chunk '" + id + "' runs past the end of the file";
      return out;
    }
    if (id == "fmt ") {
      if (size < 16 || u16(body) != 1 || u16(body + 2) != 1 || u16(body + 14) != 16) {
        out.error = "not mono 16-bit PCM";
        return out;
      }
      out.sound.rate = static_cast<int>(u32(body + 4));
      have_format = true;
    } else if (id == "data") {
      if (!have_format) {
        out.error = "'data' before 'fmt '";
        return out;
      }
      for (std::size_t i = body; i + 1 < body + size; i += 2) {
        out.sound.samples.push_back(static_cast<std::int16_t>(u16(i)) / 32768.0);
      }
      return out;
    }
    at = body + size + (size & 1U);  // chunks are padded to an even length
  }
  out.error = "no 'data' chunk";
  return out;
}

/// Reads and parses the WAV file at `path`; the error names the file.
inline WavRead readWav(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {{}, path + ": cannot open"};
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  WavRead read = parseWav(bytes);
  if (!read.error.empty()) read.error = path + ": " + read.error;
  return read;
}

}  // namespace cardemo::testing
