// The checkpoint file's integrity (docs/engine.md, "Checkpoint file"): every flipped byte is
// caught by the checksum, a size field is checked against the file before anything is allocated,
// and a file whose checksum was made to match (a deliberate edit, or another writer) is still
// refused when its content is impossible: a zero semi-axis, a zero quaternion, a repeated id,
// dt = 0, a pair naming a particle that does not exist. Nothing is overwritten on refusal.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "ellc/scenario/checkpoint.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using ellc::test::input_error_message;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("ellc_ckpt_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <typename T>
std::string bytes_of(const T& value) {
  return std::string(reinterpret_cast<const char*>(&value), sizeof value);
}

// A checkpoint of the quick example part-way into the compaction, and the runner that wrote it.
struct Written {
  Scenario scenario = quick_scenario(quick_scenario_text());
  std::unique_ptr<ScenarioRunner> runner;
  std::string bytes;

  Written() {
    runner = std::make_unique<ScenarioRunner>(scenario, in_memory(512));
    runner->advance(400);
    const std::string path = temporary_path("written.bin");
    runner->write_checkpoint(path);
    bytes = file_bytes(path);
    std::remove(path.c_str());
  }
  // The error reading `candidate` gives ("" when it is accepted).
  [[nodiscard]] std::string error_reading(const std::string& candidate) const {
    return input_error_message(
        [&] { (void)parse_checkpoint(candidate, "edited.bin", scenario, engine::EngineSettings{}); });
  }
};

// `bytes` with `replacement` written over the first occurrence of `pattern` at or after `from`,
// and the header's CRC recomputed, as a deliberate editor (or a buggy writer) would leave it.
std::string edited(std::string bytes, const std::string& pattern, const std::string& replacement,
                   std::size_t from = kCheckpointHeaderSize) {
  const auto at = bytes.find(pattern, from);
  if (at == std::string::npos) throw std::runtime_error("pattern not found in the checkpoint");
  bytes.replace(at, replacement.size(), replacement);
  const std::uint32_t crc = crc32(std::string_view(bytes).substr(kCheckpointHeaderSize));
  std::memcpy(bytes.data() + 24, &crc, sizeof crc);
  return bytes;
}

TEST(Checkpoint, Crc32IsTheStandardOne) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926U);  // the CRC-32/ISO-HDLC check value
  EXPECT_EQ(crc32(""), 0U);
}

TEST(Checkpoint, HeaderNamesFormatAndLength) {
  const Written written;
  ASSERT_GT(written.bytes.size(), kCheckpointHeaderSize);
  EXPECT_EQ(written.bytes.substr(0, 8), "ELLCCKPT");
  std::uint32_t version = 0;
  std::uint64_t payload = 0;
  std::memcpy(&version, written.bytes.data() + 8, sizeof version);
  std::memcpy(&payload, written.bytes.data() + 16, sizeof payload);
  EXPECT_EQ(version, kCheckpointFormatVersion);
  EXPECT_EQ(payload, written.bytes.size() - kCheckpointHeaderSize);
  EXPECT_EQ(written.error_reading(written.bytes), "");
}

// One flipped bit anywhere (one position in every 499, and every header byte) is refused.
TEST(Checkpoint, EveryFlippedByteIsRefused) {
  const Written written;
  int refused = 0;
  int tried = 0;
  for (std::size_t at = 0; at < written.bytes.size(); at += at < kCheckpointHeaderSize ? 1 : 499) {
    std::string flipped = written.bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    ++tried;
    if (!written.error_reading(flipped).empty()) ++refused;
  }
  EXPECT_EQ(refused, tried);
  std::string flipped = written.bytes;
  flipped[written.bytes.size() / 2] ^= 0x01;
  EXPECT_NE(written.error_reading(flipped).find("checksum does not match"), std::string::npos)
      << written.error_reading(flipped);
}

TEST(Checkpoint, TruncatedOrExtendedFileIsRefusedByItsLength) {
  const Written written;
  const std::string cut = written.error_reading(written.bytes.substr(0, written.bytes.size() - 100));
  EXPECT_NE(cut.find("announces"), std::string::npos) << cut;
  EXPECT_NE(written.error_reading(written.bytes + "x").find("announces"), std::string::npos);
  EXPECT_NE(written.error_reading(written.bytes.substr(0, 10)).find("not an ellc dem checkpoint"), std::string::npos);
  EXPECT_NE(written.error_reading("").find("not an ellc dem checkpoint"), std::string::npos);
}

