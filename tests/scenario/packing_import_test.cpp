// The packing import ([packing] file): CSV and LAMMPS data files give exactly the particles they
// describe (ids in file order, masses from the scenario's density, x and y wrapped into the box),
// the generated packing survives the data-file form unchanged, and bad files are refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "ellc/engine/particles.hpp"
#include "ellc/scenario/packing.hpp"
#include "ellc/scenario/packing_import.hpp"
#include "ellc/scenario/scenario.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("ellc_packing_import_" + name);
  std::ofstream(path) << text;
  return path.string();
}

const engine::Box kBox{30.0, 20.0};

TEST(PackingImport, CsvGivesTheParticlesItDescribes) {
  const std::string path = write_file("ok.csv",
                                      "# two bodies\n"
                                      "id,qw,qx,qy,qz,x,y,z,a,b,c\n"
                                      "7,1,0,0,0,  5.0, 3.0, 6.0, 4.0, 3.0, 2.0\n"
                                      "\n"
                                      "8,0.6,0.8,0,0, 33.0, -1.0, 10.0, 2.0, 2.0, 2.0\n");
  const engine::ParticleSet particles = import_packing(path, 2.0, kBox);
  ASSERT_EQ(particles.size(), 2U);
  EXPECT_EQ(particles.id[0], 0U);
  EXPECT_EQ(particles.id[1], 1U);
  EXPECT_EQ(particles.position[0], Eigen::Vector3d(5.0, 3.0, 6.0));
  EXPECT_EQ(particles.semi_axes[0], Eigen::Vector3d(4.0, 3.0, 2.0));
  EXPECT_DOUBLE_EQ(particles.mass[0], 2.0 * 4.0 / 3.0 * std::numbers::pi * 24.0);
  // Wrapped into [0, 30) x [0, 20): 33 → 3, −1 → 19.
  EXPECT_NEAR(particles.position[1].x(), 3.0, 1e-12);
  EXPECT_NEAR(particles.position[1].y(), 19.0, 1e-12);
  EXPECT_NEAR(particles.orientation[1].w(), 0.6, 1e-15);
  EXPECT_NEAR(particles.orientation[1].x(), 0.8, 1e-15);
}

