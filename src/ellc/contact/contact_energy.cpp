#include "ellc/contact/contact_energy.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/law/contact_law.hpp"

namespace ellc {

double recoverable_energy(const ContactConstants& constants, double overlap, double max_overlap) noexcept {
  if (!(overlap > 0.0)) return 0.0;
  // ∫₀^x C s^{3/2} ds = (2/5) C x^{5/2} for the branch F = C x^{3/2}.
  const auto energy = [](double coefficient, double x) {
    return x > 0.0 ? 0.4 * coefficient * x * x * std::sqrt(x) : 0.0;
  };
  if (max_overlap <= constants.yield_overlap) return energy(constants.hertz_coefficient, overlap);
  const UnloadingBranch branch = unloading_branch(constants, std::max(max_overlap, overlap));
  return energy(branch.unloading_coefficient, overlap - branch.plastic_overlap);
}

namespace {
// Simpson's rule for the loading force over [a, b] (exact for the linear fully plastic branch).
double loading_work(const ContactConstants& c, double a, double b) noexcept {
  if (!(b > a)) return 0.0;
  constexpr int intervals = 32;
  const double h = (b - a) / intervals;
  double sum = loading_force(c, a).force + loading_force(c, b).force;
  for (int k = 1; k < intervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * loading_force(c, a + k * h).force;
  return sum * h / 3.0;
}
}  // namespace

double plastic_work(const ContactConstants& c, double max_overlap) noexcept {
  if (!(max_overlap > c.yield_overlap)) return 0.0;
  const double yield = c.yield_overlap;
  const double hertz = 0.4 * c.hertz_coefficient * yield * yield * std::sqrt(yield);
  const double transition_end = std::min(max_overlap, c.plastic_limit_overlap);
  const double loading = hertz + loading_work(c, yield, transition_end) + loading_work(c, transition_end, max_overlap);
  return loading - recoverable_energy(c, max_overlap, max_overlap);
}

}  // namespace ellc
