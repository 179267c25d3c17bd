// Voxelisation: the column solve marks exactly the voxels whose centres pass the inside test;
// periodic images wrap; the solid fraction converges to the analytic volume fraction; bad
// resolutions are refused with the estimate.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/microstructure/voxel_grid.hpp"
#include "microstructure/microstructure_support.hpp"
#include "support/input_error.hpp"

namespace ellc::microstructure {
namespace {

TEST(Voxelise, EveryVoxelAgreesWithTheExactInsideTest) {
  const Packing packing = test::random_ellipsoids(6, 12.0, 11);
  Resolution resolution;
  resolution.spacing = 0.3;
  const VoxelGrid grid = voxelise(packing, resolution);
  std::size_t disagreements = 0;
  for (int iz = 0; iz < grid.shape[2]; ++iz)
    for (int iy = 0; iy < grid.shape[1]; ++iy)
      for (int ix = 0; ix < grid.shape[0]; ++ix) {
        const Eigen::Vector3d centre =
            grid.origin + (Eigen::Vector3d(ix, iy, iz).array() + 0.5).matrix().cwiseProduct(grid.spacing);
        bool inside = false;
        bool on_surface = false;  // to rounding: either answer is exact
        for (std::size_t p = 0; p < packing.size() && !inside && !on_surface; ++p) {
          const Ellipsoid body(packing.semi_axes[p], Pose{packing.centres[p], packing.orientations[p]});
          // The nearest periodic image of the centre.
          Eigen::Vector3d d = centre - packing.centres[p];
          for (int a = 0; a < 3; ++a) d[a] -= 12.0 * std::round(d[a] / 12.0);
          const double value = body.implicit_value(packing.centres[p] + d);
          on_surface = std::abs(value) < 1e-9;
          inside = value < 0.0;
        }
        if (!on_surface) disagreements += (grid.solid[grid.index(ix, iy, iz)] != 0) != inside ? 1U : 0U;
      }
  EXPECT_EQ(disagreements, 0U);
}

TEST(Voxelise, PeriodicImagesWrap) {
  // A sphere across the corner of a periodic box fills as many voxels as one in the middle,
  // shifted by a whole number of voxels.
  const double length = 10.0;
  Resolution resolution;
  resolution.spacing = 0.25;
  const VoxelGrid middle = voxelise(test::one_sphere(2.0, {5.1, 5.1, 5.1}, length), resolution);
  const VoxelGrid corner = voxelise(test::one_sphere(2.0, {0.1, 0.1, 0.1}, length), resolution);
  EXPECT_EQ(middle.solid_fraction(), corner.solid_fraction());
  for (int iz = 0; iz < middle.shape[2]; ++iz)
    for (int iy = 0; iy < middle.shape[1]; ++iy)
      for (int ix = 0; ix < middle.shape[0]; ++ix)
        ASSERT_EQ(middle.solid[middle.index(ix, iy, iz)],
                  corner.solid[corner.index((ix + 20) % 40, (iy + 20) % 40, (iz + 20) % 40)]);
  // Without periodicity the part outside the box is cut off: of a sphere centred on a voxel
  // corner, exactly one eighth of the voxels stays.
  const VoxelGrid cut = voxelise(test::one_sphere(2.0, {0.0, 0.0, 0.0}, length, false), resolution);
  const VoxelGrid whole = voxelise(test::one_sphere(2.0, {5.0, 5.0, 5.0}, length, false), resolution);
  EXPECT_NEAR(cut.solid_fraction() * 8.0, whole.solid_fraction(), 1e-15);
  EXPECT_GT(cut.solid_fraction(), 0.0);
}

TEST(Voxelise, SolidFractionConvergesToTheVolumeFraction) {
  const Packing packing = test::random_ellipsoids(12, 16.0, 5);
  const double exact = packing.particle_volume() / packing.box.volume();
  double previous_error = 1.0;
  for (const double voxels : {2.0, 4.0, 8.0, 16.0}) {
    Resolution resolution;
    resolution.voxels_per_semi_axis = voxels;
    const double error = std::abs(voxelise(packing, resolution).solid_fraction() - exact);
    EXPECT_LT(error, 0.6 * previous_error + 1e-4) << voxels << " voxels per smallest semi-axis";
    previous_error = error;
  }
  EXPECT_LT(previous_error / exact, 2e-3);
}

TEST(Voxelise, BadResolutionsAreRefusedWithTheEstimate) {
  const Packing packing = test::one_sphere(1.0, {5.0, 5.0, 5.0}, 10.0);
  Resolution resolution;
  resolution.spacing = -0.5;
  EXPECT_NE(test::input_error_message([&] { (void)voxelise(packing, resolution); }).find("-0.5"), std::string::npos);
  resolution.spacing = 0.0;
  resolution.voxels_per_semi_axis = 0.0;
  EXPECT_NE(test::input_error_message([&] { (void)voxelise(packing, resolution); }).find("voxels_per_semi_axis"),
            std::string::npos);
  resolution.spacing = 0.001;  // 10^12 voxels
  const std::string message = test::input_error_message([&] { (void)voxelise(packing, resolution); });
  EXPECT_NE(message.find("1e+12 voxels"), std::string::npos) << message;
  EXPECT_NE(message.find("GiB"), std::string::npos) << message;
  resolution.spacing = 0.1;
  resolution.memory_limit_bytes = 1e6;  // 10^6 voxels × 59 bytes
  EXPECT_NE(test::input_error_message([&] { (void)voxelise(packing, resolution); }).find("memory limit"),
            std::string::npos);
}

TEST(Voxelise, NanSemiAxisIsRefusedNamingTheRow) {
  Packing packing = test::random_ellipsoids(3, 20.0, 1);
  packing.semi_axes[2].z() = std::nan("");
  const std::string message = test::input_error_message([&] { (void)voxelise(packing, Resolution{}); });
  EXPECT_NE(message.find("row 3 semi-axis c"), std::string::npos) << message;
}

}  // namespace
}  // namespace ellc::microstructure
