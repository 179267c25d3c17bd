// Contact geometry: the paper's tip-to-tip configuration (Sec. 5) and posed ellipsoids with the
// common-normal narrow phase, walls, and the normal force of a geometry (docs/geometry.md).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "ellc/contact/normal_contact.hpp"
#include "ellc/geometry/contact_geometry.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/tip_contact.hpp"
#include "ellc/geometry/wall_contact.hpp"

namespace ellc::python {

namespace {

// Quaternions cross the boundary as (w, x, y, z).
Eigen::Quaterniond quaternion_from(const Eigen::Vector4d& wxyz) {
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
}
Eigen::Vector4d quaternion_to(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

}  // namespace

void bind_geometry(py::module_& module) {
  py::class_<TipBody>(module, "TipBody",
                      "An ellipsoid with semi-axis a along the line of centres x, touching at its x tip, twisted "
                      "about x by `twist` radians.")
      .def(py::init([](const Eigen::Vector3d& semi_axes, double twist) {
             return TipBody{semi_axes, twist};
           }),
           py::arg("semi_axes"), py::arg("twist") = 0.0)
      .def_readwrite("semi_axes", &TipBody::semi_axes)
      .def_readwrite("twist", &TipBody::twist);

  py::class_<TipContact>(module, "TipContact", "Principal curvatures of both bodies at the tips and the angle alpha.")
      .def_readonly("body_i", &TipContact::body_i)
      .def_readonly("body_j", &TipContact::body_j)
      .def_readonly("alpha", &TipContact::alpha);

  module.def("mean_radius", &mean_radius, py::arg("semi_axes"), "r^k = (a b c)^(1/3), eq. (50).");
  module.def("tip_curvatures", &tip_curvatures, py::arg("semi_axes"), "Curvatures at the x tip: (a/b^2, a/c^2).");
  module.def("tip_contact", &tip_contact, py::arg("body_i"), py::arg("body_j"),
             "Curvatures and alpha of two bodies touching at their x tips.");

  py::class_<Pose>(module, "Pose", "Position and orientation (unit quaternion (w, x, y, z), body -> world).")
      .def(py::init([](const Eigen::Vector3d& position, const Eigen::Vector4d& orientation) {
             return Pose{position, quaternion_from(orientation)};
           }),
           py::arg("position") = Eigen::Vector3d::Zero(), py::arg("orientation") = Eigen::Vector4d(1, 0, 0, 0))
      .def_readwrite("position", &Pose::position)
      .def_property(
          "orientation", [](const Pose& pose) { return quaternion_to(pose.orientation); },
          [](Pose& pose, const Eigen::Vector4d& wxyz) { pose.orientation = quaternion_from(wxyz); },
          "Unit quaternion as (w, x, y, z).");

  py::class_<SurfaceCurvature>(module, "SurfaceCurvature",
                               "Principal curvatures kappa_1 >= kappa_2 (1/µm) and their world directions.")
      .def_readonly("kappa_1", &SurfaceCurvature::kappa_1)
      .def_readonly("kappa_2", &SurfaceCurvature::kappa_2)
      .def_readonly("direction_1", &SurfaceCurvature::direction_1)
      .def_readonly("direction_2", &SurfaceCurvature::direction_2)
      .def("principal", &SurfaceCurvature::principal, "As PrincipalCurvatures (for make_contact_constants).");

  py::class_<Ellipsoid>(module, "Ellipsoid",
                        "A posed ellipsoid: semi-axes (a, b, c) along its body x, y, z axes, and a Pose.")
      .def(py::init([](const Eigen::Vector3d& semi_axes, const Pose& pose) {
             Ellipsoid body(semi_axes, pose);
             if (!body.valid())
               throw py::value_error("Ellipsoid: expected finite semi_axes > 0 and a non-zero finite quaternion");
             return body;
           }),
           py::arg("semi_axes"), py::arg("pose") = Pose{})
      .def_property_readonly("semi_axes", &Ellipsoid::semi_axes)
      .def_property_readonly("pose", &Ellipsoid::pose)
      .def_property_readonly("center", &Ellipsoid::center)
      .def_property_readonly("rotation", &Ellipsoid::rotation, "Body -> world rotation matrix (columns: body axes).")
      .def_property_readonly("mean_radius", &Ellipsoid::mean_radius, "r^ = (a b c)^(1/3), eq. (50).")
      .def_property_readonly("volume", &Ellipsoid::volume)
      .def("support_point", &Ellipsoid::support_point, py::arg("direction"),
           "The surface point farthest along `direction`.")
      .def("normal_at", &Ellipsoid::normal_at, py::arg("point"), "Outward unit normal at (the projection of) a point.")
      .def("curvature_at", &Ellipsoid::curvature_at, py::arg("point"),
           "Principal curvatures and directions at (the radial projection of) a surface point.")
      .def("implicit_value", &Ellipsoid::implicit_value, py::arg("point"),
           "< 0 inside, 0 on the surface, > 0 outside.");

  py::class_<ContactGeometry>(module, "ContactGeometry", "Common-normal contact geometry of two bodies.")
      .def_readonly("point", &ContactGeometry::point)
      .def_readonly("normal", &ContactGeometry::normal, "Unit normal from I towards J.")
      .def_readonly("overlap", &ContactGeometry::overlap, "delta = (p_I - p_J).n; > 0 in contact.")
      .def_readonly("surface_point_i", &ContactGeometry::surface_point_i)
      .def_readonly("surface_point_j", &ContactGeometry::surface_point_j)
      .def_readonly("relative", &ContactGeometry::relative, "A and B of eq. (5): what the law uses.")
      .def_readonly("curvature_i", &ContactGeometry::curvature_i)
      .def_readonly("curvature_j", &ContactGeometry::curvature_j)
      .def_readonly("alpha", &ContactGeometry::alpha, "Angle between the kappa_1 directions, in [0, pi/2].");

  py::enum_<NarrowPhaseStatus>(module, "NarrowPhaseStatus")
      .value("CONTACT", NarrowPhaseStatus::contact)
      .value("SEPARATED", NarrowPhaseStatus::separated)
      .value("FAILED", NarrowPhaseStatus::failed);
  py::class_<NarrowPhaseWarmStart>(module, "NarrowPhaseWarmStart", "Pass back to the next ellipsoid_contact call.")
      .def(py::init<>())
      .def_readonly("normal", &NarrowPhaseWarmStart::normal)
      .def_readonly("valid", &NarrowPhaseWarmStart::valid);
  py::class_<NarrowPhaseResult>(module, "NarrowPhaseResult")
      .def_readonly("status", &NarrowPhaseResult::status)
      .def_readonly("geometry", &NarrowPhaseResult::geometry)
      .def_readonly("iterations", &NarrowPhaseResult::iterations)
      .def_readonly("warm_start", &NarrowPhaseResult::warm_start)
      .def_readonly("cold_start", &NarrowPhaseResult::cold_start);
  module.def(
      "ellipsoid_contact",
      [](const Ellipsoid& body_i, const Ellipsoid& body_j, const std::optional<NarrowPhaseWarmStart>& warm_start) {
        return ellipsoid_contact(body_i, body_j, warm_start ? &*warm_start : nullptr);
      },
      py::arg("body_i"), py::arg("body_j"), py::arg("warm_start") = py::none(),
      "Common-normal narrow phase of two ellipsoids: status, geometry (point, normal, overlap, curvatures, alpha).");

  py::class_<Plane>(module, "Plane", "A wall: a point and the unit normal into the particles' half-space.")
      .def(py::init([](const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
             return Plane{point, normal};
           }),
           py::arg("point"), py::arg("normal"))
      .def_readwrite("point", &Plane::point)
      .def_readwrite("normal", &Plane::normal);
  module.def("wall_contact", &wall_contact, py::arg("body"), py::arg("wall"),
             "Ellipsoid (I) against a plane (J, zero curvature).");
  module.def("wall_mean_radius_sum", &wall_mean_radius_sum, py::arg("body"),
             "r^{I,J} for a wall contact: 2 r^ of the particle (its mirror image).");

  py::class_<NormalContact>(module, "NormalContact", "Normal force of a contact geometry.")
      .def_readonly("force_on_j", &NormalContact::force_on_j, "F n: pushes J away from I (µN).")
      .def_readonly("application_point", &NormalContact::application_point)
      .def_readonly("law", &NormalContact::law, "LawResult: force magnitude, new delta_*, regime.")
      .def_readonly("constants", &NormalContact::constants);
  module.def(
      "normal_contact",
      [](const ContactGeometry& geometry, const ContactMaterial& material, double mean_radius_sum,
         const std::string& hertz, const LawParameters& law, double max_overlap) {
        return normal_contact(geometry, material, mean_radius_sum, hertz_mode(hertz), law, max_overlap);
      },
      py::arg("geometry"), py::arg("material"), py::arg("mean_radius_sum"), py::arg("hertz") = "hale",
      py::arg("law") = LawParameters{}, py::arg("max_overlap") = 0.0,
      "Curvatures and alpha of a geometry through the contact law: force vector, LawResult, constants. "
      "max_overlap is the contact's delta_* before this step.");
}

}  // namespace ellc::python
