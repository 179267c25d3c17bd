// --set KEY=VALUE on a parsed TOML table (io/toml_overrides.hpp): what it changes, what it leaves,
// and that every malformed entry is refused with a message naming the option and the entry.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ellc/io/input_error.hpp"
#include "ellc/io/toml_overrides.hpp"

namespace ellc {
namespace {

toml::table sample() {
  return toml::parse(R"(
[calendering]
speed = 0.05
approach_speed = 0.2
[packing]
seed = 2026
speed = 7.0
[walls.material]
poisson_ratio = 0.3
[[species]]
fraction = 1.0
)");
}

std::string error_of(const std::vector<std::string>& overrides) {
  toml::table root = sample();
  try {
    apply_toml_overrides(root, overrides);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(TomlOverrides, ReplacesExactlyTheNamedEntry) {
  toml::table root = sample();
  apply_toml_overrides(root, {"calendering.speed=0.025", "packing.seed = 2027", "walls.material.poisson_ratio=0.25"});
  EXPECT_EQ(root["calendering"]["speed"].value<double>(), 0.025);
  EXPECT_EQ(root["packing"]["speed"].value<double>(), 7.0) << "a key of the same name in another table changed";
  EXPECT_EQ(root["calendering"]["approach_speed"].value<double>(), 0.2);
  EXPECT_EQ(root["packing"]["seed"].value<std::int64_t>(), 2027);
  EXPECT_EQ(root["walls"]["material"]["poisson_ratio"].value<double>(), 0.25);
}

TEST(TomlOverrides, ValuesAreTomlOfAnyType) {
  toml::table root = sample();
  apply_toml_overrides(
      root, {R"(calendering.hold="servo")", "box.size=[100, 80.5]", "output.vtk=false", "calendering.speed=1e-2"});
  EXPECT_EQ(root["calendering"]["hold"].value<std::string>(), "servo");
  ASSERT_NE(root["box"]["size"].as_array(), nullptr) << "a missing table on the path is created";
  EXPECT_EQ(root["box"]["size"][1].value<double>(), 80.5);
  EXPECT_EQ(root["output"]["vtk"].value<bool>(), false);
  EXPECT_EQ(root["calendering"]["speed"].value<double>(), 0.01);
}

TEST(TomlOverrides, LaterEntriesWin) {
  toml::table root = sample();
  apply_toml_overrides(root, {"packing.seed=1", "packing.seed=2"});
  EXPECT_EQ(root["packing"]["seed"].value<std::int64_t>(), 2);
}

TEST(TomlOverrides, MalformedEntriesNameTheOptionAndTheEntry) {
  for (const std::string entry : {"calendering.speed", "=0.1", "calendering..speed=1", "calendering.sp eed=1",
                                  "calendering.speed=", "calendering.speed=fast", "calendering.speed=1\nx = 2"}) {
    const std::string message = error_of({entry});
    EXPECT_NE(message.find("--set " + entry), std::string::npos) << entry << " -> " << message;
    EXPECT_NE(message.find("expected"), std::string::npos) << message;
  }
}

TEST(TomlOverrides, APathThroughSomethingNotATableIsRefused) {
  EXPECT_NE(error_of({"calendering.speed.x=1"}).find("calendering.speed is not a table"), std::string::npos);
  EXPECT_NE(error_of({"species.fraction=0.5"}).find("species is not a table"), std::string::npos);
}

TEST(TomlOverrides, DescribeListsTheOverridesAfterTheSource) {
  EXPECT_EQ(describe_overrides("a.toml", {}), "a.toml");
  EXPECT_EQ(describe_overrides("a.toml", {"x.y=1", "z.w=\"s\""}), "a.toml --set x.y=1 --set z.w=\"s\"");
}

}  // namespace
}  // namespace ellc
