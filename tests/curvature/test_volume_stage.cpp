// isoform_volume_curvature reports its fits as ISOFORM_STAGE_CURVATURE: a
// call cancelled before it starts stops in that stage (after the grid's
// load), with no result volume.
#include <gtest/gtest.h>

#include <vector>

#include "isoform.h"

namespace {

// An 8^3 fog volume, every voxel 1 + 0.01 r^2 (all active).
isoform_volume* small_volume() {
  std::vector<float> v(8 * 8 * 8);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) v[size_t((k * 8 + j) * 8 + i)] = 1.0f + 0.01f * float(i * i + j * j + k * k);
  const double spacing[3] = {1, 1, 1}, origin[3] = {0, 0, 0};
  isoform_volume* out = nullptr;
  EXPECT_EQ(isoform_volume_from_dense(v.data(), 8, 8, 8, spacing, origin, "f", ISOFORM_CLASS_FOG, &out), ISOFORM_OK);
  return out;
}

TEST(VolumeCurvatureStage, CancelledCallStopsInTheCurvatureStage) {
  isoform_volume* volume = small_volume();
  ASSERT_NE(volume, nullptr);
  isoform_progress progress{};
  progress.cancel = 1;
  isoform_volume* out = nullptr;
  EXPECT_EQ(isoform_volume_curvature(volume, 0, nullptr, &progress, &out), ISOFORM_ERR_CANCELLED);
  EXPECT_EQ(out, nullptr);
  EXPECT_EQ(progress.stage, ISOFORM_STAGE_CURVATURE);
  isoform_volume_free(volume);
}

TEST(VolumeCurvatureStage, FinishedCallEndsDone) {
  isoform_volume* volume = small_volume();
  ASSERT_NE(volume, nullptr);
  isoform_progress progress{};
  isoform_volume* out = nullptr;
  EXPECT_EQ(isoform_volume_curvature(volume, 0, nullptr, &progress, &out), ISOFORM_OK);
  EXPECT_NE(out, nullptr);
  EXPECT_EQ(progress.stage, ISOFORM_STAGE_DONE);
  isoform_volume_free(out);
  isoform_volume_free(volume);
}

}  // namespace
