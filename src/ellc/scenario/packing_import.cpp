#include "ellc/scenario/packing_import.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

namespace {

struct Body {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axes = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  bool has_centre = false;
  bool has_shape = false;
};

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> words;
  if (separator == ' ') {
    std::istringstream stream(line);
    for (std::string word; stream >> word;) words.push_back(word);
    return words;
  }
  std::string word;
  std::istringstream stream(line);
  while (std::getline(stream, word, separator)) {
    word.erase(0, word.find_first_not_of(" \t\r"));
    word.erase(word.find_last_not_of(" \t\r") + 1);
    words.push_back(word);
  }
  return words;
}

std::string field(long line, const std::string& name) { return "line " + std::to_string(line) + ": " + name; }

double to_number(const std::string& path, long line, const std::string& name, const std::string& word) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != word.size() || !std::isfinite(value))
    throw InputError(path, field(line, name), "'" + word + "'", "a finite number");
  return value;
}

// The body's checks and its place in the box.
void finish(const std::string& path, long line, Body& body, const engine::Box& box) {
  for (int k = 0; k < 3; ++k)
    if (!(body.axes[k] > 0.0))
      throw InputError(path, field(line, "semi-axis " + std::to_string(k + 1)), format_number(body.axes[k]),
                       "a semi-axis > 0 µm");
  const double norm = body.rotation.norm();
  if (std::abs(norm - 1.0) > 1e-6)
    throw InputError(path, field(line, "quaternion"), "of norm " + format_number(norm),
                     "a unit quaternion (norm 1 to 1e-6)");
  // A file written with 17 digits carries unit quaternions exactly: leave them bit for bit.
  if (norm != 1.0) body.rotation.normalize();
  body.centre.x() -= box.lx * std::floor(body.centre.x() / box.lx);
  body.centre.y() -= box.ly * std::floor(body.centre.y() / box.ly);
  const double bottom = body.centre.z() - body.axes.maxCoeff();
  if (bottom < 0.0)
    throw InputError(path, field(line, "z"), format_number(body.centre.z()),
                     "a particle above the floor z = 0 (its centre at least its largest semi-axis, " +
                         format_number(body.axes.maxCoeff()) + " µm, up)");
}

engine::ParticleSet read_csv(const std::string& path, std::istream& in, double density, const engine::Box& box) {
  static const char* const kColumns[] = {"x", "y", "z", "a", "b", "c", "qw", "qx", "qy", "qz"};
  std::map<std::string, std::size_t> column;
  std::size_t width = 0;
  engine::ParticleSet particles;
  long line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const std::vector<std::string> words = split(line, ',');
    if (column.empty()) {  // the header
      for (std::size_t k = 0; k < words.size(); ++k) {
        const bool known =
            words[k] == "id" || std::find_if(std::begin(kColumns), std::end(kColumns),
                                             [&](const char* name) { return words[k] == name; }) != std::end(kColumns);
        if (!known)
          throw InputError(path, field(line_number, "column " + std::to_string(k + 1)), "'" + words[k] + "'",
                           "one of x, y, z, a, b, c, qw, qx, qy, qz, id");
        column[words[k]] = k;
      }
      for (const char* name : kColumns)
        if (column.count(name) == 0)
          throw InputError(path, field(line_number, "header"), "without column " + std::string(name),
                           "the columns x, y, z, a, b, c, qw, qx, qy, qz");
      width = words.size();
      continue;
    }
    if (words.size() != width)
      throw InputError(path, field(line_number, "row"), std::to_string(words.size()) + " values",
                       std::to_string(width) + " values, as the header");
    const auto value = [&](const char* name) { return to_number(path, line_number, name, words[column[name]]); };
    Body body;
    body.centre = {value("x"), value("y"), value("z")};
    body.axes = {value("a"), value("b"), value("c")};
    body.rotation = Eigen::Quaterniond(value("qw"), value("qx"), value("qy"), value("qz"));
    finish(path, line_number, body, box);
    particles.add(static_cast<std::uint32_t>(particles.size()), body.axes, density, body.centre, body.rotation);
  }
  if (column.empty()) throw InputError(path, "header", "missing", "a CSV header x, y, z, a, b, c, qw, qx, qy, qz");
  return particles;
}

