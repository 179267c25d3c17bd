#include "ellc/calibration/calibration_case.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"

namespace ellc {

namespace {

namespace fs = std::filesystem;

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(first, last - first + 1));
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

struct CsvContent {
  std::vector<double> overlaps;
  std::vector<double> forces;
  std::string case_reference;  // from a "# case = ..." comment, if any
};

CsvContent read_overlap_force_csv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError(path, "cannot open the calibration data file");
  CsvContent content;
  std::string line;
  long line_number = 0;
  std::ptrdiff_t overlap_column = -1;
  std::ptrdiff_t force_column = -1;
  std::size_t column_count = 0;
  while (std::getline(file, line)) {
    ++line_number;
    const std::string text = trim(line);
    if (text.empty()) continue;
    const std::string where = path + ":" + std::to_string(line_number);
    if (text.front() == '#') {
      const std::string comment = trim(std::string_view(text).substr(1));
      if (comment.rfind("case", 0) == 0) {
        const auto equals = comment.find('=');
        if (equals != std::string::npos && trim(std::string_view(comment).substr(4, equals - 4)).empty())
          content.case_reference = trim(std::string_view(comment).substr(equals + 1));
      }
      continue;
    }
    const std::vector<std::string> fields = split_fields(text);
    if (column_count == 0) {  // the header
      column_count = fields.size();
      for (std::size_t index = 0; index < fields.size(); ++index) {
        if (fields[index] == "overlap") overlap_column = static_cast<std::ptrdiff_t>(index);
        if (fields[index] == "force") force_column = static_cast<std::ptrdiff_t>(index);
      }
      if (overlap_column < 0 || force_column < 0)
        throw InputError(where, "header = \"" + text + "\": expected a header naming the columns overlap and force");
      continue;
    }
    if (fields.size() != column_count)
      throw InputError(where, "a row of " + std::to_string(fields.size()) + " fields: expected " +
                                  std::to_string(column_count) + " like the header");
    auto number = [&](std::ptrdiff_t column, const char* name) {
      const std::string& field = fields[static_cast<std::size_t>(column)];
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(value))
        throw InputError(where, name, "\"" + field + "\"", "a finite number");
      return value;
    };
    content.overlaps.push_back(number(overlap_column, "overlap"));
    content.forces.push_back(number(force_column, "force"));
  }
  if (column_count == 0) throw InputError(path, "empty file: expected a header naming overlap and force, then rows");
  if (content.overlaps.empty()) throw InputError(path, "no data rows after the header");
  return content;
}

// "name.csv" and "name.incomplete.csv" → "name".
std::string case_name_of(const fs::path& csv) {
  std::string name = csv.filename().string();
  for (const char* suffix : {".incomplete.csv", ".csv"}) {
    const std::string ending(suffix);
    if (name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
      return name.substr(0, name.size() - ending.size());
  }
  return csv.stem().string();
}

}  // namespace

void read_case_geometry(const std::string& case_path, BodySpec& body_i, BodySpec& body_j,
                        std::vector<std::string>& warnings) {
  const toml::table root_table = parse_toml_file(case_path);
  TableReader root(root_table, "", case_path);
  auto pair = read_body_pair(root, warnings);
  body_i = std::move(pair.body_i);
  body_j = std::move(pair.body_j);
  (void)root.has("protocol");  // a full `ellc curve` case is fine; the protocol is not needed
  (void)root.has("model");
  root.finish();
}

CalibrationCase read_calibration_case(const std::string& csv_path, const std::string& case_path) {
  CalibrationCase result;
  CsvContent content = read_overlap_force_csv(csv_path);
  result.name = case_name_of(csv_path);
  result.case_path = case_path;
  std::vector<std::string> warnings;  // aspect-ratio warnings do not matter for a calibration
  read_case_geometry(case_path, result.body_i, result.body_j, warnings);
  result.overlaps = std::move(content.overlaps);
  result.forces = std::move(content.forces);
  return result;
}

CalibrationCase read_calibration_case(const std::string& data_argument) {
  // Explicit pairing "data.csv:case.toml" (the part after the last ':' must name a .toml file).
  if (const auto colon = data_argument.rfind(':'); colon != std::string::npos) {
    const std::string case_part = data_argument.substr(colon + 1);
    if (case_part.size() > 5 && case_part.compare(case_part.size() - 5, 5, ".toml") == 0)
      return read_calibration_case(data_argument.substr(0, colon), case_part);
  }
  const fs::path csv(data_argument);
  if (!fs::exists(csv)) throw InputError(data_argument, "no such calibration data file");
  const CsvContent content = read_overlap_force_csv(data_argument);
  fs::path case_path;
  if (!content.case_reference.empty()) {
    case_path = fs::path(content.case_reference);
    if (case_path.is_relative()) case_path = csv.parent_path() / case_path;
  } else {
    case_path = csv.parent_path() / (case_name_of(csv) + ".toml");
  }
  if (!fs::exists(case_path))
    throw InputError(data_argument, "no case file " + case_path.string() +
                                        " for its geometry and material: expected a sidecar TOML with [material], "
                                        "[body_I], [body_J] (or DATA.csv:CASE.toml, or a '# case = CASE.toml' line)");
  return read_calibration_case(data_argument, case_path.string());
}

}  // namespace ellc
