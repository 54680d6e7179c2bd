#pragma once
// The simulator's random numbers: SplitMix64 (Steele, Lea, Flood 2014) and normals by
// Marsaglia and Tsang's ziggurat (2000; 256 layers: one 64-bit draw, a multiply and a compare
// for 99 % of the normals, where the polar method needed two draws, a log and a square root
// per pair), written out rather than taken from <random> so that a seed gives the same stream
// with every standard library (std::normal_distribution's algorithm is unspecified) and so
// that a generator is one 64-bit word: seeding one per profile costs nothing.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace cosmos {

// A well-mixed 64-bit value from `seed` and a stream number: independent generators for
// independent purposes (pose, per-profile noise, camera frames) from one user seed.
constexpr std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed = 0) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Standard normal (ziggurat). Draw bits: layer (8), sign (1), position in the layer (53).
  double normal() {
    const Ziggurat& z = ziggurat();
    for (;;) {
      const std::uint64_t bits = next();
      const auto layer = static_cast<std::size_t>(bits & 0xFFu);
      const std::uint64_t sign_bit = (bits & 0x100u) << 55;
      const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.x[layer];
      if (x < z.x[layer + 1]) return with_sign(x, sign_bit);  // inside the layer's core rectangle
      if (layer == 0) return with_sign(tail(z.r), sign_bit);
      // The wedge between the layer's rectangle and the density.
      const double y = z.f[layer + 1] + uniform() * (z.f[layer] - z.f[layer + 1]);
      if (y < std::exp(-0.5 * x * x)) return with_sign(x, sign_bit);
    }
  }

 private:
  // Layer i spans [0, x[i]) between heights f[i] and f[i + 1] (f = exp(-x^2/2)); every layer,
  // the base one with the tail beyond r included, has the same area v. x[0] = v / f(r) makes
  // the base layer a rectangle of that area; x[1] = r; x[256] = 0.
  struct Ziggurat {
    static constexpr double r = 3.6541528853610088;
    static constexpr double v = 4.92867323399e-3;
    std::array<double, 257> x{};
    std::array<double, 257> f{};
    Ziggurat() {
      x[0] = v / std::exp(-0.5 * r * r);
      x[1] = r;
      for (std::size_t i = 1; i < 256; ++i)
        x[i + 1] = std::sqrt(-2.0 * std::log(std::exp(-0.5 * x[i] * x[i]) + v / x[i]));
      x[256] = 0.0;
      for (std::size_t i = 0; i <= 256; ++i) f[i] = std::exp(-0.5 * x[i] * x[i]);
    }
  };
  static const Ziggurat& ziggurat() {
    static const Ziggurat tables;
    return tables;
  }
  static double with_sign(double magnitude, std::uint64_t sign_bit) {
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(magnitude) | sign_bit);
  }
  // Beyond r (Marsaglia 1964): r + a with a ~ Exp(r) accepted with probability exp(-a^2/2).
  double tail(double r) {
    for (;;) {
      const double a = -std::log(1.0 - uniform()) / r;
      const double b = -std::log(1.0 - uniform());
      if (2.0 * b > a * a) return r + a;
    }
  }

  std::uint64_t state_;
};

}  // namespace cosmos
