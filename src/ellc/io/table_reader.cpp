#include "ellc/io/table_reader.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ellc/io/input_error.hpp"

namespace ellc {

namespace {
std::string describe_node(const toml::node& node) {
  std::ostringstream out;
  if (const auto* text = node.as_string())
    out << '"' << text->get() << '"';
  else if (node.is_table())
    out << "a table";
  else if (node.is_array())
    out << "an array";
  else if (const auto number = node.value<double>(); number && !node.is_boolean())
    out << format_number(*number);
  else if (const auto flag = node.value_exact<bool>())
    out << (*flag ? "true" : "false");
  else
    out << "a value of another type";
  return out.str();
}
}  // namespace

TableReader::TableReader(const toml::table& table, std::string path, std::string source)
    : table_(&table), path_(std::move(path)), source_(std::move(source)) {}

std::string TableReader::field(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TableReader::fail(std::string_view key, const std::string& value, const std::string& expected) const {
  throw InputError(source_, field(key), value, expected);
}

void TableReader::fail(std::string_view key, double value, const std::string& expected) const {
  fail(key, format_number(value), expected);
}

const toml::node* TableReader::find(std::string_view key) {
  known_.emplace(key);
  return table_->get(key);
}

bool TableReader::has(std::string_view key) { return find(key) != nullptr; }

double TableReader::finite_number(const toml::node& node, const std::string& field_name) const {
  const auto value = node.value<double>();
  if (!value || node.is_boolean()) throw InputError(source_, field_name, describe_node(node), "a number");
  if (!std::isfinite(*value)) throw InputError(source_, field_name, format_number(*value), "a finite number");
  return *value;
}

std::optional<double> TableReader::optional_number(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr) return std::nullopt;
  return finite_number(*node, field(key));
}

double TableReader::number(std::string_view key) {
  const auto value = optional_number(key);
  if (!value) fail(key, "missing", "a number");
  return *value;
}

double TableReader::number_or(std::string_view key, double fallback) { return optional_number(key).value_or(fallback); }

double TableReader::positive(std::string_view key) {
  const double value = number(key);
  if (value <= 0.0) fail(key, value, "a finite number > 0");
  return value;
}

double TableReader::non_negative(std::string_view key) {
  const double value = number(key);
  if (value < 0.0) fail(key, value, "a finite number >= 0");
  return value;
}

long TableReader::integer_at_least(std::string_view key, long minimum, std::optional<long> fallback) {
  const toml::node* node = find(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    fail(key, "missing", "an integer >= " + std::to_string(minimum));
  }
  const auto value = node->value_exact<int64_t>();
  if (!value) fail(key, describe_node(*node), "an integer >= " + std::to_string(minimum));
  if (*value < minimum) fail(key, std::to_string(*value), "an integer >= " + std::to_string(minimum));
  return static_cast<long>(*value);
}

bool TableReader::boolean_or(std::string_view key, bool fallback) {
  const toml::node* node = find(key);
  if (node == nullptr) return fallback;
  const auto value = node->value_exact<bool>();
  if (!value) fail(key, describe_node(*node), "true or false");
  return *value;
}

std::optional<std::vector<double>> TableReader::optional_numbers(std::string_view key, std::size_t required_size) {
  const toml::node* node = find(key);
  if (node == nullptr) return std::nullopt;
  const std::string expected =
      required_size ? "an array of " + std::to_string(required_size) + " numbers" : "a non-empty array of numbers";
  const toml::array* array = node->as_array();
  if (array == nullptr) fail(key, describe_node(*node), expected);
  if (array->empty() || (required_size && array->size() != required_size))
    fail(key, "an array of " + std::to_string(array->size()) + " elements", expected);
  std::vector<double> values;
  values.reserve(array->size());
  for (std::size_t index = 0; index < array->size(); ++index)
    values.push_back(finite_number(*array->get(index), field(key) + "[" + std::to_string(index) + "]"));
  return values;
}

std::optional<std::vector<long>> TableReader::optional_integers(std::string_view key, long minimum) {
  const toml::node* node = find(key);
  if (node == nullptr) return std::nullopt;
  const std::string expected = "an integer >= " + std::to_string(minimum);
  const toml::array* array = node->as_array();
  if (array == nullptr) fail(key, describe_node(*node), "an array of integers >= " + std::to_string(minimum));
  std::vector<long> values;
  values.reserve(array->size());
  for (std::size_t index = 0; index < array->size(); ++index) {
    const toml::node& element = *array->get(index);
    const std::string element_field = field(key) + "[" + std::to_string(index) + "]";
    const auto value = element.value_exact<int64_t>();
    if (!value) {
      std::string seen = describe_node(element);
      if (element.is_floating_point() && seen.find_first_of(".eni") == std::string::npos) seen += ".0";  // 3.0, not 3
      throw InputError(source_, element_field, seen, expected);
    }
    if (*value < minimum) throw InputError(source_, element_field, std::to_string(*value), expected);
    values.push_back(static_cast<long>(*value));
  }
  return values;
}

std::vector<double> TableReader::numbers(std::string_view key, std::size_t required_size) {
  auto values = optional_numbers(key, required_size);
  if (!values)
    fail(key, "missing",
         required_size ? "an array of " + std::to_string(required_size) + " numbers" : "a non-empty array of numbers");
  return *values;
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr) return std::nullopt;
  const auto value = node->value_exact<std::string>();
  if (!value) fail(key, describe_node(*node), "a string");
  return *value;
}

