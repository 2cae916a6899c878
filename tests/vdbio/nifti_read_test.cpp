// NIfTI-1 and NIfTI-2 files, written field by field, read back: the three
// ways to world coordinates, both byte orders, gzip, .hdr/.img pairs, 4-D
// files, scaling, and headers that lie.
#include "vdbio/nifti_read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "libcore/errors.h"
#include "nifti_samples.h"
#include "test_support.h"
#include "vdbio/input_file.h"

namespace isoform::vdbio {
namespace {

using test::error_of;
using test::NiftiSample;
using test::nifti_bytes;
using test::TempDir;
using test::write_file;

std::vector<float> samples_of(const VolumeFile& volume) {
  const auto grid = volume.load(0);
  return dynamic_cast<const DenseBricks&>(*grid->bricks).values();
}

std::vector<double> ramp(size_t n, double start = 0) {
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = start + double(i);
  return v;
}

// 3x2x2 float samples 0..11 whose sform permutes and scales the axes.
NiftiSample oblique_sform() {
  NiftiSample s;
  s.dim[1] = 3, s.dim[2] = 2, s.dim[3] = 2;
  s.pixdim[1] = 1.5, s.pixdim[2] = 3, s.pixdim[3] = 2;
  s.sform_code = 1;
  const double rows[3][4] = {{0, 0, -2, 10}, {1.5, 0, 0, -4}, {0, 3, 0, 7}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) s.srow[r][c] = rows[r][c];
  s.samples = ramp(12);
  return s;
}

void expect_affine(const Affine& got, const double want[3][4], double tolerance) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got.m[r][c], want[r][c], tolerance) << "row " << r << " column " << c;
}

