#pragma once

#include <cstdint>
#include <random>

namespace dream::agents {

/// Gaussian noise from a seeded generator: each sensor owns one, seeded from
/// the run's seed, the robot id and the sensor's index, so runs repeat
/// exactly whatever the process layout. Never std::rand().
class NoiseSource {
 public:
  explicit NoiseSource(uint64_t seed) : engine_(seed) {}

  /// A sample of N(0, std_dev^2); exactly 0 (no draw) when std_dev is 0, so a
  /// noiseless sensor does not consume the stream.
  double Gaussian(double std_dev) {
    if (std_dev == 0.0) return 0.0;
    return std::normal_distribution<double>(0.0, std_dev)(engine_);
  }

  /// Uniform in [0, 1).
  double Uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(engine_); }

  /// A seed mixing the run seed with up to two small integers (robot id,
  /// component index): SplitMix64, so nearby inputs give unrelated streams.
  static uint64_t MixSeed(uint64_t run_seed, uint64_t a, uint64_t b = 0) {
    uint64_t z = run_seed + 0x9E3779B97F4A7C15ULL * (a + 1) + 0xBF58476D1CE4E5B9ULL * (b + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace dream::agents
