// `ellc geometry POSES.toml [--hertz hale|exact]`
// Contact data of two posed ellipsoids (or an ellipsoid and a wall), for checking a
// configuration by hand: contact point, common normal, overlap, curvatures and directions on both
// sides, α, and the constants and force of the law at that overlap.
//
// The poses file ([material], [body_I], [body_J] or [wall], [model], max_overlap) is read by
// read_poses() in ellc/cases/poses_file.hpp; this command only runs it and prints. Bad input exits
// with code 2.

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "ellc/cases/poses_file.hpp"
#include "ellc/contact/normal_contact.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/wall_contact.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::cli {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct GeometryOptions {
  std::string poses_path;
  std::string hertz;
};

void print_vector(const char* label, const Eigen::Vector3d& v) {
  // + 0.0 prints −0 as 0.
  std::printf("  %-22s (%.10g, %.10g, %.10g)\n", label, v.x() + 0.0, v.y() + 0.0, v.z() + 0.0);
}

void print_curvature(const std::string& side, const SurfaceCurvature& c) {
  std::printf("  %-22s kappa_1 = %.10g, kappa_2 = %.10g 1/µm%s\n", ("curvature " + side).c_str(), c.kappa_1, c.kappa_2,
              c.umbilic() ? "  (umbilic)" : "");
  print_vector("  direction_1", c.direction_1);
  print_vector("  direction_2", c.direction_2);
}

void print_law(const NormalContact& contact, HertzMode mode) {
  const ContactConstants& c = contact.constants;
  std::printf("  law (Hertz %s):\n", mode == HertzMode::exact ? "exact" : "hale");
  std::printf("    R_e = %.10g µm, e = %.10g, f1 = %.10g, f2 = %.10g\n", c.equivalent_radius,
              std::sqrt(c.eccentricity_sq), c.f1, c.f2);
  std::printf("    delta_Y = %.10g µm, F_pY = %.10g µN, delta_max = %.10g µm\n", c.yield_overlap, c.yield_force,
              c.plastic_limit_overlap);
  std::printf("    force = %.10g µN (%s), delta_* after = %.10g µm\n", contact.law.force,
              regime_name(contact.law.regime), contact.law.max_overlap);
  print_vector("  force on J", contact.force_on_j);
  print_vector("  application point", contact.application_point);
}

// The input fields a result of this poses file depends on, for messages.
TwoBodyFields poses_fields(const PosesCase& poses, const std::string& source) {
  const BodySpec& spec_i = poses.body_i.spec;
  if (poses.body_j) {
    TwoBodyFields fields = two_body_fields(source, spec_i, "body_I", poses.body_j->spec, "body_J");
    fields.shape += ", body_I.position = " + format_vector(poses.body_i.pose.position) +
                    ", body_J.position = " + format_vector(poses.body_j->pose.position);
    return fields;
  }
  BodySpec wall_side = spec_i;  // the wall has the body's shape for naming purposes only
  if (poses.wall->material) wall_side.material = *poses.wall->material;
  TwoBodyFields fields = two_body_fields(source, spec_i, "body_I", wall_side, "wall");
  fields.shape = "body_I.semi_axes = " + format_vector(spec_i.semi_axes) +
                 ", body_I.position = " + format_vector(poses.body_i.pose.position) +
                 ", wall.point = " + format_vector(poses.wall->plane.point);
  return fields;
}

bool finite_geometry(const ContactGeometry& g) {
  return std::isfinite(g.overlap) && g.normal.allFinite() && g.point.allFinite() && g.surface_point_i.allFinite() &&
         g.surface_point_j.allFinite() && std::isfinite(g.curvature_i.kappa_1) &&
         std::isfinite(g.curvature_i.kappa_2) && std::isfinite(g.curvature_j.kappa_1) &&
         std::isfinite(g.curvature_j.kappa_2) && std::isfinite(g.alpha);
}

