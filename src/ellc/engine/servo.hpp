#pragma once
// The plate servo of both engines: the built-in protocol's servo hold and servo release
// (scenario/protocol_stages.cpp) and fix wall/ellipsoid/bk's `servo` (integrations/lammps).
//
// The speed at which the plate moves towards the particles to bring its pressure p to the target P:
//   v = rate · clamp(g (P − p)/p_ref, −1, 1),   0 when |P − p| ≤ tolerance · P,
// capped so that one step moves the plate by at most half the distance that would close the error
// at the present stiffness of the plate's contacts:
//   |v| dt ≤ ½ |P − p| / k_A,   k_A = Σ k_n / A  (the contacts' normal stiffness per plate area).
// Why the cap: the loop gain of the plain law is g · rate · dt · k_A / p_ref. Unloading plastic
// contacts are stiff, so in a small box (few contacts carry the plate's area) the gain passes 2 and
// the servo overshoots every step: a two-step cycle between ±20 % of P, with a mean below P and the
// plate creeping into the layer. A sampled time series shows one phase of the cycle (a "held"
// 119 MPa against a 100 MPa target). In large boxes the gain is far below ½ and the cap never acts.

#include <algorithm>
#include <cmath>

namespace ellc::engine {

struct PlateServo {
  double target = 0.0;     // P (MPa)
  double reference = 0.0;  // p_ref (MPa): P for a hold; the held pressure for the servo release
  double rate = 0.0;       // µm/µs, the speed at full error
  double gain = 5.0;       // g
  double tolerance = 0.0;  // relative to P: within it the plate stands still
};

// At most this fraction of the pressure error is closed by one step at the contacts' stiffness.
inline constexpr double kServoStepFraction = 0.5;

// Speed towards the particles (> 0 presses), from the plate's pressure and the stiffness per area
// of its contacts at the last force evaluation (0: no contacts, no cap).
[[nodiscard]] inline double servo_speed(const PlateServo& servo, double pressure, double stiffness_per_area,
                                        double dt) noexcept {
  const double difference = servo.target - pressure;
  if (std::abs(difference) <= servo.tolerance * servo.target) return 0.0;
  const double speed = servo.rate * std::clamp(servo.gain * (difference / servo.reference), -1.0, 1.0);
  if (!(stiffness_per_area > 0.0 && dt > 0.0)) return speed;
  const double limit = kServoStepFraction * std::abs(difference) / (stiffness_per_area * dt);
  return std::clamp(speed, -limit, limit);
}

}  // namespace ellc::engine
