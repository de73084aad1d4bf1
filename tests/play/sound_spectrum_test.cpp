// The committed sounds (assets/sounds, made by scripts/make_sounds.py) carry their energy where
// laptop speakers play it, measured from their power spectra; the engine at every speed the game
// mixes it at.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "../support/wav_pcm.hpp"
#include "play/sound_mix.hpp"

namespace cardemo {
namespace {

/// Power of each DFT bin, |X_k|^2, k = 0 .. N-1.
using PowerSpectrum = std::vector<double>;

// Small laptop speakers roll off steeply below about 150 Hz; the band's top keeps a sound from
// hiding its weight in a thin, harsh treble instead.
constexpr double kBandLowHz = 150.0;
constexpr double kBandHighHz = 2000.0;
// With at most 20 % of the energy outside the band, a speaker that plays nothing outside it plays
// the sound at most 10 log10(0.8) = -0.97 dB quieter: under the 1 dB a listener notices.
constexpr double kMinBandShare = 0.8;

const std::string kSoundFolder = std::string(CARDEMO_SOURCE_DIR) + "/assets/sounds/";

testing::PcmSound loadSound(const std::string& name) {
  testing::WavRead read = testing::readWav(kSoundFolder + name);
  EXPECT_EQ(read.error, "");
  EXPECT_FALSE(read.sound.samples.empty()) << name;
  return read.sound;
}

PowerSpectrum powerOf(const std::vector<double>& samples) {
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> bins;
  fft.fwd(bins, samples);
  PowerSpectrum power(bins.size());
  for (std::size_t k = 0; k < bins.size(); ++k) power[k] = std::norm(bins[k]);
  return power;
}

// Share of the power in [kBandLowHz, kBandHighHz]: bin k of N stands for min(k, N - k) * rate / N
// Hz (the upper half mirrors the lower for a real signal), so both halves count alike.
double bandShare(const PowerSpectrum& power, int rate) {
  const std::size_t n = power.size();
  double in_band = 0.0;
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double hz = static_cast<double>(std::min(k, n - k)) * rate / static_cast<double>(n);
    total += power[k];
    if (hz >= kBandLowHz && hz <= kBandHighHz) in_band += power[k];
  }
  return total > 0.0 ? in_band / total : 0.0;
}

TEST(WavPcm, ReadsMono16BitSamplesAndRejectsOtherFiles) {
  // A 44-byte header as Python's wave module writes it, then samples 0, 16384, -32768.
  std::vector<unsigned char> wav = {'R', 'I', 'F', 'F', 42, 0, 0, 0, 'W',  'A', 'V', 'E', 'f',
                                    'm', 't', ' ', 16,  0,  0, 0, 1, 0,    1,   0,   34,  86,
                                    0,   0,   68,  172, 0,  0, 2, 0, 16,   0,   'd', 'a', 't',
                                    'a', 6,   0,   0,   0,  0, 0, 0, 0x40, 0,   0x80};
  const testing::WavRead read = testing::parseWav(wav);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.sound.rate, 22050);
  EXPECT_EQ(read.sound.samples, (std::vector<double>{0.0, 0.5, -1.0}));

  std::vector<unsigned char> truncated(wav.begin(), wav.end() - 1);
  EXPECT_EQ(testing::parseWav(truncated).error, "chunk 'data' runs past the end of the file");
  std::vector<unsigned char> stereo = wav;
  stereo[22] = 2;
  EXPECT_EQ(testing::parseWav(stereo).error, "not mono 16-bit PCM");
  std::vector<unsigned char> no_data(wav.begin(), wav.begin() + 36);
  EXPECT_EQ(testing::parseWav(no_data).error, "no 'data' chunk");
  EXPECT_EQ(testing::parseWav({'R', 'I', 'F'}).error, "not a RIFF/WAVE file");
}

TEST(SoundSpectrum, ShareMeasuresTheBand) {
  // Tones on whole bins: all inside, all outside, and one of each at equal power.
  const int rate = 22050;
  const auto tone = [&](double hz, std::size_t n) {
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = std::sin(2.0 * std::numbers::pi * hz * i / rate);
    return out;
  };
  EXPECT_NEAR(bandShare(powerOf(tone(440.0, 11025)), rate), 1.0, 1e-9);
  EXPECT_NEAR(bandShare(powerOf(tone(100.0, 11025)), rate), 0.0, 1e-9);
  std::vector<double> both = tone(60.0, 11025);
  const std::vector<double> high = tone(3000.0, 11025);
  for (std::size_t i = 0; i < both.size(); ++i) both[i] += high[i];
  EXPECT_NEAR(bandShare(powerOf(both), rate), 0.0, 1e-9);
  const std::vector<double> mid = tone(1000.0, 11025);
  for (std::size_t i = 0; i < both.size(); ++i) both[i] = high[i] + mid[i];
  EXPECT_NEAR(bandShare(powerOf(both), rate), 0.5, 1e-9);
}

