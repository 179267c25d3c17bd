// Fuzz target: the two-body case file of `ellc curve` (cases/case_file.hpp). Bytes → TOML →
// validated CurveCase → the contact constants → the law along the first points of the protocol.
// Crashes, sanitizer reports and hangs are findings here; whether `ellc curve` prints finite
// numbers is its own check (apps/ellc/curve_command.cpp).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ellc/cases/case_file.hpp"
#include "ellc/cases/protocol.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/law/law_along_path.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellc;
  try {
    const CurveCase curve = parse_curve_case(fuzz::text_of(data, size), "fuzz_case.toml");
    const ContactConstants constants =
        case_contact_constants(curve.body_i, curve.body_j, curve.model.hertz, curve.model.law);
    if (!validation_error(constants).empty()) return 0;  // `ellc curve` stops here with an error
    std::vector<double> path = protocol_overlaps(curve.waypoints, std::min(curve.points_per_segment, 4L));
    if (path.size() > 64) path.resize(64);
    std::vector<LawResult> results(path.size());
    evaluate_along_path(constants, path, results);
    (void)results;
  } catch (const InputError&) {
  }
  return 0;
}
