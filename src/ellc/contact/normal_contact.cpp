#include "ellc/contact/normal_contact.hpp"

namespace ellc {

NormalContact normal_contact(const ContactGeometry& geometry, const ContactMaterial& material, double mean_radius_sum,
                             HertzMode mode, const LawParameters& parameters, double max_overlap) noexcept {
  NormalContact contact;
  contact.constants =
      make_contact_constants(material, hertz_shape(geometry.relative, mode), mean_radius_sum, parameters);
  const LawOnBranch law = evaluate_contact_on_branch(contact.constants, geometry.overlap, max_overlap);
  contact.law = law.law;
  contact.branch = law.branch;
  contact.force_on_j = contact.law.force * geometry.normal;
  contact.application_point = geometry.point;
  return contact;
}

}  // namespace ellc
