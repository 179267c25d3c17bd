#pragma once
// Property test of the narrow phase over the documented shape range (issue 19, item 8;
// docs/geometry.md §6): random pairs of ellipsoids with aspect ratios up to 1:100 (flat discs,
// slender needles, general triaxial bodies and the ordinary 1:[0.3..3]:[0.3..3]), mean radii
// 0.1–10, random poses, each built around a known common normal with a chosen overlap depth.
// Every result is checked, never trusted:
//   * no NaN or inf anywhere in the result;
//   * `contact` is a genuine common normal (both surface normals anti-parallel along n at the
//     reported points, the joining line along n, δ consistent, curvatures > 0); `separated`
//     carries a genuine separating axis. A contact at another common normal than the constructed
//     one is counted (`other_minimum`), not an error: when δ exceeds the local radii of curvature
//     (the rim of a thin body: c²/a) g has several minima;
//   * swap symmetry: solving (J, I) gives the same status, the same δ and the opposite normal.
// The pairs are counted by shape class × largest aspect ratio × overlap depth (in units of the
// smallest semi-axis of the pair). Used by the ctest `NarrowPhaseProperty.*` (10⁴ pairs) and by
// the documented command `narrow_phase_property --pairs 1000000` (not a CI step).

#include <array>
#include <cstdint>
#include <string>

namespace ellc::test {

enum class PairShape : std::uint8_t { ordinary, flat, slender, mixed };
inline constexpr std::array<const char*, 4> kPairShapeNames{"ordinary", "flat", "slender", "mixed"};

// Largest aspect ratio (largest / smallest semi-axis) of the two bodies.
inline constexpr std::array<double, 4> kAspectBinUpper{3.0, 10.0, 30.0, 100.0 * (1 + 1e-12)};
inline constexpr std::array<const char*, 4> kAspectBinNames{"1-3", "3-10", "10-30", "30-100"};

// Constructed overlap δ / smallest semi-axis of the pair.
enum class DepthBin : std::uint8_t { separated, grazing, shallow, moderate, deep, very_deep };
inline constexpr std::array<const char*, 6> kDepthBinNames{
    "separated (-20..0 %)", "grazing (|d| <= 1e-7)", "0..1 %", "1..10 %", "10..30 %", "30..100 %"};

struct PropertyCell {
  long pairs = 0;
  long contact = 0;
  long separated = 0;
  long failed = 0;
  long non_finite = 0;
  long unverified = 0;     // a contact or separated result that does not check out
  long swap_mismatch = 0;  // (J, I) disagrees with (I, J) beyond the tolerance
  long other_minimum = 0;  // a verified contact at another common normal than the constructed one
  long newton_steps = 0;
};

struct PropertyReport {
  // [shape][aspect bin][depth bin]
  std::array<std::array<std::array<PropertyCell, 6>, 4>, 4> cells{};
  double max_swap_overlap_difference = 0.0;  // |δ(I,J) − δ(J,I)| / (sum of largest semi-axes)
  double max_swap_normal_difference = 0.0;   // |n(I,J) + n(J,I)|
  long pairs = 0;
  double seconds = 0.0;

  [[nodiscard]] PropertyCell total() const;
  // Sum over shapes and aspect bins of one depth bin.
  [[nodiscard]] PropertyCell depth_total(DepthBin depth) const;
  // Failed, non-finite, unverified or swap-mismatched pairs with 0 < δ ≤ 10 % of the smallest
  // semi-axis, or grazing, or separated: the pairs that must all be solved (issue 19, item 6).
  [[nodiscard]] long required_failures() const;
  // A plain-text report: totals, the failure table (shape × aspect × depth), swap symmetry.
  [[nodiscard]] std::string text() const;
};

[[nodiscard]] PropertyReport run_narrow_phase_property(long pairs, std::uint64_t seed);

}  // namespace ellc::test
