#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace dream::world {

// Which realism model a RealismRandom serves; the numbers seed the streams,
// so they never change (a run's noise would).
enum class RealismStream : uint64_t { kNoise = 1, kDropout = 2, kDropoutBurst = 3, kRobotTraits = 4, kLoopTiming = 5 };

// One seeded stream of the realism models' random numbers. mt19937_64's
// output is fixed by the C++ standard and the transforms below are written
// out (the standard distributions are not), so a seed gives the same numbers
// with any standard library.
class RealismRandom {
 public:
  // `stream` separates the models: each draws from its own sequence, so
  // turning one model on does not change another's draws.
  RealismRandom(uint64_t seed, RealismStream stream) : engine_(Mix(seed, static_cast<uint64_t>(stream))) {}

  // Uniform in [0, 1), 53 random bits.
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Standard normal (Box-Muller; the second value of each pair is kept).
  double Gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - Uniform();  // (0, 1]: log(u1) is finite
    const double u2 = Uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * 3.14159265358979323846 * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  // splitmix64 of the seed and stream, so neighbouring seeds give unrelated
  // engines.
  static uint64_t Mix(uint64_t seed, uint64_t stream) {
    uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace dream::world
