// Fuzz target: the checkpoint reader of `ellc dem --restart` (scenario/checkpoint.hpp), for the
// scenario in checkpoint_scenario.toml. Bytes → header checks → checksum → the state and its
// content checks → two engine steps from the restored state.
//
// A mutated file almost never keeps a matching checksum, so when the bytes start with the
// checkpoint's magic and the header's reserved word (bytes 28..31) is zero, the harness writes
// the right payload length and CRC-32 into the header first: the mutations then reach the content
// checks, as a deliberately edited file would. A non-zero reserved word leaves the header as the
// fuzzer made it: the length and checksum checks (the reader then refuses the reserved word).

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"
#include "ellc/scenario/checkpoint.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace ellc;
using namespace ellc::scenario;

const Scenario& fixed_scenario() {
  static const Scenario scenario = [] {
    const std::string path = std::string(ELLC_FUZZ_DIR) + "/checkpoint_scenario.toml";
    return parse_scenario(read_text_file(path), path);
  }();
  return scenario;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(fuzz::text_of(data, size));
  if (bytes.size() >= kCheckpointHeaderSize && bytes.compare(0, 8, "ELLCCKPT") == 0) {
    std::uint32_t reserved = 0;
    std::memcpy(&reserved, bytes.data() + 28, sizeof reserved);
    if (reserved == 0) {
      const std::uint64_t payload = bytes.size() - kCheckpointHeaderSize;
      const std::uint32_t crc = crc32(std::string_view(bytes).substr(kCheckpointHeaderSize));
      std::memcpy(bytes.data() + 16, &payload, sizeof payload);
      std::memcpy(bytes.data() + 24, &crc, sizeof crc);
    }
  }
  const Scenario& scenario = fixed_scenario();
  engine::EngineSettings settings;
  settings.contact = scenario.contact;
  settings.box = scenario.box;
  settings.skin = scenario.skin;
  settings.max_speed = scenario.max_speed;
  try {
    Checkpoint checkpoint = parse_checkpoint(bytes, "fuzz.bin", scenario, settings);
    for (int step = 0; step < 2; ++step) checkpoint.simulation->step();
    fuzz::require_finite(checkpoint.simulation->kinetic_energy(), "non-finite kinetic energy after a restart");
    fuzz::require_finite(checkpoint.simulation->wall_pressure(engine::kTopWall), "non-finite plate pressure");
  } catch (const InputError&) {
  } catch (const engine::RunawayError&) {
  }
  return 0;
}
