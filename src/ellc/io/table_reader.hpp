#pragma once
// Typed, validating access to one TOML table. Every key asked for becomes "known"; finish()
// rejects the keys nobody asked for and lists the known ones, so a typo never passes silently.
// Shared by every input file of the tools (curve cases, poses, DEM scenarios).

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace ellc {

class TableReader {
 public:
  // `path` is the table's dotted name for messages ("" for the root); `source` the file name.
  TableReader(const toml::table& table, std::string path, std::string source);

  [[nodiscard]] bool has(std::string_view key);

  // Finite numbers (integers accepted). Throw InputError naming the key when missing/ill-typed.
  [[nodiscard]] double number(std::string_view key);
  [[nodiscard]] std::optional<double> optional_number(std::string_view key);
  [[nodiscard]] double number_or(std::string_view key, double fallback);
  [[nodiscard]] double positive(std::string_view key);      // > 0
  [[nodiscard]] double non_negative(std::string_view key);  // ≥ 0
  [[nodiscard]] long integer_at_least(std::string_view key, long minimum, std::optional<long> fallback = {});
  [[nodiscard]] bool boolean_or(std::string_view key, bool fallback);
  [[nodiscard]] std::vector<double> numbers(std::string_view key, std::size_t required_size = 0);
  [[nodiscard]] std::optional<std::vector<double>> optional_numbers(std::string_view key,
                                                                    std::size_t required_size = 0);
  // An array of integers, each >= minimum (an empty array is returned as such; absent: nullopt).
  // A float (even 3.0), a string or a value below `minimum` is refused naming `key[index]`.
  [[nodiscard]] std::optional<std::vector<long>> optional_integers(std::string_view key, long minimum);
  // A string that must be one of `allowed`.
  [[nodiscard]] std::string choice(std::string_view key, const std::vector<std::string>& allowed,
                                   std::optional<std::string> fallback = {});
  [[nodiscard]] std::optional<std::string> optional_string(std::string_view key);

  [[nodiscard]] TableReader table(std::string_view key);  // required sub-table
  [[nodiscard]] std::optional<TableReader> optional_table(std::string_view key);
  // Array of tables ([[key]]); empty when absent.
  [[nodiscard]] std::vector<TableReader> tables(std::string_view key);

  // Throws InputError for the first key that was never asked for, listing the known keys.
  void finish() const;

  [[nodiscard]] std::string field(std::string_view key) const;  // "path.key"
  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] const std::string& path() const noexcept { return path_; }

  // Error helpers that fill in the source file and the field path.
  [[noreturn]] void fail(std::string_view key, const std::string& value, const std::string& expected) const;
  [[noreturn]] void fail(std::string_view key, double value, const std::string& expected) const;

 private:
  const toml::node* find(std::string_view key);
  double finite_number(const toml::node& node, const std::string& field_name) const;

  const toml::table* table_;
  std::string path_;
  std::string source_;
  std::set<std::string, std::less<>> known_;
};

// The whole of a text input file. Refuses, naming the path, what is not a readable regular file
// (a directory, a device, a missing file) and files above kMaxInputFileBytes.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{256} << 20;  // 256 MiB
[[nodiscard]] std::string read_text_file(const std::string& path);

// Parses a TOML file (or text, for tests) into a table; parse errors become InputError with
// the line and column.
[[nodiscard]] toml::table parse_toml_file(const std::string& path);
[[nodiscard]] toml::table parse_toml_text(std::string_view text, const std::string& source);

}  // namespace ellc