void run_geometry(const GeometryOptions& options) {
  PosesCase poses = read_poses(options.poses_path);
  if (!options.hertz.empty()) poses.model.hertz = options.hertz == "exact" ? HertzMode::exact : HertzMode::hale;
  for (const auto& warning : poses.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());
  const TwoBodyFields fields = poses_fields(poses, options.poses_path);

  const PosesContact found = find_contact(poses);
  const Ellipsoid& body_i = found.body_i;
  const NarrowPhaseResult& result = found.result;
  const ContactMaterial& material = found.material;
  const double mean_radius_sum = found.mean_radius_sum;
  // Wholly behind the wall: no contact of the law's kind (and δ without bound).
  if (!poses.body_j && result.status == NarrowPhaseStatus::contact &&
      result.geometry.overlap > 2.0 * body_i.bounding_radius())
    throw InputError(options.poses_path, "body_I.position = " + format_vector(poses.body_i.pose.position) +
                                             " with wall.point = " + format_vector(poses.wall->plane.point) +
                                             " puts the body wholly behind the wall (overlap " +
                                             format_number(result.geometry.overlap) +
                                             " µm): expected at most twice its largest semi-axis, " +
                                             format_number(2.0 * body_i.bounding_radius()) + " µm");

  const ContactGeometry& g = result.geometry;
  if (result.status != NarrowPhaseStatus::failed && !finite_geometry(g))
    throw InputError(options.poses_path, "the inputs " + fields.shape +
                                             " overflow the number format in the contact geometry: expected "
                                             "positions and semi-axes of comparable magnitude");
  std::printf("ellc geometry: %s (%s)\n", options.poses_path.c_str(),
              poses.body_j ? "ellipsoid pair" : "ellipsoid and wall");
  std::printf("  status                 %s\n", status_name(result.status));
  if (result.status == NarrowPhaseStatus::failed)
    throw std::runtime_error("the narrow phase did not converge for this configuration (status failed) of " +
                             fields.shape);
  std::printf("  overlap                %.10g µm%s\n", g.overlap,
              result.status == NarrowPhaseStatus::separated ? "  (<= 0: minus the gap along the normal)" : "");
  print_vector("normal (I to J)", g.normal);
  print_vector("contact point", g.point);
  print_vector("surface point I", g.surface_point_i);
  print_vector(poses.body_j ? "surface point J" : "surface point wall", g.surface_point_j);
  std::printf("  newton iterations      %d (contact-function iterations %d)\n", result.iterations,
              result.contact_function_iterations);
  if (result.status != NarrowPhaseStatus::contact) return;
  const NormalContact contact =
      normal_contact(g, material, mean_radius_sum, poses.model.hertz, poses.model.law, poses.max_overlap);
  if (const std::string error = traced_constants_error(contact.constants, fields); !error.empty())
    throw InputError(options.poses_path, "the contact constants of this configuration: " + error);
  if (!std::isfinite(contact.law.force) || !std::isfinite(contact.law.max_overlap) || !contact.force_on_j.allFinite() ||
      !contact.application_point.allFinite())
    throw InputError(options.poses_path,
                     "the inputs " + fields.material + " with " + fields.shape +
                         ", max_overlap = " + format_number(poses.max_overlap) +
                         " overflow the number format (force = " + format_number(contact.law.force) +
                         " µN): expected a material and bodies whose force is finite");
  print_curvature("I", g.curvature_i);
  print_curvature(poses.body_j ? "J" : "wall", g.curvature_j);
  std::printf("  alpha                  %.10g deg\n", g.alpha / kDegree);
  std::printf("  r_hat I+J              %.10g µm%s\n", mean_radius_sum,
              poses.body_j ? "" : "  (wall: 2 r_hat, mirror image)");
  print_law(contact, poses.model.hertz);
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<GeometryOptions>();
  CLI::App* command =
      root.add_subcommand("geometry", "Contact point, normal, overlap, curvatures and force of two posed bodies");
  command
      ->add_option("poses", options->poses_path,
                   "Poses file (TOML): [material], [body_I], [body_J] or [wall], optional [model], max_overlap")
      ->required();
  command->add_option("--hertz", options->hertz, "Hertz solution: hale or exact (overrides [model].hertz)")
      ->check(CLI::IsMember({"hale", "exact"}));
  command->callback([options] { run_geometry(*options); });
});

}  // namespace
}  // namespace ellc::cli
