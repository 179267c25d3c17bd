#include "ellc/microstructure/packing.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>

#include "ellc/io/input_error.hpp"

namespace ellc::microstructure {

double Packing::particle_volume() const {
  double volume = 0.0;
  for (const auto& axes : semi_axes) volume += 4.0 / 3.0 * std::numbers::pi * axes.prod();
  return volume;
}

double Packing::smallest_semi_axis() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& axes : semi_axes) smallest = std::min(smallest, axes.minCoeff());
  return smallest;
}

namespace {

std::string vector_text(const Eigen::Vector3d& v) {
  return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
}

}  // namespace

void validate_packing(const Packing& packing, const std::string& source) {
  const std::size_t count = packing.size();
  if (packing.semi_axes.size() != count || packing.orientations.size() != count)
    throw InputError(source, "particles",
                     std::to_string(count) + " centres, " + std::to_string(packing.semi_axes.size()) + " semi-axes, " +
                         std::to_string(packing.orientations.size()) + " orientations",
                     "as many semi-axes and orientations as centres");
  const PackingBox& box = packing.box;
  if (!box.lower.allFinite() || !box.upper.allFinite() || !(box.upper.array() > box.lower.array()).all())
    throw InputError(source, "box", "lower " + vector_text(box.lower) + ", upper " + vector_text(box.upper),
                     "finite corners with upper > lower along x, y and z");
  static constexpr std::array<char, 3> kAxisNames{'a', 'b', 'c'};
  for (std::size_t row = 0; row < count; ++row) {
    const std::string name = "row " + std::to_string(row + 1);
    if (!packing.centres[row].allFinite())
      throw InputError(source, name + " centre", vector_text(packing.centres[row]), "finite coordinates");
    for (int axis = 0; axis < 3; ++axis) {
      const double value = packing.semi_axes[row][axis];
      if (!(std::isfinite(value) && value > 0.0))
        throw InputError(source, name + " semi-axis " + kAxisNames[static_cast<std::size_t>(axis)],
                         format_number(value), "a finite number > 0");
    }
    const Eigen::Quaterniond& q = packing.orientations[row];
    if (!q.coeffs().allFinite() || q.norm() == 0.0)
      throw InputError(source, name + " quaternion", format_number(q.w()) + " " + vector_text(q.vec()),
                       "a finite, non-zero quaternion");
  }
  for (std::size_t k = 0; k < packing.contacts.size(); ++k) {
    const ContactRecord& contact = packing.contacts[k];
    if (contact.i >= count || contact.j >= count)
      throw InputError(source, "contact row " + std::to_string(k + 1),
                       "particles " + std::to_string(contact.i) + ", " + std::to_string(contact.j),
                       "particle rows (0-based) below " + std::to_string(count));
    if (!std::isfinite(contact.normal_force) || !std::isfinite(contact.max_overlap) || !contact.point.allFinite())
      throw InputError(source, "contact row " + std::to_string(k + 1), "a non-finite value",
                       "finite point, normal_force and max_overlap");
  }
}

namespace {

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// A number of a CSV cell; "nan" reads as NaN, so that validate_packing names the row.
double cell_number(const std::string& text, const std::string& source, const std::string& field) {
  const std::string cell = trim(text);
  try {
    std::size_t used = 0;
    const double value = std::stod(cell, &used);
    if (used == cell.size()) return value;
  } catch (const std::exception&) {
  }
  throw InputError(source, field, cell, "a number");
}

Eigen::Vector3d header_vector(const std::string& text, const std::string& source, const std::string& key) {
  std::istringstream stream(text);
  Eigen::Vector3d v;
  std::string word;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(stream >> word)) throw InputError(source, key, text, "three numbers x y z");
    v[axis] = cell_number(word, source, key);
  }
  if (stream >> word) throw InputError(source, key, text, "three numbers x y z");
  return v;
}

std::array<bool, 3> header_flags(const std::string& text, const std::string& source) {
  std::istringstream stream(text);
  std::array<bool, 3> flags{};
  std::string word;
  for (auto& flag : flags) {
    if (!(stream >> word) || (word != "true" && word != "false" && word != "1" && word != "0"))
      throw InputError(source, "periodic", text, "three flags x y z, each true or false");
    flag = word == "true" || word == "1";
  }
  return flags;
}

// Rows of a CSV with the given header (after '#' lines); calls `row(fields, line_number)`.
template <typename RowAction>
void read_rows(std::istream& in, const std::string& source, const std::vector<std::string>& header,
               const RowAction& row, const std::function<void(const std::string&)>& comment) {
  std::string line;
  int line_number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string text = trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      comment(text);
      continue;
    }
    std::vector<std::string> fields = split(text, ',');
    for (auto& field : fields) field = trim(field);
    if (!header_seen) {
      if (fields != header) {
        std::string expected;
        for (const auto& name : header) expected += (expected.empty() ? "" : ",") + name;
        throw InputError(source, "header (line " + std::to_string(line_number) + ")", text, expected);
      }
      header_seen = true;
      continue;
    }
    if (fields.size() != header.size())
      throw InputError(source, "line " + std::to_string(line_number), std::to_string(fields.size()) + " columns",
                       std::to_string(header.size()) + " columns");
    row(fields, line_number);
  }
  if (!header_seen) throw InputError(source, "header", "none", "a CSV header line");
}

}  // namespace

