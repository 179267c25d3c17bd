#pragma once
// The analysis step shared by `ellc analyse` and `ellc dem`'s [analysis]: run the microstructure
// analysis of a packing, write its files into a folder, print its summary, draw its PNGs.

#include <string>

#include "ellc/microstructure/analysis.hpp"
#include "ellc/scenario/scenario_runner.hpp"

namespace ellc::cli {

// Returns the report; the PNGs (python3 -m ellc.plots analysis DIR) unless `no_plot`.
microstructure::AnalysisReport analyse_into(const microstructure::Packing& packing,
                                            const microstructure::AnalysisOptions& options,
                                            const std::string& directory, const std::string& source,
                                            const std::string& title, bool no_plot);

// `ellc dem` with [analysis], after a finished run: the loaded state (end of the hold) and the
// released state (the end) into DIR/analysis_loaded/ and DIR/analysis_released/, their summary
// (porosity, τ_z, the Bruggeman exponent across them) printed and appended to DIR/summary.txt,
// and DIR/tortuosity_porosity.png.
void analyse_run_states(const scenario::ScenarioRunner& runner, bool no_plot);

}  // namespace ellc::cli