std::string TableReader::choice(std::string_view key, const std::vector<std::string>& allowed,
                                std::optional<std::string> fallback) {
  std::string options;
  for (const auto& option : allowed) options += (options.empty() ? "\"" : ", \"") + option + "\"";
  const auto value = optional_string(key);
  if (!value) {
    if (fallback) return *fallback;
    fail(key, "missing", "one of " + options);
  }
  for (const auto& option : allowed)
    if (*value == option) return *value;
  fail(key, "\"" + *value + "\"", "one of " + options);
}

TableReader TableReader::table(std::string_view key) {
  auto child = optional_table(key);
  if (!child) throw InputError(source_, "missing table [" + field(key) + "]");
  return *child;
}

std::optional<TableReader> TableReader::optional_table(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr) return std::nullopt;
  const toml::table* child = node->as_table();
  if (child == nullptr) fail(key, describe_node(*node), "a table");
  return TableReader(*child, field(key), source_);
}

std::vector<TableReader> TableReader::tables(std::string_view key) {
  std::vector<TableReader> result;
  const toml::node* node = find(key);
  if (node == nullptr) return result;
  const toml::array* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) fail(key, describe_node(*node), "an array of tables [[...]]");
  for (std::size_t index = 0; index < array->size(); ++index)
    result.emplace_back(*array->get(index)->as_table(), field(key) + "[" + std::to_string(index) + "]", source_);
  return result;
}

void TableReader::finish() const {
  for (const auto& [key, node] : *table_) {
    if (known_.contains(key.str())) continue;
    std::string known;
    for (const auto& name : known_) known += (known.empty() ? "" : ", ") + name;
    throw InputError(source_, "unknown key '" + field(key.str()) + "'" +
                                  (path_.empty() ? " at the top level" : " in [" + path_ + "]") +
                                  "; known keys: " + known);
  }
}

toml::table parse_toml_text(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << "not valid TOML at line " << error.source().begin.line << ", column " << error.source().begin.column << ": "
        << error.description();
    throw InputError(source, out.str());
  }
}

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throw InputError(path, "no such file");
  if (fs::is_directory(status)) throw InputError(path, "is a directory: expected a file");
  if (!fs::is_regular_file(status))
    throw InputError(path, "is not a regular file (a device or a pipe?): expected a file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (!error && size > kMaxInputFileBytes)
    throw InputError(path, "is " + std::to_string(size) + " bytes long: expected an input file of at most " +
                               std::to_string(kMaxInputFileBytes >> 20) + " MiB");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "cannot open the file for reading");
  std::stringstream contents;
  contents << file.rdbuf();
  if (file.bad()) throw InputError(path, "cannot read the file");
  return contents.str();
}

toml::table parse_toml_file(const std::string& path) { return parse_toml_text(read_text_file(path), path); }

}  // namespace ellc
