#pragma once
// The full state of a simulation as bytes (Simulation::write_state, the checkpoint body): equal
// bytes mean bitwise-equal runs. Shared by the engine's determinism tests and the scenario's
// restart tests.

#include <sstream>
#include <string>

#include "ellc/engine/simulation.hpp"

namespace ellc::test {

[[nodiscard]] inline std::string state_bytes(const engine::Simulation& simulation) {
  std::ostringstream out(std::ios::binary);
  simulation.write_state(out);
  return out.str();
}

}  // namespace ellc::test
