#include "ellc/cases/poses_file.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"

namespace ellc {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Eigen::Vector3d vector3(const std::vector<double>& values) { return {values[0], values[1], values[2]}; }

// A point in space (a body's position, the wall's point): each coordinate within ±kMaxLength, so
// that differences and squared distances of points stay finite (docs/geometry.md §10).
Eigen::Vector3d point3(TableReader& table, const char* key, const std::vector<double>& values) {
  for (std::size_t axis = 0; axis < 3; ++axis)
    if (!(std::abs(values[axis]) <= kMaxLength))
      table.fail(std::string(key) + "[" + std::to_string(axis) + "]", values[axis],
                 "a coordinate within ±" + format_number(kMaxLength) + " (µm)");
  return vector3(values);
}

Eigen::Vector3d unit_vector(TableReader& table, const char* key, const std::vector<double>& values) {
  const Eigen::Vector3d vector = vector3(values);
  const double length = vector.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    table.fail(key,
               "[" + format_number(values[0]) + ", " + format_number(values[1]) + ", " + format_number(values[2]) + "]",
               "a non-zero vector");
  return vector / length;
}

// Reads the pose keys first (so read_body's finish() knows them), then the body itself.
PosedBodySpec read_posed_body(TableReader& table, const std::optional<Material>& shared_material,
                              std::vector<std::string>& warnings) {
  PosedBodySpec body;
  if (const auto position = table.optional_numbers("position", 3))
    body.pose.position = point3(table, "position", *position);
  const auto orientation = table.optional_numbers("orientation", 4);
  const auto axis = table.optional_numbers("axis", 3);
  const auto angle = table.optional_number("angle_deg");
  if (orientation && (axis || angle))
    throw InputError(table.source(),
                     "[" + table.path() + "] gives both orientation and axis/angle_deg: expected one of the two");
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  if (orientation) {
    const Eigen::Quaterniond q((*orientation)[0], (*orientation)[1], (*orientation)[2], (*orientation)[3]);
    if (!(q.norm() > 1e-12))
      table.fail("orientation", "a zero quaternion", "a unit quaternion [w, x, y, z] (it is normalised)");
    rotation = q.normalized();
  } else if (axis || angle) {
    if (!axis) table.fail("axis", "missing", "axis = [x, y, z], required with angle_deg");
    if (!angle) table.fail("angle_deg", "missing", "a number (degrees), required with axis");
    rotation = Eigen::AngleAxisd(*angle * kDegree, unit_vector(table, "axis", *axis));
  }
  body.spec = read_body(table, shared_material, warnings);
  body.pose.orientation = rotation * Eigen::Quaterniond(Eigen::AngleAxisd(body.spec.twist, Eigen::Vector3d::UnitX()));
  return body;
}

WallSpec read_wall(TableReader& table) {
  WallSpec wall;
  const auto point = table.optional_numbers("point", 3);
  if (!point) table.fail("point", "missing", "point = [x, y, z] on the wall");
  const auto normal = table.optional_numbers("normal", 3);
  if (!normal) table.fail("normal", "missing", "normal = [x, y, z], pointing to the particles' side");
  wall.plane = {point3(table, "point", *point), unit_vector(table, "normal", *normal)};
  if (auto material = table.optional_table("material")) wall.material = read_material(*material);
  table.finish();
  return wall;
}

PosesCase read_poses_table(const toml::table& root_table, const std::string& source) {
  TableReader root(root_table, "", source);
  PosesCase poses;
  std::optional<Material> shared_material;
  if (auto material = root.optional_table("material")) shared_material = read_material(*material);
  {
    auto body = root.table("body_I");
    poses.body_i = read_posed_body(body, shared_material, poses.warnings);
  }
  auto body_j = root.optional_table("body_J");
  auto wall = root.optional_table("wall");
  if (body_j && wall) throw InputError(source, "the file gives both [body_J] and [wall]: expected one of the two");
  if (!body_j && !wall) root.fail("body_J", "missing", "a table [body_J] or a table [wall]");
  if (body_j) poses.body_j = read_posed_body(*body_j, shared_material, poses.warnings);
  if (wall) poses.wall = read_wall(*wall);
  if (auto model = root.optional_table("model")) poses.model = read_model(*model);
  poses.max_overlap = root.number_or("max_overlap", 0.0);
  if (poses.max_overlap < 0.0) root.fail("max_overlap", poses.max_overlap, "a finite number >= 0 (µm)");
  // δ_* of a real history: the bodies cannot have overlapped by more than their reach (pair:
  // the centres coincide at a_max^I + a_max^J; wall: the body is wholly behind it at 2 a_max^I).
  const double reach = poses.body_j ? poses.body_i.spec.semi_axes.maxCoeff() + poses.body_j->spec.semi_axes.maxCoeff()
                                    : 2.0 * poses.body_i.spec.semi_axes.maxCoeff();
  if (poses.max_overlap > reach)
    root.fail("max_overlap", poses.max_overlap,
              "at most " + format_number(reach) + " µm (" +
                  (poses.body_j ? std::string("the largest semi-axes of body_I and body_J together")
                                : std::string("twice the largest semi-axis of body_I")) +
                  ": no overlap can have been deeper)");
  root.finish();
  return poses;
}

}  // namespace

PosesCase read_poses(const std::string& path) { return read_poses_table(parse_toml_file(path), path); }

PosesCase parse_poses(std::string_view toml_text, const std::string& source) {
  return read_poses_table(parse_toml_text(toml_text, source), source);
}

PosesContact find_contact(const PosesCase& poses) {
  PosesContact found{Ellipsoid(poses.body_i.spec.semi_axes, poses.body_i.pose), {}, {}, 0.0};
  if (poses.body_j) {
    const Ellipsoid body_j(poses.body_j->spec.semi_axes, poses.body_j->pose);
    found.result = ellipsoid_contact(found.body_i, body_j);
    found.material = mix(poses.body_i.spec.material, poses.body_j->spec.material);
    found.mean_radius_sum = found.body_i.mean_radius() + body_j.mean_radius();
  } else if (poses.wall) {  // the reader guarantees one of the two
    found.result = wall_contact(found.body_i, poses.wall->plane);
    found.material = mix(poses.body_i.spec.material, poses.wall->material.value_or(poses.body_i.spec.material));
    found.mean_radius_sum = wall_mean_radius_sum(found.body_i);
  }
  return found;
}

}  // namespace ellc
