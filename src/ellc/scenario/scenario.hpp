#pragma once
// A DEM scenario as read from SCENARIO.toml (`ellc dem`): packing generation, settling and
// calendering, plus the output cadence. Units: µm, µN, µs, ng (docs/engine.md).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ellc/engine/settings.hpp"
#include "ellc/scenario/packing.hpp"

namespace ellc::scenario {

struct SettleSpec {
  double gravity = 0.5;           // µm/µs², along −z
  double drag_rate = 0.5;         // 1/µs, global viscous drag while settling
  double time = 100.0;            // µs: shortest settling
  double max_time = 0.0;          // µs: longest settling (0 → 3 × time)
  double speed_tolerance = 0.05;  // µm/µs: settled when the rms particle speed is below this
};

struct CalenderingSpec {
  double speed = 0.1;  // µm/µs, top plate moving down once it presses the layer
  // The plate first compacts the loose deposit at approach_speed, until its pressure reaches
  // approach_pressure; then it calenders at `speed` (0 → no approach: `speed` throughout).
  double approach_speed = 0.0;             // µm/µs
  double approach_pressure = 5.0;          // MPa
  double lift_speed = 0.1;                 // µm/µs, top plate moving up
  std::optional<double> target_thickness;  // µm (plate gap)
  std::optional<double> target_pressure;   // MPa on the top plate
  double hold_time = 10.0;                 // µs
  double gravity = 0.0;                    // µm/µs² during calendering
  double start_gap = 0.0;                  // µm between the highest particle and the plate when it starts
  // Unloading ends when the plate has lost contact: no particle touches it, or its pressure is
  // below this fraction of the maximum (particles set flying by the release, with no gravity to
  // bring them back, would otherwise keep touching the rising plate now and then).
  double release_fraction = 1e-3;

  // Quasi-static protocol (docs/engine.md, "Loading protocol").
  // Every change of the plate's velocity is a half-cosine ramp over ramp_time (0: a step).
  double ramp_time = 0.0;  // µs
  // The approach ends when the top pressure averaged over approach_window (an exponential average
  // with that time constant; 0: the instantaneous pressure) reaches approach_pressure, or, when
  // given, when the solid fraction between the plates reaches approach_solid_fraction.
  double approach_window = 0.0;  // µs
  std::optional<double> approach_solid_fraction;
  // Hold: the plate stays where it is (`fixed`) or a servo holds target_pressure (`servo`), with
  // the plate speed −speed · clamp(servo_gain (p_target − p)/p_target, −1, 1).
  // Within servo_tolerance of the target the plate stands still, so the layer can come to rest.
  bool servo_hold = false;
  double servo_gain = 5.0;
  double servo_tolerance = 0.01;
  // Readings at equilibrium: the hold (and the relaxation after the release) last at least their
  // time, then until the unbalanced-force ratio is below equilibrium_ratio; a run that has not got
  // there by max_hold_time (max_relax_time) stops with an error naming the criterion.
  double equilibrium_ratio = 1e-3;
  double max_hold_time = 0.0;  // µs, 0 → 5 × hold_time
  double relax_time = 0.0;     // µs after the plate lost contact; 0: the released state is read at once
  // Background damping −γ m v during the hold and the relaxation only (1/µs): it removes the
  // kinetic energy a static reading must not have, without touching the loading (0: none).
  double rest_drag_rate = 0.0;
  double max_relax_time = 0.0;  // µs, 0 → 5 × relax_time (release = servo: 5 × max(relax_time, hold_time))
  // Release: `contact_lost` reads the released state when the plate has lost contact (after
  // relax_time, if given: only with gravity does a free layer come to rest); `servo` unloads the
  // plate by servo to the residual pressure p_r = release_pressure_fraction × the held pressure,
  // holds p_r (within release_tolerance of it), and reads the released state there, at
  // equilibrium, as an oedometer's unloading to a seating load does. The servo's plate speed is
  // lift_speed · clamp(servo_gain (p − p_r)/p_held, −1, 1), bounded by the lift's ramp.
  bool servo_release = false;
  double release_pressure_fraction = 0.02;
  double release_tolerance = 0.05;  // relative to p_r

