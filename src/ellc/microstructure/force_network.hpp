#pragma once
// The contact-force network of a packing: the distribution of the normal forces of its
// particle–particle contacts, normalised by their mean (the form in which DEM studies compare
// force networks: P(f/⟨f⟩), with its exponential tail above the mean).

#include <vector>

#include "ellc/microstructure/packing.hpp"

namespace ellc::microstructure {

struct ForceDistribution {
  double mean_force = 0.0;      // ⟨f⟩ over the contacts with f > 0, µN
  std::size_t contacts = 0;     // contacts with f > 0
  std::vector<double> bin_low;  // f/⟨f⟩
  std::vector<double> bin_high;
  std::vector<double> density;  // PDF of f/⟨f⟩: Σ density × width = 1
  std::vector<long> counts;
};

// Histogram of f/⟨f⟩ over the contacts with a positive normal force, bins of `bin_width` from 0
// to the largest value.
[[nodiscard]] ForceDistribution normal_force_distribution(const std::vector<ContactRecord>& contacts,
                                                          double bin_width = 0.1);

}  // namespace ellc::microstructure