TEST(SoundSpectrum, ScreechImpactAndChimeSitInTheBand) {
  for (const std::string name : {"screech.wav", "impact.wav", "chime.wav"}) {
    const testing::PcmSound sound = loadSound(name);
    const double share = bandShare(powerOf(sound.samples), sound.rate);
    RecordProperty(name, std::to_string(share));
    EXPECT_GE(share, kMinBandShare) << name;
  }
}

// SDL_mixer plays every engine loop at its recorded rate (no pitch change at run time): the speed
// only moves their gains (engineGains), so the engine heard at speed v is the sum of the loops
// weighted by engineGains(v). They start within one mixer buffer of each other, at no fixed
// offset, so the power spectrum heard is the gain^2-weighted sum of theirs (its mean over the
// offsets; the loops share few bins, and offsets tried by hand moved the share by under 0.1 %).
TEST(SoundSpectrum, EngineSitsInTheBandAtEverySpeed) {
  std::vector<PowerSpectrum> loops;
  int rate = 0;
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    const testing::PcmSound loop = loadSound("engine-" + std::to_string(i + 1) + ".wav");
    rate = loop.rate;
    loops.push_back(powerOf(loop.samples));
    ASSERT_EQ(loops.back().size(), loops.front().size()) << "engine loops differ in length";
  }
  const double top = SoundSettings{}.top_speed;
  double lowest = 1.0;
  double lowest_at = 0.0;
  for (double speed = 0.0; speed <= 1.25 * top; speed += top / 80.0) {
    const std::array<double, kEngineLoops> gains = engineGains(speed);
    PowerSpectrum heard(loops.front().size(), 0.0);
    for (std::size_t i = 0; i < kEngineLoops; ++i) {
      for (std::size_t k = 0; k < heard.size(); ++k) heard[k] += gains[i] * gains[i] * loops[i][k];
    }
    const double share = bandShare(heard, rate);
    // The pitch extremes: the lowest loop alone at a standstill, the highest at top speed.
    if (speed == 0.0) RecordProperty("engine_idle", std::to_string(share));
    if (speed == top) RecordProperty("engine_top", std::to_string(share));
    if (share < lowest) {
      lowest = share;
      lowest_at = speed;
    }
  }
  RecordProperty("engine_lowest", std::to_string(lowest) + " at " + std::to_string(lowest_at));
  EXPECT_GE(lowest, kMinBandShare) << "at " << lowest_at << " m/s";
}

TEST(SoundSpectrum, EachEngineLoopSitsInTheBand) {
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    const std::string name = "engine-" + std::to_string(i + 1) + ".wav";
    const testing::PcmSound loop = loadSound(name);
    const double share = bandShare(powerOf(loop.samples), loop.rate);
    RecordProperty(name, std::to_string(share));
    EXPECT_GE(share, kMinBandShare) << name;
  }
}

// Share of the power on whole multiples of `hz` (each on a bin of its own: the loops hold whole
// cycles of every partial).
double harmonicShare(const PowerSpectrum& power, int rate, double hz) {
  const std::size_t n = power.size();
  double on_harmonics = 0.0;
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double bin_hz = static_cast<double>(std::min(k, n - k)) * rate / static_cast<double>(n);
    total += power[k];
    const double harmonic = std::round(bin_hz / hz);
    if (harmonic >= 1.0 && std::abs(bin_hz - harmonic * hz) < 1e-6) on_harmonics += power[k];
  }
  return total > 0.0 ? on_harmonics / total : 0.0;
}

TEST(SoundSpectrum, EngineLoopsAreHarmonicsOfTheirFiringRates) {
  // The firing frequencies of assets/sounds/README.md, below the band: the rate is heard from its
  // harmonics above it. At least 70 % on them; the rest is the weaker every-other firing (half
  // orders) and the seeded jitter that make the engine rough rather than a pure buzz.
  const std::array<double, kEngineLoops> firing_hz = {36.0, 60.0, 92.0, 136.0};
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    const std::string name = "engine-" + std::to_string(i + 1) + ".wav";
    const testing::PcmSound loop = loadSound(name);
    const double share = harmonicShare(powerOf(loop.samples), loop.rate, firing_hz[i]);
    RecordProperty(name, std::to_string(share));
    EXPECT_GE(share, 0.7) << name;
  }
}

TEST(SoundSpectrum, LoopsJoinNoSteeperThanTheyMove) {
  // A loop that does not end where it starts clicks at the seam; a clean one's last-to-first step
  // is one more step of the same waveform, no steeper than its steepest step inside.
  std::vector<std::string> names = {"screech.wav"};
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    names.push_back("engine-" + std::to_string(i + 1) + ".wav");
  }
  for (const std::string& name : names) {
    const std::vector<double> x = loadSound(name).samples;
    ASSERT_GE(x.size(), 2U) << name;
    double steepest = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      steepest = std::max(steepest, std::abs(x[i + 1] - x[i]));
    }
    EXPECT_LE(std::abs(x.front() - x.back()), steepest) << name;
  }
}

}  // namespace
}  // namespace cardemo