  // One rule, for the protocol that enforces the limits, the run plan that budgets them and the
  // LAMMPS export that writes them: the longest hold, whether there is a relaxation phase, and its
  // longest duration, before a run stops for want of equilibrium.
  [[nodiscard]] double hold_time_limit() const { return max_hold_time > 0.0 ? max_hold_time : 5.0 * hold_time; }
  [[nodiscard]] bool relaxes() const { return servo_release || relax_time > 0.0; }
  [[nodiscard]] double relax_time_limit() const {
    if (!relaxes()) return 0.0;
    if (max_relax_time > 0.0) return max_relax_time;
    return servo_release ? 5.0 * std::max(relax_time, hold_time) : 5.0 * relax_time;
  }
};

struct OutputSpec {
  std::string directory = "dem_out";
  long csv_every = 100;       // steps
  long vtk_every = 0;         // steps, 0 = only the first and last frame
  long checkpoint_every = 0;  // steps, 0 = only at the end (and on failure)
};

// [analysis] (opt-in): `ellc dem` analyses the microstructure of the loaded and the released state
// (docs/microstructure.md, "In the calendering workflow").
struct AnalysisSpec {
  double voxels_per_semi_axis = 5.0;  // the resolution against the smallest semi-axis, unless
  double spacing = 0.0;               // a voxel size is given (µm)
  double memory_limit_gib = 4.0;      // grids above it are refused with the estimate
  double coarse_factor = 2.0;         // τ again at this × the voxel size (the resolution check); 1: not
  std::string axes = "xyz";           // the tortuosity directions
};

struct Scenario {
  std::string source;  // file name and any --set entries, for messages
  std::string path;    // the file it was read from: relative paths in it start from its folder
  std::string text;    // the file's text (its hash goes into checkpoints)
  engine::ContactSettings contact;
  PackingSpec packing;
  std::vector<std::uint64_t> seeds;  // [packing] seeds: one run per seed (ensemble.hpp); empty: one run
  engine::Box box;
  double mass_scaling = 1.0;         // density multiplier (quasi-static speed-up), docs/engine.md
  double material_density = 4.7e-3;  // ng/µm³ before scaling
  std::optional<double> dt;          // µs; default safety × Rayleigh estimate
  double time_step_safety = 0.2;
  double skin = 0.0;        // µm, 0 → automatic
  double max_speed = 50.0;  // µm/µs: runaway threshold
  SettleSpec settle;
  CalenderingSpec calendering;
  OutputSpec output;
  std::optional<AnalysisSpec> analysis;  // [analysis]; empty: no microstructure analysis
  std::vector<std::string> warnings;
};

// Reads and validates; throws InputError naming the field (unknown keys included). `overrides`
// ("calendering.speed=0.025", ...: `ellc dem --set`, io/toml_overrides.hpp) edit the file's
// entries before validation; they then appear in `source` and in `text`.
[[nodiscard]] Scenario read_scenario(const std::string& path, const std::vector<std::string>& overrides = {});
[[nodiscard]] Scenario parse_scenario(std::string_view toml_text, const std::string& source,
                                      const std::vector<std::string>& overrides = {});

// The time-step estimate of a packing of the scenario: safety × the Rayleigh time of its smallest
// semi-axis, the shortest over the species (each with its density and material).
[[nodiscard]] double packing_time_step(const engine::ParticleSet& particles, const Scenario& scenario);

// The largest bounding radius and the smallest semi-axis the packing spec can produce.
[[nodiscard]] double largest_bounding_radius(const PackingSpec& spec) noexcept;

}  // namespace ellc::scenario
