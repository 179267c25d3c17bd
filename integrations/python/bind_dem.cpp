// The engine side of ellc.dem (python/ellc/dem.py): a scenario run of `ellc dem` stepped from
// Python. It is the CLI's own ScenarioRunner (scenario/scenario_runner.hpp), so a Python run and
// `ellc dem` take the same steps and write the same files, bit for bit. Particle fields are
// read-only numpy views onto the engine's structure of arrays (no copies), kept alive by the run;
// contacts are gathered into new arrays (the engine stores them per pair slot, not as arrays).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bind_dem.hpp"
#include "bindings.hpp"
#include "ellc/scenario/run_outputs.hpp"
#include "ellc/scenario/scenario.hpp"
#include "ellc/scenario/scenario_runner.hpp"

namespace ellc::python {

namespace {

using scenario::Phase;
using scenario::ScenarioRunner;

constexpr Phase kPhases[] = {Phase::settle, Phase::load, Phase::hold, Phase::unload, Phase::relax, Phase::done};

Phase phase_from_name(const std::string& name) {
  std::string names;
  for (Phase phase : kPhases) {
    if (name == scenario::phase_name(phase)) return phase;
    names += names.empty() ? "" : ", ";
    names += std::string("'") + scenario::phase_name(phase) + "'";
  }
  throw py::value_error("phase = '" + name + "': expected one of " + names);
}

// A run and what it knows about itself: a run whose step threw cannot be stepped again (its
// state is that of the failed step, and a second try would fail the same way or worse).
class DemRun {
 public:
  DemRun(const std::string& text, const std::string& source, scenario::RunOptions options) {
    scenario::Scenario loaded = scenario::parse_scenario(text, source);
    py::gil_scoped_release release;  // packing generation or a checkpoint read can take a while
    runner_ = std::make_unique<ScenarioRunner>(std::move(loaded), std::move(options));
  }

  // Steps at most `max_steps` (stopping early where `stop` says), with the GIL released.
  std::uint64_t advance(std::uint64_t max_steps, const std::function<bool(const ScenarioRunner&)>& stop) {
    check_steppable();
    // Under the GIL: no other thread can be between this check and the flag.
    stepping_ = true;
    struct Idle {
      bool& flag;
      ~Idle() { flag = false; }
    } idle{stepping_};
    try {
      py::gil_scoped_release release;
      return runner_->advance(max_steps, stop);
    } catch (const std::exception& error) {
      failure_ = error.what();
      throw;
    }
  }

  // While another Python thread steps this run (the GIL is released then), what walks the
  // engine's lists (contacts, checkpoints, the summary) would read them mid-step.
  void check_idle() const {
    if (stepping_)
      throw std::runtime_error("this run is being stepped in another thread; read it when that call has returned");
  }

  void check_steppable() const {
    check_idle();
    if (!failure_.empty())
      throw std::runtime_error("this run failed at step " + std::to_string(sim().step_count()) + " (" + failure_ +
                               "); it cannot be stepped further: start a new run, or load a checkpoint written "
                               "before the failure");
    if (runner_->done())
      throw std::runtime_error("this run is finished (phase 'done' at step " + std::to_string(sim().step_count()) +
                               "); there is nothing left to step");
  }

  [[nodiscard]] const ScenarioRunner& runner() const { return *runner_; }
  [[nodiscard]] const engine::Simulation& sim() const { return runner_->simulation(); }
  [[nodiscard]] const std::string& failure() const noexcept { return failure_; }

