#pragma once
// The Becker–Kamlah normal contact law (paper Sec. 3, docs/model.md §2–4).
//
// One pure function of the contact constants, the overlap δ and the history δ_* (the largest
// overlap the contact has reached). Header-only and noexcept: no allocation, no exceptions,
// inlined into the DEM loop, LAMMPS and the Python batch calls alike.
//
// Regimes on loading (δ ≥ δ_*):  δ ≤ δ_Y Hertz (10);  δ_Y < δ ≤ δ_max eq. (25) with λ of (28);
// δ > δ_max eq. (31). Below δ_*: elastic unloading/reloading along eq. (49).

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "ellc/law/contact_constants.hpp"

namespace ellc {

enum class Regime : std::uint8_t { separated, elastic, elastic_plastic, fully_plastic, unloading };

[[nodiscard]] constexpr const char* regime_name(Regime regime) noexcept {
  switch (regime) {
    case Regime::separated: return "separated";
    case Regime::elastic: return "elastic";
    case Regime::elastic_plastic: return "elastic_plastic";
    case Regime::fully_plastic: return "fully_plastic";
    case Regime::unloading: return "unloading";
  }
  return "unknown";
}

struct LawResult {
  double force = 0.0;        // normal force, ≥ 0
  double max_overlap = 0.0;  // δ_* after this evaluation (the only history)
  Regime regime = Regime::separated;
};

// Derived unloading branch for a history δ_* > δ_Y (docs/model.md §4).
struct UnloadingBranch {
  double loading_force = 0.0;          // F_*,pmax: the loading force at δ_* (eq. 25 or 31)
  double fully_plastic_force = 0.0;    // F_*,pY = π p_Y (c_*² − c_Y²) + F_pY
  double hertz_force = 0.0;            // F_*,H = F_H(δ_*)
  double plastic_radius = 0.0;         // R_e,p = F_*,H R_e / F_*,pY, eq. (44)
  double plastic_overlap = 0.0;        // δ_p = δ_* (1 − R_e/R_e,p), eq. (34)
  double force_ratio = 1.0;            // β = F_*,pmax / F_*,pY, eq. (46)
  double unloading_radius = 0.0;       // R_e,pmax = β² R_e,p, eq. (48)
  double unloading_coefficient = 0.0;  // (4/3) E_e sqrt(R_e,pmax) f2^{-3/2}, eq. (49)
};

namespace law_detail {
inline constexpr double kPi = std::numbers::pi;

[[nodiscard]] inline double pow_three_halves(double x) noexcept { return x * std::sqrt(x); }

// Eq. (24)/(25)/(31): F = π p (c_c² − c_Y²) + F_pY with the pressure p = λ Y.
[[nodiscard]] inline double truncated_hertz_force(const ContactConstants& c, double pressure,
                                                  double contact_radius_sq) noexcept {
  return kPi * pressure * (contact_radius_sq - c.yield_contact_radius * c.yield_contact_radius) + c.yield_force;
}
}  // namespace law_detail

// λ of eq. (28) at equivalent contact radius c_c ∈ [c_Y, c_max].
[[nodiscard]] inline double transition_lambda(const ContactConstants& c, double contact_radius) noexcept {
  // Fraction of the transition still ahead: 1 at c_Y, 0 at c_max. Clamped because c_c at δ_max
  // can round to a hair above ε_max c_Y, and a negative base would give pow() a NaN.
  const double progress_left =
      (c.epsilon_max * c.yield_contact_radius - contact_radius) / ((c.epsilon_max - 1.0) * c.yield_contact_radius);
  return c.lambda_max -
         (c.lambda_max - c.yield_pressure_factor) * std::pow(std::fmax(progress_left, 0.0), c.transition_exponent);
}

// Whether the law at overlap δ with history δ_* reads the transition constants λ_max, ε_max and
// δ_max (make_yield_constants leaves them unset): only beyond first yield, i.e. on loading past
// δ_Y or below a δ_* > δ_Y (the unloading curve is derived from the loading force at δ_*).
[[nodiscard]] inline bool law_needs_transition(const ContactConstants& c, double overlap, double max_overlap) noexcept {
  return overlap > c.yield_overlap || max_overlap > c.yield_overlap;
}

// The loading envelope F(δ) for monotonic loading, and the regime it is in.
struct LoadingPoint {
  double force;
  Regime regime;
};
[[nodiscard]] inline LoadingPoint loading_force(const ContactConstants& c, double overlap) noexcept {
  if (overlap <= c.yield_overlap) return {c.hertz_coefficient * law_detail::pow_three_halves(overlap), Regime::elastic};
  const double contact_radius_sq = c.contact_radius_sq_per_overlap * overlap;  // eq. (9)
  if (overlap <= c.plastic_limit_overlap) {
    const double lambda = transition_lambda(c, std::sqrt(contact_radius_sq));
    return {law_detail::truncated_hertz_force(c, lambda * c.yield_stress, contact_radius_sq), Regime::elastic_plastic};
  }
  return {law_detail::truncated_hertz_force(c, c.lambda_max * c.yield_stress, contact_radius_sq),
          Regime::fully_plastic};
}

// Unloading branch from history δ_* (> δ_Y), given F_*,pmax = loading_force(c, δ_*).force by a
// caller that has just computed it (the law at δ = δ_*).
[[nodiscard]] inline UnloadingBranch unloading_branch_given(const ContactConstants& c, double max_overlap,
                                                            double loading_force_at_max) noexcept {
  UnloadingBranch branch;
  branch.loading_force = loading_force_at_max;
  branch.fully_plastic_force =
      law_detail::truncated_hertz_force(c, c.yield_pressure, c.contact_radius_sq_per_overlap * max_overlap);
  branch.hertz_force = c.hertz_coefficient * law_detail::pow_three_halves(max_overlap);
  const double radius_growth = branch.hertz_force / branch.fully_plastic_force;  // R_e,p / R_e
  branch.plastic_radius = c.equivalent_radius * radius_growth;
  branch.plastic_overlap = max_overlap * (1.0 - 1.0 / radius_growth);
  branch.force_ratio = branch.loading_force / branch.fully_plastic_force;
  branch.unloading_radius = branch.force_ratio * branch.force_ratio * branch.plastic_radius;
  branch.unloading_coefficient = c.hertz_coefficient * std::sqrt(branch.unloading_radius / c.equivalent_radius);
  return branch;
}

// Unloading branch from history δ_* (> δ_Y). Everything is derived from δ_*, nothing cached.
[[nodiscard]] inline UnloadingBranch unloading_branch(const ContactConstants& c, double max_overlap) noexcept {
  return unloading_branch_given(c, max_overlap, loading_force(c, max_overlap).force);
}

// δ_p for any history δ_*: the permanent overlap of eq. (34), 0 when the contact never yielded.
[[nodiscard]] inline double plastic_overlap(const ContactConstants& c, double max_overlap) noexcept {
  return max_overlap > c.yield_overlap ? unloading_branch(c, max_overlap).plastic_overlap : 0.0;
}

// All the law needs below a history δ_* > δ_Y: F = coefficient (δ − δ_p)^{3/2}, eq. (49) with δ_p
// of eq. (34). A function of the constants and δ_* only: a caller whose constants stay fixed while
// δ_* does (a path, a pair with prebuilt constants) derives it once per δ_* and passes it in,
// which saves the derivation's λ(δ_*) (a pow), three square roots and four divisions per call.
struct UnloadingCurve {
  double plastic_overlap = 0.0;  // δ_p
  double coefficient = 0.0;      // C_UL
};

[[nodiscard]] inline UnloadingCurve unloading_curve(const ContactConstants& c, double max_overlap) noexcept {
  const UnloadingBranch branch = unloading_branch(c, max_overlap);
  return {branch.plastic_overlap, branch.unloading_coefficient};
}

// The elastic curve F = coefficient · x^{3/2} the contact is on after a step, x = δ − offset: Hertz
// (eq. 10) if the contact never yielded, else the unloading curve (eq. 49) of δ_*, below δ_* and,
// at its top, while the contact loads. Its contact radius follows eq. (9) with the branch's radius,
// c² = (c_c²/δ) · radius_scale · x, radius_scale = R_e,pmax/R_e once yielded and 1 before.
// Stiffnesses that scale with the contact size (damping, tangential spring) use this radius, so
// they follow the branch.
struct ElasticBranch {
  double coefficient = 0.0;      // C or C_UL
  double elastic_overlap = 0.0;  // x = δ, or δ − δ_p once yielded (≤ 0 when the law is separated)
  double radius_scale = 1.0;     // R/R_e
};

// The law's result with the branch it was evaluated on, so that a caller that needs both (the
// contact model) derives the unloading curve once per step, not twice.
struct LawOnBranch {
  LawResult law;
  ElasticBranch branch;
};

namespace law_detail {
// The unloading curve and the radius of its patch, R_e,pmax/R_e (eq. 48): what the branch needs
// besides the force. Kept curves (16 bytes, per contact) carry no radius: their callers
// (evaluate_contact_on_curve, evaluate_contact_cached) return only the LawResult, and the branch's
// radius_scale from them would be NaN.
struct UnloadingCurveAndRadius : UnloadingCurve {
  double radius_scale = 1.0;
};
[[nodiscard]] inline UnloadingCurveAndRadius curve_and_radius_of(const UnloadingBranch& branch,
                                                                 const ContactConstants& c) noexcept {
  return {{branch.plastic_overlap, branch.unloading_coefficient}, branch.unloading_radius / c.equivalent_radius};
}
[[nodiscard]] inline UnloadingCurveAndRadius unloading_curve_and_radius(const ContactConstants& c,
                                                                        double max_overlap) noexcept {
  return curve_and_radius_of(unloading_branch(c, max_overlap), c);
}
[[nodiscard]] inline double radius_scale_of(const UnloadingCurveAndRadius& curve) noexcept {
  return curve.radius_scale;
}
[[nodiscard]] inline double radius_scale_of(const UnloadingCurve&) noexcept {
  return std::numeric_limits<double>::quiet_NaN();
}

// The law and its branch, with the unloading curve of δ_* from `curve_of()`, called only when
// unloading from δ_* > δ_Y, and the branch of a yielded contact that loads from
// `yielded_loading_branch(δ, F)`, F its loading force there. Every evaluate_contact* below is
// this one function: the same bits either way (a caller that reads only the LawResult passes
// `no_branch` and lets the compiler drop the branch).
template <class CurveOf, class YieldedLoadingBranch>
[[nodiscard]] inline LawOnBranch evaluate_contact_given(const ContactConstants& c, double overlap, double max_overlap,
                                                        CurveOf&& curve_of,
                                                        YieldedLoadingBranch&& yielded_loading_branch) noexcept {
  const ElasticBranch hertz{c.hertz_coefficient, overlap, 1.0};
  if (!(overlap > 0.0)) return {{0.0, max_overlap, Regime::separated}, hertz};
  if (overlap >= max_overlap) {
    const LoadingPoint point = loading_force(c, overlap);
    return {{point.force, overlap, point.regime},
            overlap > c.yield_overlap ? yielded_loading_branch(overlap, point.force) : hertz};
  }
  if (max_overlap <= c.yield_overlap)  // never yielded: Hertz both ways, δ_p = 0
    return {{c.hertz_coefficient * pow_three_halves(overlap), max_overlap, Regime::elastic}, hertz};
  const auto curve = curve_of();  // an UnloadingCurve, with the radius when the caller wants the branch
  const double elastic_overlap = overlap - curve.plastic_overlap;  // δ_UL, eq. (32)
  const ElasticBranch unloading{curve.coefficient, elastic_overlap, radius_scale_of(curve)};
  if (elastic_overlap <= 0.0) return {{0.0, max_overlap, Regime::separated}, unloading};
  return {{curve.coefficient * pow_three_halves(elastic_overlap), max_overlap, Regime::unloading}, unloading};
}
// For callers that read only the LawResult: no branch is derived.
[[nodiscard]] inline ElasticBranch no_branch(double, double) noexcept { return {}; }

// The branch of a yielded contact that loads (δ = δ_*): the unloading curve of eq. (49) at its
// own top, x = δ − δ_p with R_e,pmax. Its contact radius c² = R_e,pmax (δ − δ_p) f1²/f2 =
// β² R_e δ f1²/f2 is the patch the law's force implies, and the radius the contact has the moment
// it turns to unload. The Hertz radius instead (β = 1) made k_n and k_t jump by β at every turn
// at δ_*, and the tangential spring lost that jump's share of its force at each reloading
// (docs/contact_model.md, "The branch").
// `force` is the loading force at `overlap`, which the law has just computed.
[[nodiscard]] inline ElasticBranch top_of_unloading_branch(const ContactConstants& c, double overlap,
                                                           double force) noexcept {
  const UnloadingCurveAndRadius curve = curve_and_radius_of(unloading_branch_given(c, overlap, force), c);
  return {curve.coefficient, overlap - curve.plastic_overlap, curve.radius_scale};
}
}  // namespace law_detail

// The law. `max_overlap` is δ_* before this step (0 for a fresh contact). The caller stores the
// returned max_overlap; deleting history on separation is the caller's policy (docs/model.md §5).
[[nodiscard]] inline LawResult evaluate_contact(const ContactConstants& c, double overlap,
                                                double max_overlap) noexcept {
  return law_detail::evaluate_contact_given(
             c, overlap, max_overlap, [&] { return unloading_curve(c, max_overlap); }, law_detail::no_branch)
      .law;
}

// The law and the elastic branch the contact is on after it (the same bits as evaluate_contact).
[[nodiscard]] inline LawOnBranch evaluate_contact_on_branch(const ContactConstants& c, double overlap,
                                                            double max_overlap) noexcept {
  return law_detail::evaluate_contact_given(
      c, overlap, max_overlap, [&] { return law_detail::unloading_curve_and_radius(c, max_overlap); },
      [&](double top, double force) { return law_detail::top_of_unloading_branch(c, top, force); });
}

// The law with the unloading curve kept by the caller (the same bits as evaluate_contact):
// `curve` must be unloading_curve(c, max_overlap) whenever max_overlap > δ_Y (not read otherwise).
[[nodiscard]] inline LawResult evaluate_contact_on_curve(const ContactConstants& c, double overlap, double max_overlap,
                                                         const UnloadingCurve& curve) noexcept {
  return law_detail::evaluate_contact_given(
             c, overlap, max_overlap, [&] { return curve; }, law_detail::no_branch)
      .law;
}

// The unloading curve of the last δ_* asked for, for one set of constants: derived again only when
// δ_* changes, i.e. once per unloading episode instead of once per step.
class UnloadingCurveCache {
 public:
  [[nodiscard]] const UnloadingCurve& curve(const ContactConstants& c, double max_overlap) noexcept {
    if (!(max_overlap == max_overlap_)) {  // also true on the first call (NaN)
      curve_ = unloading_curve(c, max_overlap);
      max_overlap_ = max_overlap;
    }
    return curve_;
  }

 private:
  double max_overlap_ = std::numeric_limits<double>::quiet_NaN();
  UnloadingCurve curve_;
};

// The law with the curve from `cache` (which must belong to these constants): the same bits as
// evaluate_contact(c, overlap, max_overlap).
[[nodiscard]] inline LawResult evaluate_contact_cached(const ContactConstants& c, double overlap, double max_overlap,
                                                       UnloadingCurveCache& cache) noexcept {
  return law_detail::evaluate_contact_given(
             c, overlap, max_overlap, [&] { return cache.curve(c, max_overlap); }, law_detail::no_branch)
      .law;
}

}  // namespace ellc