// densities: one per species; with several, atom type t is species t − 1 (one: types are not used).
engine::ParticleSet read_data(const std::string& path, std::istream& in, const std::vector<double>& densities,
                              const engine::Box& box) {
  std::map<long, long> type_of;  // atom ID → its type
  long atoms = -1;
  std::optional<double> xlo, xhi, ylo, yhi;
  std::map<long, Body> bodies;
  std::map<long, long> line_of;  // atom ID → its Atoms line, for messages
  std::string section;
  long line_number = 0;
  bool first = true;
  for (std::string raw; std::getline(in, raw);) {
    ++line_number;
    if (first) {  // the title line
      first = false;
      continue;
    }
    const std::string style = raw.find('#') != std::string::npos ? raw.substr(raw.find('#') + 1) : std::string();
    const std::string line = raw.substr(0, raw.find('#'));
    const std::vector<std::string> words = split(line, ' ');
    if (words.empty()) continue;
    const bool numeric = words[0].find_first_not_of("+-.0123456789eE") == std::string::npos;
    if (!numeric) {  // a section keyword
      section = words[0];
      if (section == "Atoms") {
        const std::vector<std::string> styles = split(style, ' ');
        if (!styles.empty() && styles[0] != "ellipsoid")
          throw InputError(path, field(line_number, "Atoms"), "# " + styles[0], "atom_style ellipsoid");
      }
      continue;
    }
    if (section.empty()) {  // the header
      if (words.size() == 2 && words[1] == "atoms")
        atoms = std::lround(to_number(path, line_number, "atoms", words[0]));
      if (words.size() == 4 && words[2] == "xlo") {
        xlo = to_number(path, line_number, "xlo", words[0]);
        xhi = to_number(path, line_number, "xhi", words[1]);
      }
      if (words.size() == 4 && words[2] == "ylo") {
        ylo = to_number(path, line_number, "ylo", words[0]);
        yhi = to_number(path, line_number, "yhi", words[1]);
      }
      if (words.size() == 6 && words[3] == "xy")
        throw InputError(path, field(line_number, "xy xz yz"), "a triclinic box", "an orthogonal box");
      continue;
    }
    if (section == "Atoms") {
      if (words.size() != 7 && words.size() != 10)
        throw InputError(path, field(line_number, "Atoms"), std::to_string(words.size()) + " values",
                         "id type ellipsoidflag density x y z [ix iy iz] (atom_style ellipsoid)");
      const long id = std::lround(to_number(path, line_number, "atom ID", words[0]));
      Body& body = bodies[id];
      body.centre = {to_number(path, line_number, "x", words[4]), to_number(path, line_number, "y", words[5]),
                     to_number(path, line_number, "z", words[6])};
      if (words.size() == 10 && xlo && xhi && ylo && yhi)  // image flags: unwrap, then wrap into the box below
        body.centre += Eigen::Vector3d(to_number(path, line_number, "ix", words[7]) * (*xhi - *xlo),
                                       to_number(path, line_number, "iy", words[8]) * (*yhi - *ylo), 0.0);
      body.has_centre = true;
      line_of[id] = line_number;
      const double type = to_number(path, line_number, "atom type", words[1]);
      if (densities.size() > 1 &&
          !(type >= 1.0 && type <= static_cast<double>(densities.size()) && type == std::round(type)))
        throw InputError(path, field(line_number, "atom type"), words[1],
                         "an atom type in 1.." + std::to_string(densities.size()) +
                             ": the scenario's [[species]] in their order (type 1 = species[0])");
      type_of[id] = std::lround(type);
      if (to_number(path, line_number, "ellipsoidflag", words[2]) != 1.0)
        throw InputError(path, field(line_number, "ellipsoidflag"), words[2],
                         "1: every particle an ellipsoid with a line in the Ellipsoids section");
    } else if (section == "Ellipsoids") {
      if (words.size() != 8)
        throw InputError(path, field(line_number, "Ellipsoids"), std::to_string(words.size()) + " values",
                         "id shapex shapey shapez quatw quati quatj quatk");
      const long id = std::lround(to_number(path, line_number, "atom ID", words[0]));
      Body& body = bodies[id];
      body.axes = 0.5 * Eigen::Vector3d(to_number(path, line_number, "shapex", words[1]),
                                        to_number(path, line_number, "shapey", words[2]),
                                        to_number(path, line_number, "shapez", words[3]));
      body.rotation = Eigen::Quaterniond(
          to_number(path, line_number, "quatw", words[4]), to_number(path, line_number, "quati", words[5]),
          to_number(path, line_number, "quatj", words[6]), to_number(path, line_number, "quatk", words[7]));
      body.has_shape = true;
    }
  }
  if (!xlo || !xhi || !ylo || !yhi)
    throw InputError(path, "xlo xhi / ylo yhi", "missing", "the box bounds of the header");
  const double lx = *xhi - *xlo, ly = *yhi - *ylo;
  if (std::abs(lx - box.lx) > 1e-9 * box.lx || std::abs(ly - box.ly) > 1e-9 * box.ly)
    throw InputError(path, "xhi - xlo, yhi - ylo", format_number(lx) + " x " + format_number(ly) + " µm",
                     "the scenario's box.size " + format_number(box.lx) + " x " + format_number(box.ly) + " µm");
  if (atoms >= 0 && static_cast<long>(bodies.size()) != atoms)
    throw InputError(path, "atoms", std::to_string(atoms) + " in the header",
                     "as many as the Atoms and Ellipsoids sections hold (" + std::to_string(bodies.size()) + ")");
  if (bodies.empty()) throw InputError(path, "Atoms", "no particles", "at least one atom");
  engine::ParticleSet particles;
  for (auto& [id, body] : bodies) {
    const long line = line_of.count(id) ? line_of[id] : 0;
    if (!body.has_centre)
      throw InputError(path, "atom " + std::to_string(id), "only in Ellipsoids", "a line in the Atoms section too");
    if (!body.has_shape)
      throw InputError(path, field(line, "atom " + std::to_string(id)), "without a shape",
                       "a line in the Ellipsoids section (every particle an ellipsoid)");
    body.centre.x() -= *xlo;
    body.centre.y() -= *ylo;
    finish(path, line, body, box);
    const auto species = static_cast<std::uint16_t>(densities.size() > 1 ? type_of[id] - 1 : 0);
    particles.add(static_cast<std::uint32_t>(particles.size()), body.axes, densities[species], body.centre,
                  body.rotation, species);
  }
  return particles;
}

}  // namespace

engine::ParticleSet import_packing(const std::string& path, double density, const engine::Box& box) {
  return import_packing(path, std::vector<double>{density}, box);
}

engine::ParticleSet import_packing(const std::string& path, const std::vector<double>& species_densities,
                                   const engine::Box& box) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the packing file for reading");
  const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  if (csv && species_densities.size() > 1)
    throw InputError(path,
                     "a CSV packing with several [[species]]: expected a LAMMPS data file, whose atom types are "
                     "the species");
  return csv ? read_csv(path, in, species_densities.front(), box) : read_data(path, in, species_densities, box);
}

}  // namespace ellc::scenario
