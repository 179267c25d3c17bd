#include "ellc/contact/normal_contact.hpp"

namespace ellc {

NormalContact normal_contact(const ContactGeometry& geometry, const ContactMaterial& material, double mean_radius_sum,
                             HertzMode mode, const LawParameters& parameters, double max_overlap,
                             ConstantsScope scope) noexcept {
  NormalContact contact;
  if (scope == ConstantsScope::all) {
    contact.constants =
        make_contact_constants(material, hertz_shape(geometry.relative, mode), mean_radius_sum, parameters);
  } else {
    contact.constants =
        make_yield_constants(material, hertz_shape(geometry.relative, mode, ShapeParts::without_axes), parameters);
    if (law_needs_transition(contact.constants, geometry.overlap, max_overlap))
      set_transition_constants(contact.constants, mean_radius_sum, parameters);
  }
  const LawOnBranch law = evaluate_contact_on_branch(contact.constants, geometry.overlap, max_overlap);
  contact.law = law.law;
  contact.branch = law.branch;
  contact.force_on_j = contact.law.force * geometry.normal;
  contact.application_point = geometry.point;
  return contact;
}

}  // namespace ellc
