#include "ellc/scenario/checkpoint.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <streambuf>
#include <vector>

#include "ellc/engine/binary_io.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

using engine::EngineSettings;
using engine::ParticleSet;
using engine::Simulation;
using engine::Wall;
namespace binary = engine::binary;

namespace {

constexpr char kMagic[8] = {'E', 'L', 'L', 'C', 'C', 'K', 'P', 'T'};
// Formats 1 and 2 began with these tags and had no checksum (they are refused with that reason).
constexpr std::uint64_t kUncheckedTags[] = {0x454c4c43'434b5031ULL, 0x454c4c43'434b5032ULL};
constexpr std::uint64_t kRecordTag = 0x454c4c43'52554e31ULL;  // "ELLCRUN1"

// The header, field by field (little-endian on every platform ellc builds for; no padding).
struct Header {
  std::uint32_t version = kCheckpointFormatVersion;
  std::uint32_t header_size = kCheckpointHeaderSize;
  std::uint64_t payload_size = 0;
  std::uint32_t payload_crc = 0;
  std::uint32_t reserved = 0;
};

std::string encode_header(const Header& header) {
  std::string bytes(kMagic, sizeof kMagic);
  const auto append = [&bytes](const auto& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  append(header.version);
  append(header.header_size);
  append(header.payload_size);
  append(header.payload_crc);
  append(header.reserved);
  return bytes;
}

template <typename T>
T field_at(std::string_view bytes, std::size_t offset) {
  T value{};
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

void check_payload_size(std::uint64_t announced, std::uint64_t held, const std::string& source) {
  if (announced != held)
    throw InputError(source, "corrupt checkpoint: its header announces " + std::to_string(announced) +
                                 " bytes of state, the file holds " + std::to_string(held) +
                                 " (cut short, or something appended)");
}

// The checks a checkpoint's header must pass before its payload is read: returns the payload.
std::string_view checked_payload(std::string_view bytes, const std::string& source) {
  if (bytes.size() >= 8) {
    const auto tag = field_at<std::uint64_t>(bytes, 0);
    for (const std::uint64_t old : kUncheckedTags)
      if (tag == old)
        throw InputError(source, "a checkpoint of format " + std::to_string(tag == kUncheckedTags[0] ? 1 : 2) +
                                     ", written by an older ellc without a checksum: this ellc reads format " +
                                     std::to_string(kCheckpointFormatVersion) +
                                     " only; finish that run with the ellc that wrote it, or start afresh");
  }
  if (bytes.size() < kCheckpointHeaderSize || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(source, "not an ellc dem checkpoint (it does not start with \"ELLCCKPT\")");
  Header header;
  header.version = field_at<std::uint32_t>(bytes, 8);
  header.header_size = field_at<std::uint32_t>(bytes, 12);
  header.payload_size = field_at<std::uint64_t>(bytes, 16);
  header.payload_crc = field_at<std::uint32_t>(bytes, 24);
  if (header.version != kCheckpointFormatVersion)
    throw InputError(source, "a checkpoint of format version " + std::to_string(header.version) +
                                 ": this ellc reads version " + std::to_string(kCheckpointFormatVersion));
  if (header.header_size != kCheckpointHeaderSize)
    throw InputError(source, "corrupt checkpoint: its header size field says " + std::to_string(header.header_size) +
                                 " bytes, expected " + std::to_string(kCheckpointHeaderSize));
  check_payload_size(header.payload_size, bytes.size() - kCheckpointHeaderSize, source);
  const std::string_view payload = bytes.substr(kCheckpointHeaderSize);
  if (const std::uint32_t computed = crc32(payload); computed != header.payload_crc) {
    char text[96];
    std::snprintf(text, sizeof text, "stored CRC-32 %08x, computed %08x", header.payload_crc, computed);
    throw InputError(source, std::string("corrupt checkpoint: the checksum does not match (") + text +
                                 "): the file was changed or damaged after it was written");
  }
  if (field_at<std::uint32_t>(bytes, 28) != 0)
    throw InputError(source, "corrupt checkpoint: its reserved header word is not 0");
  return payload;
}

// A field read from the payload must be a finite number (protocol state, record, dt estimate).
void check_finite(double value, const char* what) {
  if (!std::isfinite(value))
    throw std::runtime_error(std::string("checkpoint is corrupt: ") + what + " = " + format_number(value) +
                             " is not finite");
}

// The protocol state field by field (no padding bytes in the file: equal runs, equal files).
template <typename Io, typename State>
void protocol_fields(Io&& io, State& state) {
  io(state.phase);
  io(state.phase_end_time);
  io(state.load_start_gap);
  io(state.load_start_time);
  io(state.approaching);
  io(state.press_start_gap);
  io(state.max_pressure);
  io(state.gap_at_max_pressure);
  io(state.min_gap);
  io(state.pressure_end_of_hold);
  io(state.final_gap);
  io(state.final_porosity);
  io(state.loaded_porosity);
  io(state.done_step);
  io(state.plastic_at_load_start);
  io(state.ramp_start);
  io(state.ramp_from);
  io(state.ramp_to);
  io(state.approach_average);
  io(state.hold_start_time);
  io(state.relax_start_time);
  for (auto* reading : {&state.loaded, &state.released}) {
    io(reading->time);
    io(reading->unbalanced_force_ratio);
    io(reading->plate_speed);
    io(reading->gap);
    io(reading->pressure);
    io(reading->inertial_number);
  }
}

// The run's record field by field, as the protocol state.
template <typename Io, typename Record>
void record_fields(Io&& io, Record& record) {
  auto& terms = record.ledger.at_start;
  io(terms.kinetic);
  io(terms.elastic);
  io(terms.spring);
  io(terms.plastic);
  io(terms.friction);
  io(terms.damping);
  io(record.ledger.gravity_work);
  io(record.ledger.drag_dissipation);
  auto& loaded = record.loaded;
  io(loaded.recorded);
  io(loaded.unbalanced_force_ratio);
  io(loaded.kinetic_over_elastic);
  auto& validity = loaded.validity;
  io(validity.threshold);
  io(validity.pair_contacts);
  io(validity.pair_contacts_beyond);
  io(validity.pair_force);
  io(validity.pair_force_beyond);
  io(validity.wall_contacts);
  io(validity.wall_contacts_beyond);
  io(validity.wall_force);
  io(validity.wall_force_beyond);
  io(validity.largest_ratio);
}

}  // namespace

std::uint64_t scenario_hash(const std::string& text) noexcept {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

namespace {

// CRC-32 carried over consecutive pieces: crc32(a + b) = crc32_finish(extend(extend(start, a), b)).
constexpr std::uint32_t kCrcStart = 0xFFFFFFFFU;
std::uint32_t crc32_extend(std::uint32_t crc, std::string_view bytes) noexcept {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> entries{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int bit = 0; bit < 8; ++bit) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
      entries[n] = c;
    }
    return entries;
  }();
  for (const unsigned char byte : bytes) crc = table[(crc ^ byte) & 0xFFU] ^ (crc >> 8);
  return crc;
}
constexpr std::uint32_t crc32_finish(std::uint32_t crc) noexcept { return crc ^ 0xFFFFFFFFU; }

// The payload goes to the file as it is produced, through a 1 MiB buffer that also feeds its
// CRC: the checkpoint of a 10^5-particle run (350 MB) is no longer held in memory beside the
// state it copies.
class ChecksummedWriter final : public std::streambuf {
 public:
  explicit ChecksummedWriter(std::streambuf& file) : file_(file), buffer_(1 << 20) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  [[nodiscard]] std::uint64_t size() const noexcept { return written_; }
  [[nodiscard]] std::uint32_t crc() const noexcept { return crc32_finish(crc_); }

 protected:
  int_type overflow(int_type byte) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(byte, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(byte);
      pbump(1);
    }
    return traits_type::not_eof(byte);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const auto count = static_cast<std::size_t>(pptr() - pbase());
    crc_ = crc32_extend(crc_, std::string_view(pbase(), count));
    written_ += count;
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return file_.sputn(buffer_.data(), static_cast<std::streamsize>(count)) == static_cast<std::streamsize>(count);
  }
  std::streambuf& file_;
  std::vector<char> buffer_;
  std::uint32_t crc_ = kCrcStart;
  std::uint64_t written_ = 0;
};

// Reads the bytes in place (an istringstream would copy the payload once more). Seekable, so
// that binary::remaining_bytes can check an array's size field against what is left.
class ViewReader final : public std::streambuf {
 public:
  explicit ViewReader(std::string_view bytes) {
    char* begin = const_cast<char*>(bytes.data());  // never written: a get area only
    setg(begin, begin, begin + bytes.size());
  }

 protected:
  pos_type seekoff(off_type offset, std::ios_base::seekdir from, std::ios_base::openmode which) override {
    const off_type size = egptr() - eback();
    const off_type origin = from == std::ios_base::beg ? 0 : from == std::ios_base::cur ? gptr() - eback() : size;
    const off_type target = origin + offset;
    if ((which & std::ios_base::in) == 0 || target < 0 || target > size) return pos_type(off_type(-1));
    setg(eback(), eback() + target, egptr());
    return pos_type(target);
  }
  pos_type seekpos(pos_type position, std::ios_base::openmode which) override {
    return seekoff(off_type(position), std::ios_base::beg, which);
  }
};

}  // namespace

std::uint32_t crc32(std::string_view bytes) noexcept { return crc32_finish(crc32_extend(kCrcStart, bytes)); }

void write_checkpoint(const std::string& path, const Scenario& scenario, const ProtocolState& protocol,
                      double dt_estimate, const Simulation& simulation, const RunRecord& record) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + temporary + " for writing");
    Header header;
    out << encode_header(header);  // its size and CRC are known only once the payload is written
    ChecksummedWriter payload(*out.rdbuf());
    std::ostream payload_stream(&payload);
    binary::put(payload_stream, scenario_hash(scenario.text));
    protocol_fields([&payload_stream](const auto& value) { binary::put(payload_stream, value); }, protocol);
    binary::put(payload_stream, dt_estimate);
    simulation.write_state(payload_stream);
    binary::put(payload_stream, kRecordTag);
    record_fields([&payload_stream](const auto& value) { binary::put(payload_stream, value); }, record);
    payload_stream.flush();
    if (!payload_stream) throw std::runtime_error("writing " + temporary + " failed");
    header.payload_size = payload.size();
    header.payload_crc = payload.crc();
    out.seekp(0);
    out << encode_header(header);
    out.flush();
    if (!out) throw std::runtime_error("writing " + temporary + " failed");
  }
  std::filesystem::rename(temporary, path);
}