TEST(NiftiRead, SformGivesTheWorldMapAndRasFrame) {
  TempDir dir;
  const std::string path = dir.file("scan.nii");
  const NiftiSample sample = oblique_sform();
  write_file(path, nifti_bytes(sample));
  const auto volume = read_nifti(path, -1);
  EXPECT_EQ(samples_of(*volume), std::vector<float>({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  const GridFacts facts = volume->facts(0);
  expect_affine(facts.index_to_world, sample.srow, 0);
  EXPECT_EQ(facts.bbox_max, (Index3{2, 1, 1}));
  EXPECT_EQ(facts.space, "RAS");
  EXPECT_EQ(facts.unit, "mm");
  // Voxel (2, 1, 1) lands at the hand-computed point.
  EXPECT_EQ(facts.index_to_world.apply({2, 1, 1}), (Vec3d{8, -1, 10}));
}

TEST(NiftiRead, QformIsAQuaternionWithQfacOnK) {
  TempDir dir;
  NiftiSample s;
  s.dim[1] = 2, s.dim[2] = 2, s.dim[3] = 2;
  s.samples = ramp(8);
  s.qform_code = 1;
  // 90 degrees about z: (a, b, c, d) = (cos 45, 0, 0, sin 45).
  s.quatern[2] = std::sqrt(0.5);
  s.qoffset[0] = 5, s.qoffset[1] = 6, s.qoffset[2] = 7;
  s.pixdim[0] = -1, s.pixdim[1] = 2, s.pixdim[2] = 3, s.pixdim[3] = 4;
  s.srow[0][0] = 99;  // ignored: sform_code is 0
  const std::string path = dir.file("q.nii");
  write_file(path, nifti_bytes(s));
  const double want[3][4] = {{0, -3, 0, 5}, {2, 0, 0, 6}, {0, 0, -4, 7}};
  const GridFacts facts = read_nifti(path, -1)->facts(0);
  expect_affine(facts.index_to_world, want, 1e-6);
  EXPECT_EQ(facts.space, "RAS");
  // With both codes set the sform wins.
  s.sform_code = 2;
  write_file(path, nifti_bytes(s));
  EXPECT_EQ(read_nifti(path, -1)->facts(0).index_to_world.m[0][0], 99);
}

TEST(NiftiRead, WithoutCodesTheVoxelSizesAloneAndNoFrame) {
  TempDir dir;
  NiftiSample s;
  s.dim[1] = 2, s.dim[2] = 2, s.dim[3] = 2;
  s.pixdim[1] = 0.5, s.pixdim[2] = -0.25, s.pixdim[3] = 2;  // the sign is dropped
  s.xyzt_units = 0;
  s.samples = ramp(8);
  const std::string path = dir.file("plain.nii");
  write_file(path, nifti_bytes(s));
  const GridFacts facts = read_nifti(path, -1)->facts(0);
  const double want[3][4] = {{0.5, 0, 0, 0}, {0, 0.25, 0, 0}, {0, 0, 2, 0}};
  expect_affine(facts.index_to_world, want, 0);
  EXPECT_EQ(facts.space, "");
  EXPECT_EQ(facts.unit, "");
}

TEST(NiftiRead, Nifti2BigEndianScaledIntegers) {
  TempDir dir;
  NiftiSample s = oblique_sform();
  s.version = 2;
  s.big_endian = true;
  s.datatype = 4;  // int16
  s.samples = {0, 1, 2, 500, -7, 9, 10, 11, 12, 13, 14, 32767};
  s.scl_slope = 2, s.scl_inter = -1000;
  s.xyzt_units = 1 | 8;  // metres, seconds
  const std::string path = dir.file("ct.nii");
  write_file(path, nifti_bytes(s));
  const auto volume = read_nifti(path, -1);
  std::vector<float> want;
  for (double v : s.samples) want.push_back(float(2 * v - 1000));
  EXPECT_EQ(samples_of(*volume), want);
  EXPECT_EQ(volume->facts(0).unit, "m");
  expect_affine(volume->facts(0).index_to_world, s.srow, 0);
  // A slope of 0 means no scaling.
  s.scl_slope = 0;
  write_file(path, nifti_bytes(s));
  EXPECT_EQ(samples_of(*read_nifti(path, -1))[3], 500.0f);
}

TEST(NiftiRead, EveryRealDatatype) {
  TempDir dir;
  for (int datatype : {2, 4, 8, 16, 64, 256, 512, 768, 1024, 1280}) {
    NiftiSample s;
    s.dim[1] = 2, s.dim[2] = 2, s.dim[3] = 2;
    s.datatype = datatype;
    s.samples = ramp(8, 3);
    const std::string path = dir.file("t" + std::to_string(datatype) + ".nii");
    write_file(path, nifti_bytes(s));
    EXPECT_EQ(samples_of(*read_nifti(path, -1)), std::vector<float>({3, 4, 5, 6, 7, 8, 9, 10})) << datatype;
  }
}

TEST(NiftiRead, GzipAndPairsReadAsThePlainFile) {
  TempDir dir;
  const NiftiSample sample = oblique_sform();
  const std::string bytes = nifti_bytes(sample);
  const std::string gz = dir.file("scan.nii.gz");
  write_file(gz, bytes, true);
  EXPECT_EQ(samples_of(*read_nifti(gz, -1)), std::vector<float>({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  expect_affine(read_nifti(gz, -1)->facts(0).index_to_world, sample.srow, 0);
  // A .hdr and its .img (magic ni1, samples from byte 0 of the .img).
  NiftiSample pair = sample;
  pair.magic = std::string("ni1\0", 4);
  pair.vox_offset = 0;
  const std::string pair_bytes = nifti_bytes(pair);
  write_file(dir.file("two.hdr"), pair_bytes.substr(0, 348));
  write_file(dir.file("two.img"), pair_bytes.substr(352));
  EXPECT_EQ(samples_of(*read_nifti(dir.file("two.hdr"), -1)), samples_of(*read_nifti(gz, -1)));
  std::filesystem::remove(dir.file("two.img"));
  EXPECT_EQ(error_of<IoError>([&] { read_nifti(dir.file("two.hdr"), -1); }),
            dir.file("two.hdr") + ": its samples file two.img is missing");
}

TEST(NiftiRead, FourDimensionsNeedAVolumeIndex) {
  TempDir dir;
  NiftiSample s;
  s.dim[0] = 4, s.dim[1] = 2, s.dim[2] = 2, s.dim[3] = 2, s.dim[4] = 3;
  s.samples = ramp(24);
  const std::string path = dir.file("bold.nii");
  write_file(path, nifti_bytes(s));
  EXPECT_EQ(error_of<Unsupported>([&] { read_nifti(path, -1); }),
            path + ": a 4-D NIfTI of 3 volumes (2x2x2x3); choose one with --volume K (the open options' volume), "
                   "K from 0 to 2");
  EXPECT_EQ(samples_of(*read_nifti(path, 2)), std::vector<float>({16, 17, 18, 19, 20, 21, 22, 23}));
  EXPECT_EQ(error_of<InvalidArgument>([&] { read_nifti(path, 3); }),
            path + ": volume 3 asked of a NIfTI with 3 volumes");
  write_file(path, nifti_bytes(s), true);
  EXPECT_EQ(samples_of(*read_nifti(path, 1)), std::vector<float>({8, 9, 10, 11, 12, 13, 14, 15}));
}

// Each lying header gives one message naming the file and the field.
TEST(NiftiRead, HeadersThatLie) {
  TempDir dir;
  const std::string path = dir.file("bad.nii");
  const auto refused = [&](const NiftiSample& s, bool gzip = false) {
    write_file(path, nifti_bytes(s), gzip);
    return error_of<FormatError>([&] { read_nifti(path, -1); });
  };
  const std::string prefix = path + ": not a readable NIfTI file (";
  NiftiSample s = oblique_sform();
  s.pixdim[2] = 0;
  EXPECT_EQ(refused(s), prefix + "pixdim[2], a voxel size, is 0)");
  s.pixdim[2] = std::nan("");
  EXPECT_EQ(refused(s), prefix + "pixdim[2], a voxel size, is NaN)");
  s = oblique_sform();
  s.vox_offset = 100000;
  write_file(path, nifti_bytes(s).substr(0, 400));  // the samples promised past the end
  EXPECT_EQ(error_of<FormatError>([&] { read_nifti(path, -1); }),
            prefix + "3x2x2 f32 samples need bytes up to 100048, but bad.nii has 400)");
  s.vox_offset = 0;
  EXPECT_EQ(refused(s), prefix + "vox_offset, where the samples start, is 0, not a whole number past the header)");
  s = oblique_sform();
  s.dim[1] = 1000, s.dim[2] = 1000, s.dim[3] = 100;  // 400 MB promised, 48 bytes present
  EXPECT_EQ(refused(s), prefix + "1000x1000x100 f32 samples need bytes up to 400000352, but bad.nii has 400)");
  const std::string packed = refused(s, true);
  EXPECT_EQ(packed, prefix + "1000x1000x100 f32 samples need 400000352 decoded bytes, more than " +
                        std::to_string(std::filesystem::file_size(path)) + " bytes of gzip data can hold)");
  s = oblique_sform();
  s.bitpix = 8;
  EXPECT_EQ(refused(s), prefix + "datatype 16 has 32 bits per sample, but bitpix says 8)");
  s = oblique_sform();
  s.dim[0] = 0;
  EXPECT_EQ(refused(s), prefix + "dim[0], the number of dimensions, is 0, not 1 to 7)");
  s = oblique_sform();
  s.dim[2] = -5;
  EXPECT_EQ(refused(s), prefix + "dim[2] is -5)");
  s = oblique_sform();
  s.magic = std::string(4, '\0');
  EXPECT_EQ(refused(s), prefix + "no NIfTI-1 magic; an Analyze 7.5 header, whose orientation is unknown, is not read)");
  s = oblique_sform();
  for (auto& row : s.srow)
    for (double& v : row) v = 0;
  EXPECT_EQ(refused(s), prefix + "its sform is degenerate (its axes do not span space))");
  s = oblique_sform();
  s.samples[5] = std::nan("");
  EXPECT_EQ(refused(s), path + ": sample 5 is NaN; isoform needs finite values");
  write_file(path, std::string(400, 'x'));
  EXPECT_EQ(error_of<FormatError>([&] { read_nifti(path, -1); }),
            prefix + "its first field, the header size, is neither 348 nor 540)");
  // A gzip file cut in its samples.
  s = oblique_sform();
  write_file(path, nifti_bytes(s), true);
  const std::string whole = [&] {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  write_file(path, whole.substr(0, whole.size() - 30));
  const std::string cut = error_of<FormatError>([&] { read_nifti(path, -1); });
  EXPECT_EQ(cut.rfind(prefix + "its gzip data end ", 0), 0u) << cut;
  EXPECT_NE(cut.find("of the 400 decoded bytes 3x2x2 f32 samples need)"), std::string::npos) << cut;
}

TEST(NiftiRead, WhatIsNotReadIsNamed) {
  TempDir dir;
  const std::string path = dir.file("odd.nii");
  NiftiSample s = oblique_sform();
  s.datatype = 128;
  write_file(path, nifti_bytes(s));
  EXPECT_EQ(error_of<Unsupported>([&] { read_nifti(path, -1); }),
            path + ": NIfTI samples of datatype RGB24 (128); isoform reads real scalar samples");
  s = oblique_sform();
  s.dim[0] = 5, s.dim[4] = 1, s.dim[5] = 2;
  write_file(path, nifti_bytes(s));
  EXPECT_EQ(error_of<Unsupported>([&] { read_nifti(path, -1); }),
            path + ": a 5-D NIfTI (dim[5] is 2); isoform reads 3-D volumes and the volumes of 4-D files");
  EXPECT_THROW(read_nifti(dir.file("none.nii"), -1), IoError);
}

TEST(NiftiRead, TheMemoryBudgetBoundsTheSamples) {
  TempDir dir;
  NiftiSample s;
  s.dim[1] = 16, s.dim[2] = 16, s.dim[3] = 16;
  s.samples = ramp(4096);
  const std::string path = dir.file("big.nii");
  write_file(path, nifti_bytes(s));
  set_memory_budget(20000);
  const std::string message = error_of<FormatError>([&] { read_nifti(path, -1); });
  set_memory_budget(0);
  EXPECT_EQ(message, path + ": NIfTI data of 16x16x16 f32 samples would take 32.0 KiB in memory, beyond the "
                            "budget of 19.5 KiB");
  EXPECT_EQ(read_nifti(path, -1)->facts(0).active_voxels, 4096);
}

TEST(NiftiRead, NamesAndMagic) {
  EXPECT_TRUE(has_nifti_name("a/b.nii"));
  EXPECT_TRUE(has_nifti_name("B.NII.GZ"));
  EXPECT_TRUE(has_nifti_name("x.hdr"));
  EXPECT_FALSE(has_nifti_name("x.nrrd"));
  TempDir dir;
  write_file(dir.file("noext"), nifti_bytes(oblique_sform()));
  EXPECT_TRUE(has_nifti_magic(dir.file("noext")));
  NiftiSample two = oblique_sform();
  two.version = 2;
  write_file(dir.file("noext2"), nifti_bytes(two));
  EXPECT_TRUE(has_nifti_magic(dir.file("noext2")));
  write_file(dir.file("other"), std::string(400, 'x'));
  EXPECT_FALSE(has_nifti_magic(dir.file("other")));
}

}  // namespace
}  // namespace isoform::vdbio
