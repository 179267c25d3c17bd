// Packing files: a round trip keeps every number, and bad rows are refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "ellc/microstructure/packing.hpp"
#include "microstructure/microstructure_support.hpp"
#include "support/input_error.hpp"

namespace ellc::microstructure {
namespace {

std::string temporary(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("ellc_micro_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(PackingFile, RoundTripKeepsParticlesBoxAndContacts) {
  Packing packing = test::random_ellipsoids(5, 20.0, 3);
  packing.box.periodic = {true, false, true};
  ContactRecord contact;
  contact.i = 1;
  contact.j = 3;
  contact.point = {1.5, 2.5, 3.5};
  contact.centre_j = {4.0, 5.0, 6.0};
  contact.normal_force = 12.25;
  contact.max_overlap = 0.125;
  contact.regime = 3;
  packing.contacts.push_back(contact);
  const std::string path = temporary("roundtrip.csv");
  write_packing_file(path, packing);
  const Packing read = read_packing_file(path);
  ASSERT_EQ(read.size(), packing.size());
  for (std::size_t k = 0; k < packing.size(); ++k) {
    EXPECT_EQ(read.centres[k], packing.centres[k]);
    EXPECT_EQ(read.semi_axes[k], packing.semi_axes[k]);
    EXPECT_EQ(read.orientations[k].coeffs(), packing.orientations[k].coeffs());
  }
  EXPECT_EQ(read.box.upper, packing.box.upper);
  EXPECT_EQ(read.box.periodic, packing.box.periodic);
  ASSERT_EQ(read.contacts.size(), 1U);
  EXPECT_EQ(read.contacts[0].j, 3U);
  EXPECT_EQ(read.contacts[0].normal_force, 12.25);
  EXPECT_EQ(read.contacts[0].regime, 3);
  std::filesystem::remove(path);
  std::filesystem::remove(contacts_file_for(path));
}

TEST(PackingFile, NanOrNegativeSemiAxisIsRefusedNamingTheRow) {
  const std::string path = temporary("bad.csv");
  for (const char* bad : {"nan", "-2"}) {
    std::ofstream(path) << "# box_lower = 0 0 0\n# box_upper = 10 10 10\n# periodic = true true false\n"
                        << "x,y,z,a,b,c,qw,qx,qy,qz\n"
                        << "1,1,1,1,1,1,1,0,0,0\n"
                        << "5,5,5,1," << bad << ",1,1,0,0,0\n";
    const std::string message = test::input_error_message([&] { (void)read_packing_file(path); });
    EXPECT_NE(message.find("row 2 semi-axis b"), std::string::npos) << message;
    EXPECT_NE(message.find(bad), std::string::npos) << message;
    EXPECT_NE(message.find("> 0"), std::string::npos) << message;
  }
  std::filesystem::remove(path);
}

TEST(PackingFile, MissingBoxAndBadHeaderAreRefused) {
  const std::string path = temporary("nobox.csv");
  std::ofstream(path) << "x,y,z,a,b,c,qw,qx,qy,qz\n1,1,1,1,1,1,1,0,0,0\n";
  EXPECT_NE(test::input_error_message([&] { (void)read_packing_file(path); }).find("box_lower"), std::string::npos);
  std::ofstream(path) << "# box_lower = 0 0 0\n# box_upper = 1 1 1\nx,y,z,a,b,c\n";
  EXPECT_NE(test::input_error_message([&] { (void)read_packing_file(path); }).find("header"), std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ellc::microstructure
