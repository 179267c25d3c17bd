#pragma once
// A small seeded generator with its own distributions, so that a packing is the same on every
// platform and standard library (std:: distributions are implementation-defined).
// SplitMix64 (Steele, Lea & Flood 2014) for the stream; uniforms from the top 53 bits;
// normals by Box–Muller; uniform rotations by Shoemake's method (Graphics Gems III, 1992).

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace ellc::scenario {

class Random {
 public:
  explicit Random(std::uint64_t seed) noexcept : state_(seed) {}

  std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // [0, 1)
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) noexcept { return low + (high - low) * uniform(); }
  double normal() noexcept {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  Eigen::Quaterniond rotation() noexcept {
    const double u1 = uniform(), u2 = uniform(), u3 = uniform();
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double two_pi = 2.0 * std::numbers::pi;
    return {b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2), b * std::sin(two_pi * u3)};
  }

 private:
  std::uint64_t state_;
};

}  // namespace ellc::scenario
