#include "ellc/geometry/normal_contact.hpp"

namespace ellc {

NormalContact normal_contact(const ContactGeometry& geometry, const ContactMaterial& material, double mean_radius_sum,
                             HertzMode mode, const LawParameters& parameters, double max_overlap) noexcept {
  NormalContact contact;
  contact.constants = make_contact_constants(material, geometry.curvature_i.principal(), geometry.curvature_j.principal(),
                                             geometry.alpha, mean_radius_sum, mode, parameters);
  contact.law = evaluate_contact(contact.constants, geometry.overlap, max_overlap);
  contact.force_on_j = contact.law.force * geometry.normal;
  contact.application_point = geometry.point;
  return contact;
}

}  // namespace ellc
