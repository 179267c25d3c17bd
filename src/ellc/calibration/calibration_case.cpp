#include "ellc/calibration/calibration_case.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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

CsvContent parse_overlap_force_csv(std::string_view text_of_file, const std::string& path) {
  std::istringstream file{std::string(text_of_file)};
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
      // Column names compared without case: "Force" next to "force" is as ambiguous as a repeat.
      std::map<std::string, std::size_t> seen;
      for (std::size_t index = 0; index < fields.size(); ++index) {
        std::string folded = fields[index];
        for (char& c : folded) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (const auto [at, inserted] = seen.emplace(folded, index); !inserted)
          throw InputError(where, "header = \"" + text + "\": columns " + std::to_string(at->second + 1) + " (\"" +
                                      fields[at->second] + "\") and " + std::to_string(index + 1) + " (\"" +
                                      fields[index] + "\") have the same name: expected each column named once");
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
    const std::size_t row = content.overlaps.size() + 1;
    auto number = [&](std::ptrdiff_t column, const char* name) {
      const std::string& field = fields[static_cast<std::size_t>(column)];
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(value))
        throw InputError(where, std::string(name) + " of data row " + std::to_string(row), "\"" + field + "\"",
                         "a finite number");
      return value;
    };
    content.overlaps.push_back(number(overlap_column, "overlap"));
    content.forces.push_back(number(force_column, "force"));
  }
  if (column_count == 0) throw InputError(path, "empty file: expected a header naming overlap and force, then rows");
  if (content.overlaps.empty()) throw InputError(path, "no data rows after the header");
  return content;
}

std::string axes_text(const Eigen::Vector3d& axes) {
  return "[" + format_number(axes.x()) + ", " + format_number(axes.y()) + ", " + format_number(axes.z()) + "]";
}

// What the geometry says about the data: the constants of the contact are finite (else the bodies
// or the material are out of the number format's range, named as the user wrote them), every
// overlap is below a_I + a_J (where the centres meet: the bodies touch at their x tips), and the
// data spans more than one overlap.
void check_case_data(const CsvContent& content, const std::string& csv_path, const std::string& case_path,
                     const BodySpec& body_i, const BodySpec& body_j) {
  const ContactConstants constants = case_contact_constants(body_i, body_j, HertzMode::hale, LawParameters{});
  if (const std::string error = validation_error(constants); !error.empty())
    throw InputError(case_path, "body_I.semi_axes = " + axes_text(body_i.semi_axes) +
                                    ", body_J.semi_axes = " + axes_text(body_j.semi_axes) +
                                    " with the [material] given: expected bodies whose contact constants are finite "
                                    "(docs/input_limits.md), but they give " +
                                    error);
  const double reach = body_i.semi_axes.x() + body_j.semi_axes.x();
  for (std::size_t row = 0; row < content.overlaps.size(); ++row)
    if (!(std::abs(content.overlaps[row]) < reach))
      throw InputError(csv_path, "overlap of data row " + std::to_string(row + 1), format_number(content.overlaps[row]),
                       "an overlap below a_I + a_J = " + format_number(reach) +
                           " µm (body_I.semi_axes[0] + body_J.semi_axes[0] of " + case_path +
                           "; at that overlap the centres meet)");
  const auto [low, high] = std::minmax_element(content.overlaps.begin(), content.overlaps.end());
  if (*low == *high)
    throw InputError(
        csv_path, "overlap",
        "the same " + format_number(*low) + " µm in all " + std::to_string(content.overlaps.size()) + " data rows",
        "data over a range of overlaps (a force-overlap curve)");
}

CsvContent read_overlap_force_csv(const std::string& path) {
  return parse_overlap_force_csv(read_text_file(path), path);
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
  check_case_data(content, csv_path, case_path, result.body_i, result.body_j);
  result.overlaps = std::move(content.overlaps);
  result.forces = std::move(content.forces);
  return result;
}

CalibrationCase parse_calibration_case(std::string_view csv_text, const std::string& csv_source, const BodySpec& body_i,
                                       const BodySpec& body_j, const std::string& case_source) {
  CsvContent content = parse_overlap_force_csv(csv_text, csv_source);
  check_case_data(content, csv_source, case_source, body_i, body_j);
  CalibrationCase result;
  result.name = case_name_of(csv_source);
  result.body_i = body_i;
  result.body_j = body_j;
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
