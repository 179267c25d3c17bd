#pragma once
// The bridge from DEM states to the microstructure layer (docs/microstructure.md): a Simulation as
// a plain packing, a checkpoint as a packing, and the analysis of the loaded and released states
// of a run with [analysis] and its Bruggeman fit.

#include <optional>
#include <string>
#include <vector>

#include "ellc/engine/simulation.hpp"
#include "ellc/microstructure/analysis.hpp"
#include "ellc/microstructure/packing.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

// The particles (rows = slots) in the box between the walls (periodic in x and y), and the pair
// contacts of the last force evaluation: the contact point midway between the two bodies' support
// points along the normal, the normal force, δ_* and the regime.
[[nodiscard]] microstructure::Packing packing_of(const engine::Simulation& simulation);

// The state of a checkpoint written by `scenario_path`'s run, with its contact forces evaluated
// once (a step of zero length, which moves nothing). InputError as read_checkpoint.
[[nodiscard]] microstructure::Packing read_checkpoint_packing(const std::string& checkpoint_path,
                                                              const std::string& scenario_path);

// The scenario's [analysis] as the layer's options (defaults when the scenario has none).
[[nodiscard]] microstructure::AnalysisOptions analysis_options(const Scenario& scenario);

struct StateAnalysis {
  std::string state;  // "loaded", "released"
  microstructure::AnalysisReport report;
};

// The through-plane (z) summary over the states: porosity, τ_z, and the Bruggeman exponent fitted
// across them (microstructure::fit_bruggeman_exponent), as TOML `key = value` lines (appended to
// summary.txt, a TOML document, by `ellc dem`): inf where τ does not percolate, with the quoted
// reason; nan for an exponent no state determines.
[[nodiscard]] std::string states_summary(const std::vector<StateAnalysis>& states);

}  // namespace ellc::scenario