TEST(Checkpoint, OlderFormatWithoutChecksumIsRefusedByName) {
  const Written written;
  const std::string old = bytes_of(std::uint64_t{0x454c4c43'434b5032ULL}) + written.bytes.substr(8);
  const std::string message = written.error_reading(old);
  EXPECT_NE(message.find("format 2"), std::string::npos) << message;
  EXPECT_NE(message.find("without a checksum"), std::string::npos) << message;
}

// A size field made huge (with a matching checksum) is compared with the bytes left before any
// allocation: the pair list's count set to 2^40 (~300 TB of pair slots).
TEST(Checkpoint, SizeFieldIsCheckedBeforeAllocating) {
  const Written written;
  const auto& pairs = written.runner->simulation().pairs();
  ASSERT_FALSE(pairs.empty());
  const std::string count_and_key = bytes_of(std::uint64_t{pairs.size()}) + bytes_of(pairs[0].key);
  const std::string message =
      written.error_reading(edited(written.bytes, count_and_key, bytes_of(std::uint64_t{1} << 40)));
  EXPECT_NE(message.find("an array of 1099511627776 elements"), std::string::npos) << message;
  EXPECT_NE(message.find("bytes are left"), std::string::npos) << message;  // checked against the rest
}

TEST(Checkpoint, ImpossibleContentIsRefusedWithTheReason) {
  const Written written;
  const auto& particles = written.runner->simulation().particles();
  ASSERT_GE(particles.size(), 2U);

  const Eigen::Vector3d& axes = particles.semi_axes[0];
  const std::string zero_axis = bytes_of(0.0);
  std::string message = written.error_reading(
      edited(written.bytes, std::string(reinterpret_cast<const char*>(axes.data()), 24), zero_axis));
  EXPECT_NE(message.find("semi-axes"), std::string::npos) << message;

  const Eigen::Quaterniond& rotation = particles.orientation[0];
  message = written.error_reading(edited(
      written.bytes, std::string(reinterpret_cast<const char*>(rotation.coeffs().data()), 32), std::string(32, '\0')));
  EXPECT_NE(message.find("quaternion of norm 0"), std::string::npos) << message;

  const std::string ids =
      bytes_of(std::uint64_t{particles.size()}) + bytes_of(particles.id[0]) + bytes_of(particles.id[1]);
  message = written.error_reading(
      edited(written.bytes, ids,
             bytes_of(std::uint64_t{particles.size()}) + bytes_of(particles.id[0]) + bytes_of(particles.id[0])));
  EXPECT_NE(message.find("appears twice"), std::string::npos) << message;

  // dt: the tenth field of the simulation's state (after its tag and eight counters).
  const std::string state_tag = bytes_of(std::uint64_t{0x454c4c43'44454d33ULL});
  const auto state = written.bytes.find(state_tag);
  ASSERT_NE(state, std::string::npos);
  const double dt = written.runner->simulation().settings().dt;
  ASSERT_EQ(written.bytes.substr(state + 72, 8), bytes_of(dt));
  message = written.error_reading(edited(written.bytes, bytes_of(dt), bytes_of(0.0), state + 72));
  EXPECT_NE(message.find("dt = 0"), std::string::npos) << message;

  const auto& pair = written.runner->simulation().pairs()[0];
  const std::uint32_t missing = static_cast<std::uint32_t>(particles.size()) + 5;
  message = written.error_reading(edited(written.bytes, bytes_of(pair.key) + bytes_of(pair.i) + bytes_of(pair.j),
                                         bytes_of(pair.key) + bytes_of(missing)));
  EXPECT_NE(message.find("refers to particle slots"), std::string::npos) << message;
}

// The species array (after the torques): a species the scenario does not have is refused; a
// state of the format before species (tag ELLCDEM2, no species array) loads as one species.
TEST(Checkpoint, SpeciesAreCheckedAndOldStatesLoadAsOneSpecies) {
  const Written written;
  const engine::ParticleSet& particles = written.runner->simulation().particles();
  const std::size_t n = particles.size();
  // The whole torque array (its count, then every torque) anchors the species array behind it; the
  // last match (before contacts, the force array is all zeros like the torques and matches too).
  std::string torques = bytes_of(std::uint64_t{n});
  for (const Eigen::Vector3d& torque : particles.torque) torques += bytes_of(torque);
  const std::string species = torques + bytes_of(std::uint64_t{n}) + std::string(2 * n, '\0');
  const auto at = written.bytes.rfind(species);
  ASSERT_NE(at, std::string::npos);
  std::string unknown = species;
  unknown[unknown.size() - 2] = 1;  // the last particle of species 1, in a one-species scenario
  std::string message = written.error_reading(edited(written.bytes, species, unknown, at));
  EXPECT_NE(message.find("is of species 1"), std::string::npos) << message;

  std::string old = written.bytes;
  old.erase(at + torques.size(), 8 + 2 * n);
  const std::string tag = bytes_of(std::uint64_t{0x454c4c43'44454d33ULL});
  const std::uint64_t payload = old.size() - kCheckpointHeaderSize;
  std::memcpy(old.data() + 16, &payload, sizeof payload);
  old = edited(old, tag, bytes_of(std::uint64_t{0x454c4c43'44454d32ULL}));
  const Checkpoint loaded = parse_checkpoint(old, "old.bin", written.scenario, engine::EngineSettings{});
  EXPECT_EQ(loaded.simulation->particles().species, std::vector<std::uint16_t>(n, 0));
  EXPECT_EQ(loaded.simulation->particles().position, particles.position);
}

// A refused restart leaves the output directory as it was: nothing is opened for writing before
// the checkpoint has been read and checked.
TEST(Checkpoint, RefusedRestartOverwritesNothing) {
  const Written written;
  const std::filesystem::path directory = temporary_path("outputs");
  std::filesystem::create_directories(directory);
  const std::string checkpoint = (directory / "checkpoint.bin").string();
  const std::string csv = (directory / "timeseries.csv").string();
  std::string damaged = written.bytes;
  damaged[damaged.size() / 3] ^= 0x04;
  std::ofstream(checkpoint, std::ios::binary) << damaged;
  std::ofstream(csv) << "earlier rows\n";

  RunOptions options;
  options.output_directory = directory.string();
  options.restart_path = checkpoint;
  const std::string message = input_error_message([&] { ScenarioRunner runner(written.scenario, options); });
  EXPECT_NE(message.find("checksum"), std::string::npos) << message;
  EXPECT_EQ(file_bytes(checkpoint), damaged);
  EXPECT_EQ(file_bytes(csv), "earlier rows\n");
  EXPECT_FALSE(std::filesystem::exists(directory / "vtk"));

  const std::string as_directory = input_error_message([&] {
    RunOptions other = options;
    other.restart_path = directory.string();
    ScenarioRunner runner(written.scenario, other);
  });
  EXPECT_NE(as_directory.find("not a directory"), std::string::npos) << as_directory;
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace ellc::scenario
