#pragma once
// Calibration input: force against overlap for one known two-body geometry (docs/calibration.md).
//
// DATA is a CSV whose header names at least the columns `overlap` and `force` (µm, µN; other
// columns are ignored, lines starting with '#' are comments), plus the geometry and material as
// an `ellc curve` case file ([material], [body_I], [body_J]; [protocol] and [model] may be
// present and are ignored). The case file is found as
//   1. `DATA.csv:CASE.toml` given explicitly on the command line,
//   2. a comment line `# case = CASE.toml` in the CSV (relative to the CSV's folder),
//   3. the CSV's name with `.csv` (or `.incomplete.csv`) replaced by `.toml`.

#include <string>
#include <string_view>
#include <vector>

#include "ellc/cases/case_file.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_constants.hpp"

namespace ellc {

struct CalibrationCase {
  std::string name;  // for messages and plots; the CSV's file name without extension by default
  BodySpec body_i;   // compressed along x, touching at the x tips (paper Sec. 4, Fig. 8)
  BodySpec body_j;
  std::vector<double> overlaps;  // δ, µm
  std::vector<double> forces;    // F, µN
  std::string case_path{};       // the case file with the geometry and material (messages name it)
};

// The constants of a case are case_contact_constants(body_i, body_j, ...) of io/case_file.hpp,
// the same builder `ellc curve` uses.

// Reads one DATA argument as described above; throws InputError naming the file and line.
[[nodiscard]] CalibrationCase read_calibration_case(const std::string& data_argument);
[[nodiscard]] CalibrationCase read_calibration_case(const std::string& csv_path, const std::string& case_path);

// The same from the CSV's text and a geometry already read (`csv_source` and `case_source` name
// them in messages); the fuzz harness of the table reader uses it.
[[nodiscard]] CalibrationCase parse_calibration_case(std::string_view csv_text, const std::string& csv_source,
                                                     const BodySpec& body_i, const BodySpec& body_j,
                                                     const std::string& case_source);

// The geometry part of a case file: [material], [body_I], [body_J] (+ ignored [protocol], [model]).
void read_case_geometry(const std::string& case_path, BodySpec& body_i, BodySpec& body_j,
                        std::vector<std::string>& warnings);

}  // namespace ellc