std::string contacts_file_for(const std::string& packing_path) {
  const std::filesystem::path path(packing_path);
  return (path.parent_path() / (path.stem().string() + "_contacts.csv")).string();
}

Packing read_packing_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "file", path, "a readable packing file (CSV)");
  Packing packing;
  bool has_lower = false;
  bool has_upper = false;
  const auto comment = [&](const std::string& text) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) return;
    const std::string key = trim(text.substr(1, equals - 1));
    const std::string value = trim(text.substr(equals + 1));
    if (key == "box_lower") {
      packing.box.lower = header_vector(value, path, key);
      has_lower = true;
    } else if (key == "box_upper") {
      packing.box.upper = header_vector(value, path, key);
      has_upper = true;
    } else if (key == "periodic") {
      packing.box.periodic = header_flags(value, path);
    }
  };
  read_rows(
      in, path, {"x", "y", "z", "a", "b", "c", "qw", "qx", "qy", "qz"},
      [&](const std::vector<std::string>& f, int line) {
        const std::string at = "line " + std::to_string(line) + " (row " + std::to_string(packing.size() + 1) + ")";
        double v[10];
        static constexpr std::array<const char*, 10> kNames{"x", "y", "z", "a", "b", "c", "qw", "qx", "qy", "qz"};
        for (std::size_t k = 0; k < 10; ++k) v[k] = cell_number(f[k], path, at + " " + kNames[k]);
        packing.centres.emplace_back(v[0], v[1], v[2]);
        packing.semi_axes.emplace_back(v[3], v[4], v[5]);
        packing.orientations.emplace_back(v[6], v[7], v[8], v[9]);
      },
      comment);
  if (!has_lower || !has_upper)
    throw InputError(path, has_lower ? "box_upper" : "box_lower", "missing",
                     "a '# box_lower = x y z' and a '# box_upper = x y z' line");
  const std::string contacts_path = contacts_file_for(path);
  if (std::filesystem::exists(contacts_path)) {
    std::ifstream contacts(contacts_path);
    read_rows(
        contacts, contacts_path,
        {"i", "j", "px", "py", "pz", "jx", "jy", "jz", "normal_force", "max_overlap", "regime"},
        [&](const std::vector<std::string>& f, int line) {
          const std::string at = "line " + std::to_string(line);
          double v[11];
          for (std::size_t k = 0; k < 11; ++k) v[k] = cell_number(f[k], contacts_path, at);
          for (const int k : {0, 1})
            if (!(v[k] >= 0.0 && v[k] < 4.0e9 && v[k] == std::floor(v[k])))
              throw InputError(contacts_path, at + (k == 0 ? " i" : " j"), f[static_cast<std::size_t>(k)],
                               "a particle row, an integer >= 0");
          ContactRecord record;
          record.i = static_cast<std::uint32_t>(v[0]);
          record.j = static_cast<std::uint32_t>(v[1]);
          record.point = {v[2], v[3], v[4]};
          record.centre_j = {v[5], v[6], v[7]};
          record.normal_force = v[8];
          record.max_overlap = v[9];
          record.regime = static_cast<int>(v[10]);
          packing.contacts.push_back(record);
        },
        [](const std::string&) {});
  }
  validate_packing(packing, path);
  return packing;
}

void write_packing_file(const std::string& path, const Packing& packing) {
  const auto write = [](const std::string& file, const std::function<void(std::ostream&)>& body) {
    std::ofstream out(file);
    if (!out) throw InputError(file, "file", file, "a writable path");
    out.precision(17);
    body(out);
  };
  write(path, [&](std::ostream& out) {
    const auto flag = [](bool b) { return b ? "true" : "false"; };
    out << "# ellc packing (docs/microstructure.md, \"Packing files\")\n"
        << "# box_lower = " << packing.box.lower.x() << ' ' << packing.box.lower.y() << ' ' << packing.box.lower.z()
        << "\n# box_upper = " << packing.box.upper.x() << ' ' << packing.box.upper.y() << ' ' << packing.box.upper.z()
        << "\n# periodic = " << flag(packing.box.periodic[0]) << ' ' << flag(packing.box.periodic[1]) << ' '
        << flag(packing.box.periodic[2]) << "\nx,y,z,a,b,c,qw,qx,qy,qz\n";
    for (std::size_t k = 0; k < packing.size(); ++k) {
      const auto& c = packing.centres[k];
      const auto& s = packing.semi_axes[k];
      const auto& q = packing.orientations[k];
      out << c.x() << ',' << c.y() << ',' << c.z() << ',' << s.x() << ',' << s.y() << ',' << s.z() << ',' << q.w()
          << ',' << q.x() << ',' << q.y() << ',' << q.z() << '\n';
    }
  });
  const std::string contacts_path = contacts_file_for(path);
  if (packing.contacts.empty()) {
    std::error_code ignored;
    std::filesystem::remove(contacts_path, ignored);
    return;
  }
  write(contacts_path, [&](std::ostream& out) {
    out << "i,j,px,py,pz,jx,jy,jz,normal_force,max_overlap,regime\n";
    for (const ContactRecord& c : packing.contacts)
      out << c.i << ',' << c.j << ',' << c.point.x() << ',' << c.point.y() << ',' << c.point.z() << ','
          << c.centre_j.x() << ',' << c.centre_j.y() << ',' << c.centre_j.z() << ',' << c.normal_force << ','
          << c.max_overlap << ',' << c.regime << '\n';
  });
}

}  // namespace ellc::microstructure