Checkpoint parse_checkpoint(std::string_view bytes, const std::string& source, const Scenario& scenario,
                            EngineSettings settings) {
  const std::string_view payload = checked_payload(bytes, source);
  ViewReader payload_reader(payload);
  std::istream in(&payload_reader);
  std::uint64_t hash = 0;
  Checkpoint checkpoint;
  try {
    binary::get(in, hash);
    if (hash != scenario_hash(scenario.text))
      throw InputError(source, "--restart", source,
                       "a checkpoint written by this same scenario file with the same --set entries (" +
                           scenario.source + " has changed since, or is another scenario)");
    ProtocolState& protocol = checkpoint.protocol;
    protocol_fields(
        [&in](auto& value) {
          binary::get(in, value);
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) check_finite(value, "a protocol time");
        },
        protocol);
    if (static_cast<int>(protocol.phase) > static_cast<int>(Phase::relax))
      throw std::runtime_error("checkpoint is corrupt: the protocol phase " +
                               std::to_string(static_cast<int>(protocol.phase)) + " is unknown");
    binary::get(in, checkpoint.dt_estimate);
    if (!(checkpoint.dt_estimate > 0.0) || !std::isfinite(checkpoint.dt_estimate))
      throw std::runtime_error("checkpoint is corrupt: the time-step estimate " +
                               format_number(checkpoint.dt_estimate) + " is not a finite number > 0");
    settings.dt = 1.0;  // overwritten by the stored state
    checkpoint.simulation = std::make_unique<Simulation>(settings, ParticleSet{}, std::array<Wall, 2>{});
    checkpoint.simulation->read_state(in);
    std::uint64_t record_tag = 0;
    binary::get(in, record_tag);
    if (record_tag != kRecordTag) throw std::runtime_error("checkpoint is corrupt: the run record's tag is missing");
    RunRecord record;
    record_fields(
        [&in](auto& value) {
          binary::get(in, value);
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) check_finite(value, "a record entry");
        },
        record);
    checkpoint.record = record;
    if (in.peek() != std::char_traits<char>::eof())
      throw std::runtime_error("checkpoint is corrupt: bytes left over after the run record");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    // The checksum matched, so the file is as it was written: a writer of another build, or a
    // deliberately edited file. The reason is named all the same.
    throw InputError(source, std::string(error.what()) + "; the checkpoint is refused");
  }
  return checkpoint;
}

Checkpoint read_checkpoint(const std::string& path, const Scenario& scenario, EngineSettings settings) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(path, "--restart", path, "a checkpoint file, not a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the checkpoint for reading");
  const auto size = std::filesystem::file_size(path, error);
  if (error) throw InputError(path, "cannot tell the checkpoint's size: " + error.message());
  // The header first: its payload size is checked against the file's length before the payload
  // is read into memory.
  std::string bytes(std::min<std::uintmax_t>(size, kCheckpointHeaderSize), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!in) throw InputError(path, "cannot read the checkpoint");
  if (size >= kCheckpointHeaderSize && std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0 &&
      field_at<std::uint32_t>(bytes, 8) == kCheckpointFormatVersion) {
    check_payload_size(field_at<std::uint64_t>(bytes, 16), size - kCheckpointHeaderSize, path);
    bytes.resize(size);
    in.read(bytes.data() + kCheckpointHeaderSize, static_cast<std::streamsize>(size - kCheckpointHeaderSize));
    if (!in) throw InputError(path, "cannot read the checkpoint");
  }
  return parse_checkpoint(bytes, path, scenario, std::move(settings));
}

}  // namespace ellc::scenario
