// Gravity settling (the [settle] phase: gravity with a global viscous drag until the rms speed is
// below speed_tolerance, docs/engine.md): the loose deposit of the quick example falls onto the
// bottom wall and comes to rest there as a dense, load-bearing packing whose weight the wall carries.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "scenario_support.hpp"

namespace ellc::scenario {
namespace {

using engine::Box;
using engine::ContactCounts;
using engine::kBottomWall;
using engine::kTopWall;
using engine::PairSlot;
using engine::ParticleSet;
using engine::Simulation;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

// The quick example's 100 NMC ellipsoids (density × 10⁴), inserted looser than there (25 % solid
// instead of 38 %, a deposit ~60 µm high) so that they have somewhere to fall. g = 0.02 µm/µs²
// with the scaled density puts ~15 MPa under the layer (ρ_s g H φ = 47 × 0.02 × 31 × 0.5):
// elastic-ish contacts, overlaps ~1 % of r̂. The drag γ = 0.1/µs caps the fall at g/γ = 0.2 µm/µs
// (impacts at 0.2 m/s). The minimum time (20 µs) is far shorter than the fall (~100 µs), so the
// phase ends on the speed criterion, not on the clock; max_time is twice the ~280 µs it takes.
constexpr double kGravity = 0.02;      // µm/µs²
constexpr double kDragRate = 0.1;      // 1/µs
constexpr double kMinTime = 20.0;      // µs
constexpr double kMaxTime = 600.0;     // µs
constexpr double kSpeedTolerance = 2e-3;  // µm/µs: 1 % of the terminal speed g/γ

std::string settling_scenario_text() {
  std::string text = quick_scenario_text();
  text = replace_line(text, "insertion_fraction", "insertion_fraction = 0.25");
  char settle[256];
  std::snprintf(settle, sizeof settle, "time = %g\nmax_time = %g\ngravity = %g\ndrag_rate = %g\nspeed_tolerance = %g",
                kMinTime, kMaxTime, kGravity, kDragRate, kSpeedTolerance);
  return replace_line(text, "time = 0.0", settle);  // the [settle] table's only line
}

// Half the z extent of a posed ellipsoid, from the geometry layer's tight bounds. (The bounding
// radius, the largest semi-axis, would be wrong by up to a factor 2 for a flat-lying ellipsoid,
// and hide a particle sunk into the floor.)
double half_height(const ParticleSet& p, std::size_t slot) {
  const Ellipsoid posed(p.semi_axes[slot], Pose{p.position[slot], p.orientation[slot]});
  const AxisAlignedBox bounds = posed.axis_aligned_bounds();
  return 0.5 * (bounds.upper.z() - bounds.lower.z());
}

struct Layer {
  double centre_of_mass_z = 0.0;  // µm
  double deepest = 0.0;           // min over particles of (lowest surface point − floor) / r̂
  double top = 0.0;               // µm above the floor, highest surface point
  double solid_fraction = 0.0;    // V_solid / (lx ly top)
};

Layer layer_of(const Simulation& sim) {
  const ParticleSet& p = sim.particles();
  const double floor = sim.walls()[kBottomWall].position;
  Layer layer;
  layer.deepest = std::numeric_limits<double>::infinity();
  double mass = 0.0;
  for (std::size_t slot = 0; slot < p.size(); ++slot) {
    const double z = p.position[slot].z() - floor;
    const double h = half_height(p, slot);
    layer.centre_of_mass_z += p.mass[slot] * z;
    mass += p.mass[slot];
    layer.deepest = std::min(layer.deepest, (z - h) / p.mean_radius[slot]);
    layer.top = std::max(layer.top, z + h);
  }
  layer.centre_of_mass_z /= mass;
  const Box& box = sim.settings().box;
  layer.solid_fraction = p.total_volume() / (box.lx * box.ly * layer.top);
  return layer;
}

TEST(EngineSettling, DepositComesToRestOnTheFloorWhichCarriesItsWeight) {
  ScenarioRunner runner(quick_scenario(settling_scenario_text()), in_memory(512));
  const Simulation& sim = runner.simulation();
  ASSERT_EQ(runner.state().phase, Phase::settle);
  const Layer inserted = layer_of(sim);
  double total_mass = 0.0;  // scaled masses: what gravity pulls on
  for (const double mass : sim.particles().mass) total_mass += mass;
  const double weight = total_mass * kGravity;  // µN

  // Step by step: the runner switches to `load` (gravity and drag off, plate placed) inside a step.
  const auto step_limit = static_cast<std::uint64_t>(1.2 * kMaxTime / sim.settings().dt) + 100;
  while (runner.state().phase == Phase::settle && sim.step_count() < step_limit) runner.advance(1);
  ASSERT_EQ(runner.state().phase, Phase::load) << "the settle phase never ended";

  // 1. It ended because the packing came to rest, not on the clock: the runner's rms speed
  //    (sqrt(2 E_kin / M), rotation included) is below the tolerance, before max_time.
  const double settle_time = runner.state().load_start_time;
  const double rms_speed = std::sqrt(2.0 * sim.kinetic_energy() / total_mass);
  EXPECT_LT(rms_speed, kSpeedTolerance);
  EXPECT_GE(settle_time, kMinTime);
  EXPECT_LT(settle_time, kMaxTime) << "settling timed out";

  // 2. It fell (inserted centre of mass at ~30 µm, a settled layer ~13 µm; 5 µm is more than one
  //    particle radius) and nothing sank into the floor: the lowest surface point of any particle
  //    at most 5 % of its r̂ below the wall. A Hertz estimate of the heaviest floor contact
  //    (weight / 21 floor contacts) gives ~1 %, measured 1.2 %.
  const Layer settled = layer_of(sim);
  EXPECT_LT(settled.centre_of_mass_z, inserted.centre_of_mass_z - 5.0);
  EXPECT_GT(settled.deepest, -0.05);

  // 3. Dense but not squashed. Solid fraction up to the highest surface point: inserted at 25 %,
  //    a settled frictional packing of these ellipsoids 50–60 % in the bulk, less over the rough
  //    top (measured 48 %); 40 % is well above the insertion, 70 % more than such a frictional
  //    deposit reaches even in the bulk (jammed frictionless ellipsoids: at most ~74 %).
  //    Largest particle–particle overlap below 5 % of the smaller r̂ (measured 1 %).
  EXPECT_GT(settled.solid_fraction, 0.40);
  EXPECT_LT(settled.solid_fraction, 0.70);
  const ParticleSet& p = sim.particles();
  double max_overlap = 0.0;  // relative to the smaller r̂ of the pair
  for (const PairSlot& pair : sim.pairs())
    if (pair.history.active())
      max_overlap =
          std::max(max_overlap, pair.cache.last_overlap / std::min(p.mean_radius[pair.i], p.mean_radius[pair.j]));
  EXPECT_LT(max_overlap, 0.05);

  // 4. The particles rest on each other and on the floor. A frictional packing at rest needs about
  //    d + 1 = 4 contacts per particle (fewer on the floor, none for the odd rattler; measured 5.2),
  //    a deposit still falling or floating has ~0: coordination above 3. The 42 µm × 42 µm floor
  //    under a layer of r̂ = 4 µm ellipsoids carries a full bottom layer (measured 21 contacts): at
  //    least 10. The top plate, 2 r̂ above the inserted deposit, is not touched.
  const ContactCounts counts = sim.contact_counts();
  const double coordination = 2.0 * static_cast<double>(counts.particle_contacts) / static_cast<double>(p.size());
  EXPECT_GT(coordination, 3.0);
  EXPECT_GE(sim.wall_contact_count(kBottomWall), 10U);
  EXPECT_EQ(sim.wall_contact_count(kTopWall), 0U);

  // 5. Static equilibrium: the floor carries the weight. Vertically, F_floor = W − Σ m a_z − γ Σ m v_z;
  //    at an rms speed below 2e-3 µm/µs the drag term is at most γ v / g = 1 % of W and the
  //    remaining jiggle adds a few 0.1 % (measured F/W = 1.001). 5 % leaves room; a deposit not
  //    resting on the floor gives 0 (gravity off), one stopped mid-fall at 60 µs 0.32. (At 150 µs,
  //    rms speed 0.055, it is already 0.98: that the layer is fully at rest is assertion 1's job.)
  const double floor_force = -sim.walls()[kBottomWall].force.z();  // particles push it down (−z)
  EXPECT_NEAR(floor_force / weight, 1.0, 0.05);

  RecordProperty("settle_time_us", std::to_string(settle_time));
  RecordProperty("steps", std::to_string(sim.step_count()));
  RecordProperty("rms_speed", std::to_string(rms_speed));
  RecordProperty("com_z_inserted", std::to_string(inserted.centre_of_mass_z));
  RecordProperty("com_z_settled", std::to_string(settled.centre_of_mass_z));
  RecordProperty("deepest_below_floor_over_r", std::to_string(settled.deepest));
  RecordProperty("solid_fraction_inserted", std::to_string(inserted.solid_fraction));
  RecordProperty("solid_fraction_settled", std::to_string(settled.solid_fraction));
  // The bulk, without the rough top: a uniform layer of height H has its centre of mass at H / 2.
  RecordProperty("solid_fraction_bulk",
                 std::to_string(p.total_volume() / (sim.settings().box.lx * sim.settings().box.ly * 2.0 *
                                                    settled.centre_of_mass_z)));
  RecordProperty("max_overlap_over_r", std::to_string(max_overlap));
  RecordProperty("coordination", std::to_string(coordination));
  RecordProperty("floor_contacts", std::to_string(sim.wall_contact_count(kBottomWall)));
  RecordProperty("floor_force_over_weight", std::to_string(floor_force / weight));
}

}  // namespace
}  // namespace ellc::scenario
