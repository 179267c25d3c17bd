#include "ellc/microstructure/force_network.hpp"

#include <algorithm>
#include <cmath>

namespace ellc::microstructure {

ForceDistribution normal_force_distribution(const std::vector<ContactRecord>& contacts, double bin_width) {
  ForceDistribution distribution;
  double sum = 0.0;
  double largest = 0.0;
  for (const ContactRecord& contact : contacts)
    if (contact.normal_force > 0.0) {
      ++distribution.contacts;
      sum += contact.normal_force;
      largest = std::max(largest, contact.normal_force);
    }
  if (distribution.contacts == 0 || !(bin_width > 0.0)) return distribution;
  distribution.mean_force = sum / static_cast<double>(distribution.contacts);
  const auto bins = static_cast<std::size_t>(std::floor(largest / distribution.mean_force / bin_width)) + 1;
  distribution.counts.assign(bins, 0);
  for (const ContactRecord& contact : contacts)
    if (contact.normal_force > 0.0) {
      const auto bin =
          std::min(bins - 1, static_cast<std::size_t>(contact.normal_force / distribution.mean_force / bin_width));
      ++distribution.counts[bin];
    }
  for (std::size_t k = 0; k < bins; ++k) {
    distribution.bin_low.push_back(static_cast<double>(k) * bin_width);
    distribution.bin_high.push_back(static_cast<double>(k + 1) * bin_width);
    distribution.density.push_back(static_cast<double>(distribution.counts[k]) /
                                   (static_cast<double>(distribution.contacts) * bin_width));
  }
  return distribution;
}

}  // namespace ellc::microstructure