 private:
  std::unique_ptr<ScenarioRunner> runner_;
  std::string failure_;
  bool stepping_ = false;  // read and written under the GIL only
};

const double* coefficients(const Eigen::Vector3d& vector) { return vector.data(); }
const double* coefficients(const Eigen::Quaterniond& quaternion) { return quaternion.coeffs().data(); }  // x, y, z, w

// A read-only (rows × columns) float64 view of a vector of fixed-size Eigen vectors.
template <typename Vector>
py::array field_view(const std::vector<Vector>& field, py::ssize_t columns, const py::object& owner) {
  static_assert(sizeof(Vector) % sizeof(double) == 0);
  const auto rows = static_cast<py::ssize_t>(field.size());
  py::array view(py::dtype::of<double>(), {rows, columns},
                 {static_cast<py::ssize_t>(sizeof(Vector)), static_cast<py::ssize_t>(sizeof(double))},
                 rows > 0 ? coefficients(field.front()) : nullptr, owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

template <typename Scalar>
py::array scalar_view(const std::vector<Scalar>& field, const py::object& owner) {
  const auto rows = static_cast<py::ssize_t>(field.size());
  py::array view(py::dtype::of<Scalar>(), {rows}, {static_cast<py::ssize_t>(sizeof(Scalar))},
                 rows > 0 ? field.data() : nullptr, owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

py::array_t<double> rows_of_three(const std::vector<Eigen::Vector3d>& values) {
  py::array_t<double> array({static_cast<py::ssize_t>(values.size()), py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t row = 0; row < values.size(); ++row)
    for (int axis = 0; axis < 3; ++axis) out(static_cast<py::ssize_t>(row), axis) = values[row][axis];
  return array;
}

template <typename T>
py::array_t<T> column(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

// The contacts of the last force evaluation (Simulation::for_each_contact): pairs, then the
// floor's, then the plate's. Particles by id (persistent), not by slot.
py::dict contacts_of(const engine::Simulation& sim) {
  const engine::ParticleSet& particles = sim.particles();
  std::vector<std::int8_t> wall;
  std::vector<std::int64_t> id_i, id_j;
  std::vector<double> overlap, max_overlap, normal_force, size_ratio;
  std::vector<std::uint8_t> regime;
  std::vector<Eigen::Vector3d> normal, force, tangential_force, centre_i, other;
  sim.for_each_contact([&](const engine::ContactView& contact) {
    wall.push_back(static_cast<std::int8_t>(contact.wall));
    id_i.push_back(particles.id[contact.i]);
    id_j.push_back(contact.wall < 0 ? static_cast<std::int64_t>(particles.id[contact.j]) : -1);
    overlap.push_back(contact.overlap);
    max_overlap.push_back(contact.max_overlap);
    regime.push_back(static_cast<std::uint8_t>(contact.regime));
    normal_force.push_back(contact.normal_force);
    size_ratio.push_back(contact.size_ratio);
    normal.push_back(contact.normal);
    force.push_back(contact.force);
    // The force's part in the contact plane (friction): F − (F·n) n.
    tangential_force.push_back(contact.force - contact.normal_force * contact.normal);
    centre_i.push_back(contact.centre_i);
    other.push_back(contact.other);
  });
  py::dict result;
  result["wall"] = column(wall);
  result["id_i"] = column(id_i);
  result["id_j"] = column(id_j);
  result["overlap"] = column(overlap);
  result["max_overlap"] = column(max_overlap);
  result["regime"] = column(regime);
  result["normal_force"] = column(normal_force);
  result["size_ratio"] = column(size_ratio);
  result["normal"] = rows_of_three(normal);
  result["force"] = rows_of_three(force);
  result["tangential_force"] = rows_of_three(tangential_force);
  result["centre_i"] = rows_of_three(centre_i);
  result["other"] = rows_of_three(other);
  return result;
}

std::uint64_t step_budget(long long steps) {
  if (steps < 0) throw py::value_error("steps = " + std::to_string(steps) + ": expected an integer >= 0");
  return static_cast<std::uint64_t>(steps);
}

}  // namespace

void bind_dem(py::module_& module) {
  py::class_<DemRun>(module, "_DemRun",
                     "A run of an `ellc dem` scenario (the CLI's ScenarioRunner); use ellc.dem.Run, which wraps it.")
      .def(py::init([](const std::string& text, const std::string& source, const std::string& output_directory,
                       const std::string& restart_path, bool force, bool write_files, long long parallel_threshold) {
             scenario::RunOptions options;
             options.output_directory = output_directory;
             options.restart_path = restart_path;
             options.force = force;
             options.write_files = write_files;
             if (parallel_threshold >= 0) options.parallel_threshold = static_cast<std::size_t>(parallel_threshold);
             return std::make_unique<DemRun>(text, source, std::move(options));
           }),
           py::arg("text"), py::arg("source"), py::arg("output_directory") = "", py::arg("restart_path") = "",
           py::arg("force") = false, py::arg("write_files") = true, py::arg("parallel_threshold") = -1)
      .def(
          "advance", [](DemRun& run, long long steps) { return run.advance(step_budget(steps), {}); }, py::arg("steps"),
          "Steps at most `steps` times (fewer if the protocol ends); returns the steps taken.")
      .def(
          "advance_until_phase",
          [](DemRun& run, const std::string& name, long long steps) {
            const Phase phase = phase_from_name(name);
            return run.advance(step_budget(steps),
                               [phase](const ScenarioRunner& runner) { return runner.state().phase == phase; });
          },
          py::arg("phase"), py::arg("max_steps"), "Steps until the protocol enters `phase` (or ends).")
      .def(
          "advance_until_time",
          [](DemRun& run, double time, long long steps) {
            if (!std::isfinite(time)) throw py::value_error("time: expected a finite number of µs");
            return run.advance(step_budget(steps),
                               [time](const ScenarioRunner& runner) { return runner.simulation().time() >= time; });
          },
          py::arg("time"), py::arg("max_steps"), "Steps until the simulated time reaches `time` µs (or the end).")
      .def("check_steppable", &DemRun::check_steppable)
      .def_property_readonly("done", [](const DemRun& run) { return run.runner().done(); })
      .def_property_readonly("failure", &DemRun::failure)
      .def_property_readonly(
          "phase", [](const DemRun& run) { return std::string(scenario::phase_name(run.runner().state().phase)); })
      .def_property_readonly("step", [](const DemRun& run) { return run.sim().step_count(); })
      .def_property_readonly("time", [](const DemRun& run) { return run.sim().time(); })
      .def_property_readonly("dt", [](const DemRun& run) { return run.sim().settings().dt; })
      .def_property_readonly("progress", [](const DemRun& run) { return run.runner().progress(); })
      .def_property_readonly("gap", [](const DemRun& run) { return run.sim().gap(); })
      .def_property_readonly("porosity", [](const DemRun& run) { return run.sim().porosity(); })
      .def_property_readonly("plate_pressure",
                             [](const DemRun& run) { return run.sim().wall_pressure(engine::kTopWall); })
      .def_property_readonly("bottom_pressure",
                             [](const DemRun& run) { return run.sim().wall_pressure(engine::kBottomWall); })
      .def_property_readonly("kinetic_energy", [](const DemRun& run) { return run.sim().kinetic_energy(); })
      .def_property_readonly("plastic_dissipation", [](const DemRun& run) { return run.sim().plastic_dissipation(); })
      .def_property_readonly("unbalanced_force_ratio",
                             [](const DemRun& run) { return run.sim().unbalanced_force_ratio(); })
      .def_property_readonly("wall_positions",
                             [](const DemRun& run) {
                               const auto& walls = run.sim().walls();
                               return std::vector<double>{walls[0].position, walls[1].position};
                             })
      .def_property_readonly("wall_velocities",
                             [](const DemRun& run) {
                               const auto& walls = run.sim().walls();
                               return std::vector<double>{walls[0].velocity, walls[1].velocity};
                             })
      .def_property_readonly("output_directory", [](const DemRun& run) { return run.runner().output_directory(); })
      .def_property_readonly("warnings", [](const DemRun& run) { return run.runner().warnings(); })
      .def_property_readonly("particle_count", [](const DemRun& run) { return run.sim().particles().size(); })
      .def_property_readonly("species_names",
                             [](const DemRun& run) {
                               std::vector<std::string> names;
                               for (const auto& species : scenario::species_of(run.runner().scenario().packing))
                                 names.push_back(species.name);
                               return names;
                             })
      // Views: base object = the run, so the numpy array keeps it alive; the engine never
      // reallocates these vectors while stepping (tests/python/test_dem.py checks the addresses).
      .def(
          "particle_field",
          [](py::object self, const std::string& name) -> py::array {
            const engine::ParticleSet& p = self.cast<const DemRun&>().sim().particles();
            if (name == "id") return scalar_view(p.id, self);
            if (name == "position") return field_view(p.position, 3, self);
            if (name == "orientation") return field_view(p.orientation, 4, self);  // x, y, z, w (Eigen's order)
            if (name == "semi_axes") return field_view(p.semi_axes, 3, self);
            if (name == "velocity") return field_view(p.velocity, 3, self);
            if (name == "angular_velocity") return field_view(p.angular_velocity, 3, self);
            if (name == "force") return field_view(p.force, 3, self);
            if (name == "torque") return field_view(p.torque, 3, self);
            if (name == "mass") return scalar_view(p.mass, self);
            if (name == "mean_radius") return scalar_view(p.mean_radius, self);
            if (name == "inertia") return field_view(p.inertia, 3, self);
            if (name == "species") return scalar_view(p.species, self);
            throw py::value_error("particle field '" + name + "' does not exist");
          },
          py::arg("name"))
      .def("contacts",
           [](const DemRun& run) {
             run.check_idle();
             return contacts_of(run.sim());
           })
      .def(
          "write_checkpoint",
          [](const DemRun& run, const std::string& path) {
            run.check_idle();
            py::gil_scoped_release release;
            run.runner().write_checkpoint(path);
          },
          py::arg("path"))
      .def("write_summary",
           [](const DemRun& run) {
             run.check_idle();
             return run.runner().write_summary();
           })
      .def("summary_text", [](const DemRun& run) {
        run.check_idle();
        std::ostringstream out;
        scenario::write_summary_lines(out, run.runner().scenario().source, run.runner().summary());
        return out.str();
      });

  module.def(
      "_check_scenario",
      [](const std::string& text, const std::string& source) { (void)scenario::parse_scenario(text, source); },
      py::arg("text"), py::arg("source"), "Reads the scenario text as `ellc dem` does; raises ellc.InputError.");
  module.def(
      "_phase_names",
      [] {
        std::vector<std::string> names;
        for (Phase phase : kPhases) names.emplace_back(scenario::phase_name(phase));
        return names;
      },
      "The protocol's phases, in the order a run passes them (relax only when relax_time > 0).");
}

}  // namespace ellc::python
