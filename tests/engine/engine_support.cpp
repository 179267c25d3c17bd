#include "engine_support.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "ellc/scenario/random.hpp"

namespace ellc::engine::testing {

EngineSettings free_settings(NormalModel model) {
  EngineSettings settings;
  settings.contact.material = kNmc;
  settings.contact.model.normal = model;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.0;
  settings.contact.model.friction = 0.0;
  settings.contact.wall_friction = 0.0;
  settings.box = {200.0, 200.0};
  settings.max_speed = 1e6;
  return settings;
}

ParticleSet colliding_packing(std::size_t count, std::uint64_t seed, double insertion_fraction, double floor,
                              std::uint64_t velocity_seed) {
  PackingSpec spec;
  spec.count = count;
  spec.mean_radius = 4.0;
  spec.radius_spread = 0.1;
  spec.seed = seed;
  spec.density = kScaledDensity;
  spec.insertion_fraction = insertion_fraction;
  ParticleSet particles = generate_packing(spec, kCollidingBox, floor, ellipsoid_overlap_test());
  Random random(velocity_seed);
  for (auto& velocity : particles.velocity)
    velocity = Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
  return particles;
}

std::string quick_scenario_text() {
  std::ifstream file(std::string(ELLC_EXAMPLES_DIR) + "/calendering_quick.toml");
  if (!file) throw std::runtime_error("examples/calendering_quick.toml not found");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replace_line(std::string text, const std::string& starts_with, const std::string& line) {
  const auto at = text.find("\n" + starts_with);
  if (at == std::string::npos) throw std::runtime_error("no line starting with " + starts_with);
  const auto end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, line);
}

Scenario quick_scenario(const std::string& text) { return parse_scenario(text, "calendering_quick.toml"); }

RunOptions in_memory(std::size_t parallel_threshold) {
  RunOptions options;
  options.write_files = false;
  options.parallel_threshold = parallel_threshold;
  return options;
}

std::string state_bytes(const Simulation& simulation) {
  std::ostringstream out(std::ios::binary);
  simulation.write_state(out);
  return out.str();
}

}  // namespace ellc::engine::testing