// Several species: atom type t is species t − 1, of its density; a type beyond them is refused.
TEST(PackingImport, DataFileTypesAreTheSpecies) {
  const std::string text =
      "title\n\n2 atoms\n2 atom types\n2 ellipsoids\n\n0 30 xlo xhi\n0 20 ylo yhi\n-8 40 zlo zhi\n\n"
      "Atoms # ellipsoid\n\n1 2 1 4.7 5.0 5.0 9.0\n2 1 1 4.7 15.0 5.0 9.0\n\n"
      "Ellipsoids\n\n1 4.0 4.0 4.0 1 0 0 0\n2 4.0 4.0 4.0 1 0 0 0\n";
  const engine::ParticleSet particles = import_packing(write_file("types.data", text), {1.0, 3.0}, kBox);
  ASSERT_EQ(particles.size(), 2U);
  EXPECT_EQ(particles.species, (std::vector<std::uint16_t>{1, 0}));
  EXPECT_DOUBLE_EQ(particles.mass[0], 3.0 * 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_DOUBLE_EQ(particles.mass[1], 1.0 * 4.0 / 3.0 * std::numbers::pi * 8.0);
  // One species: the types are not used (every particle species 0).
  EXPECT_EQ(import_packing(write_file("types1.data", text), 1.0, kBox).species, (std::vector<std::uint16_t>{0, 0}));
  std::string bad = text;
  bad.replace(bad.find("1 2 1 4.7"), 9, "1 3 1 4.7");
  const std::string message = test::input_error_message([&] {
    (void)import_packing(write_file("types3.data", bad), {1.0, 3.0}, kBox);
  });
  EXPECT_NE(message.find("atom type = 3"), std::string::npos) << message;
}

TEST(PackingImport, DataFileGivesTheParticlesItDescribes) {
  // Atom IDs out of order, an x/y box starting at −10 and image flags, shapes as diameters.
  const std::string path = write_file("ok.data",
                                      "title\n\n2 atoms\n1 atom types\n2 ellipsoids\n\n"
                                      "-10 20 xlo xhi\n-5 15 ylo yhi\n-8 40 zlo zhi\n\n"
                                      "Atoms # ellipsoid\n\n"
                                      "5 1 1 4.7 0.0 0.0 9.0 1 0 0\n"
                                      "2 1 1 4.7 -9.0 14.0 5.0\n\n"
                                      "Ellipsoids\n\n"
                                      "2 8.0 6.0 4.0 1 0 0 0\n"
                                      "5 4.0 4.0 4.0 0 0 0 1\n");
  const engine::ParticleSet particles = import_packing(path, 1.0, kBox);
  ASSERT_EQ(particles.size(), 2U);
  // ID 2 first: x −9 − (−10) = 1, y 14 − (−5) = 19.
  EXPECT_NEAR(particles.position[0].x(), 1.0, 1e-12);
  EXPECT_NEAR(particles.position[0].y(), 19.0, 1e-12);
  EXPECT_EQ(particles.semi_axes[0], Eigen::Vector3d(4.0, 3.0, 2.0));
  // ID 5: x 0 + 1 image (30) − (−10) = 40 → 10.
  EXPECT_NEAR(particles.position[1].x(), 10.0, 1e-12);
  EXPECT_NEAR(particles.orientation[1].z(), 1.0, 1e-15);
}

TEST(PackingImport, GeneratedPackingSurvivesTheDataFileForm) {
  PackingSpec spec;
  spec.count = 40;
  spec.mean_radius = 2.0;
  spec.radius_spread = 0.1;
  spec.seed = 11;
  spec.density = 3.0;
  const engine::ParticleSet generated = generate_packing(spec, kBox, 0.0, ellipsoid_overlap_test());
  std::string text = "written like ellc export-lammps\n\n" + std::to_string(generated.size()) +
                     " atoms\n1 atom types\n\n0 30 xlo xhi\n0 20 ylo yhi\n-8 80 zlo zhi\n\nAtoms # ellipsoid\n\n";
  char line[512];
  for (std::size_t k = 0; k < generated.size(); ++k) {
    const auto& x = generated.position[k];
    std::snprintf(line, sizeof line, "%u 1 1 3.0 %.17g %.17g %.17g\n", generated.id[k] + 1, x.x(), x.y(), x.z());
    text += line;
  }
  text += "\nEllipsoids\n\n";
  for (std::size_t k = 0; k < generated.size(); ++k) {
    const auto& a = generated.semi_axes[k];
    const auto& q = generated.orientation[k];
    std::snprintf(line, sizeof line, "%u %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", generated.id[k] + 1, 2 * a.x(),
                  2 * a.y(), 2 * a.z(), q.w(), q.x(), q.y(), q.z());
    text += line;
  }
  const engine::ParticleSet imported = import_packing(write_file("generated.data", text), spec.density, kBox);
  ASSERT_EQ(imported.size(), generated.size());
  for (std::size_t k = 0; k < generated.size(); ++k) {
    EXPECT_EQ(imported.position[k], generated.position[k]) << k;
    EXPECT_EQ(imported.semi_axes[k], generated.semi_axes[k]) << k;
    EXPECT_NEAR(imported.orientation[k].angularDistance(generated.orientation[k]), 0.0, 1e-14) << k;
    EXPECT_DOUBLE_EQ(imported.mass[k], generated.mass[k]) << k;
  }
}

TEST(PackingImport, BadFilesAreRefusedByName) {
  const auto message = [](const std::string& name, const std::string& text) {
    return test::input_error_message([&] { (void)import_packing(write_file(name, text), 1.0, kBox); });
  };
  {
    const std::string m = message("nocol.csv", "x,y,z,a,b,c,qw,qx,qy\n1,1,5,1,1,1,1,0,0\n");
    EXPECT_NE(m.find("line 1: header"), std::string::npos) << m;
    EXPECT_NE(m.find("qz"), std::string::npos) << m;
  }
  EXPECT_NE(message("quat.csv", "x,y,z,a,b,c,qw,qx,qy,qz\n1,1,5,1,1,1,1,1,0,0\n").find("line 2: quaternion"),
            std::string::npos);
  EXPECT_NE(message("floor.csv", "x,y,z,a,b,c,qw,qx,qy,qz\n1,1,0.5,1,1,1,1,0,0,0\n").find("line 2: z"),
            std::string::npos);
  EXPECT_NE(message("axis.csv", "x,y,z,a,b,c,qw,qx,qy,qz\n1,1,5,1,-1,1,1,0,0,0\n").find("line 2: semi-axis 2"),
            std::string::npos);
  EXPECT_NE(message("word.csv", "x,y,z,a,b,c,qw,qx,qy,qz\n1,one,5,1,1,1,1,0,0,0\n").find("line 2: y = 'one'"),
            std::string::npos);
  const std::string header = "t\n\n1 atoms\n\n0 30 xlo xhi\n0 20 ylo yhi\n0 9 zlo zhi\n\n";
  EXPECT_NE(
      message("box.data", "t\n\n1 atoms\n\n0 31 xlo xhi\n0 20 ylo yhi\n\nAtoms\n\n1 1 1 1 1 1 5\n").find("box.size"),
      std::string::npos);
  EXPECT_NE(message("noshape.data", header + "Atoms # ellipsoid\n\n1 1 1 1 1 1 5\n").find("Ellipsoids section"),
            std::string::npos);
  EXPECT_NE(message("style.data", header + "Atoms # sphere\n\n1 1 1 1 1 1 5\n").find("atom_style ellipsoid"),
            std::string::npos);
}

TEST(PackingImport, ScenarioReadsThePackingFile) {
  const std::string csv =
      write_file("scenario.csv", "x,y,z,a,b,c,qw,qx,qy,qz\n5,5,6,4,3,2,1,0,0,0\n9,9,9,2,2,2,1,0,0,0\n");
  const std::string toml =
      "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n"
      "[box]\nsize = [30.0, 20.0]\n[packing]\nfile = \"" +
      csv +
      "\"\ndensity = 4.7e-3\n"
      "[calendering]\nspeed = 0.1\ntarget_pressure = 100.0\n";
  const Scenario scenario = parse_scenario(toml, "import.toml");
  EXPECT_EQ(scenario.packing.count, 2U);
  EXPECT_NEAR(scenario.packing.mean_radius, 0.5 * (std::cbrt(24.0) + 2.0), 1e-12);
  EXPECT_EQ(largest_bounding_radius(scenario.packing), 4.0);
  const engine::ParticleSet particles = generate_packing(scenario.packing, scenario.box, 0.0);
  ASSERT_EQ(particles.size(), 2U);
  EXPECT_DOUBLE_EQ(particles.mass[1], 4.7e-3 * 4.0 / 3.0 * std::numbers::pi * 8.0);
  // The generator's keys do not go with a file.
  const std::string both = test::input_error_message([&] {
    (void)parse_scenario(
        "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n"
        "[box]\nsize = [30.0, 20.0]\n[packing]\nfile = \"" +
            csv +
            "\"\ndensity = 4.7e-3\ncount = 5\n"
            "[calendering]\nspeed = 0.1\ntarget_pressure = 100.0\n",
        "import.toml");
  });
  EXPECT_NE(both.find("count"), std::string::npos) << both;
}

// A relative [packing] file is found next to the scenario, also when an --set entry (here the file
// itself, a path with a '/') is part of the scenario's description.
TEST(PackingImport, RelativeFileIsResolvedAgainstTheScenarioFileDespiteOverrides) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "ellc_packing_import_relative";
  std::filesystem::create_directories(folder / "sub");
  std::ofstream(folder / "sub" / "two.csv") << "x,y,z,a,b,c,qw,qx,qy,qz\n5,5,6,4,3,2,1,0,0,0\n9,9,9,2,2,2,1,0,0,0\n";
  std::ofstream(folder / "one.csv") << "x,y,z,a,b,c,qw,qx,qy,qz\n5,5,6,2,2,2,1,0,0,0\n";
  const std::string toml =
      "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n"
      "[box]\nsize = [30.0, 20.0]\n[packing]\nfile = \"one.csv\"\ndensity = 4.7e-3\n"
      "[calendering]\nspeed = 0.1\ntarget_pressure = 100.0\n";
  const std::string path = (folder / "import.toml").string();
  EXPECT_EQ(parse_scenario(toml, path).packing.file, (folder / "one.csv").string());
  const Scenario changed = parse_scenario(toml, path, {"packing.file=\"sub/two.csv\""});
  EXPECT_EQ(changed.packing.file, (folder / "sub" / "two.csv").string());
  EXPECT_EQ(changed.packing.count, 2U);
  EXPECT_EQ(changed.path, path);
  EXPECT_NE(changed.source.find("--set packing.file=\"sub/two.csv\""), std::string::npos) << changed.source;
}

}  // namespace
}  // namespace ellc::scenario
