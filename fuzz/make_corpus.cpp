// Writes the fuzzers' seed corpora, one folder per target under the folder
// given: VDBs of every value type, map and compression (the tests' samples),
// NRRDs of every encoding written by Teem, NIfTI-1 and -2 files of every
// datatype, byte order and world map (plain and gzip), raw scans with their layout
// bytes, and meshes in every format and flavour the readers take.
//
// usage: isoform_fuzz_corpus DIR
#include <teem/nrrd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../tests/vdbio/nifti_samples.h"
#include "../tests/vdbio/vdb_samples.h"
#include "isoform.h"

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void vdb_seeds(const fs::path& dir) {
  int n = 0;
  for (const auto& sample : isoform::vdbio::test::vdb_samples())
    for (const uint32_t compression : isoform::vdbio::test::vdb_compressions())
      isoform::vdbio::test::write_vdb_sample(sample, compression, (dir / ("seed" + std::to_string(n++))).string());
}

// A 6 x 5 x 4 ball of each sample type, in each encoding Teem writes.
void nrrd_seeds(const fs::path& dir) {
  const size_t sizes[3] = {6, 5, 4};
  std::vector<double> ball(6 * 5 * 4);
  for (size_t i = 0; i < ball.size(); ++i) {
    const double x = double(i % 6) - 2.5, y = double(i / 6 % 5) - 2, z = double(i / 30) - 1.5;
    ball[i] = 100.0 - 10.0 * (x * x + y * y + z * z);
  }
  const int types[] = {nrrdTypeUChar, nrrdTypeShort, nrrdTypeUInt, nrrdTypeFloat, nrrdTypeDouble};
  const NrrdEncoding* encodings[] = {nrrdEncodingRaw, nrrdEncodingGzip, nrrdEncodingAscii, nrrdEncodingHex};
  int n = 0;
  for (const int type : types)
    for (const NrrdEncoding* encoding : encodings) {
      Nrrd* doubles = nrrdNew();
      Nrrd* typed = nrrdNew();
      nrrdWrap_nva(doubles, ball.data(), nrrdTypeDouble, 3, sizes);
      nrrdConvert(typed, doubles, type);
      if (n % 2) {  // half of them with an oblique frame
        const double directions[3][NRRD_SPACE_DIM_MAX] = {{0.8, 0.6, 0}, {-0.6, 0.8, 0}, {0, 0, 2}};
        nrrdSpaceSet(typed, nrrdSpaceRightAnteriorSuperior);
        nrrdSpaceOriginSet(typed, std::vector<double>{10, -5, 3}.data());
        nrrdAxisInfoSet_nva(typed, nrrdAxisInfoSpaceDirection, directions);
      }
      NrrdIoState* io = nrrdIoStateNew();
      io->encoding = encoding;
      const std::string path = (dir / ("seed" + std::to_string(n++) + ".nrrd")).string();
      nrrdSave(path.c_str(), typed, io);
      nrrdIoStateNix(io);
      nrrdNuke(typed);
      nrrdNix(doubles);
      if (biffCheck(NRRD)) free(biffGetDone(NRRD));  // none expected; freed if any
    }
}

// The raw target reads 12 layout bytes, then the file.
void nifti_seeds(const fs::path& dir) {
  using isoform::vdbio::test::NiftiSample;
  int n = 0;
  for (int version : {1, 2})
    for (int datatype : {2, 4, 16, 64, 512})
      for (int world = 0; world < 3; ++world) {
        NiftiSample s;
        s.version = version;
        s.big_endian = datatype == 4;
        s.datatype = datatype;
        s.dim[0] = world == 2 ? 4 : 3;
        s.dim[1] = 6, s.dim[2] = 5, s.dim[3] = 4, s.dim[4] = world == 2 ? 2 : 1;
        s.pixdim[0] = -1, s.pixdim[1] = 0.5, s.pixdim[2] = 0.75, s.pixdim[3] = 2;
        s.qform_code = world == 1;
        s.quatern[0] = 0.2, s.quatern[1] = -0.1, s.quatern[2] = 0.3;
        s.sform_code = world == 0;
        s.scl_slope = datatype == 4 ? 2 : 0, s.scl_inter = -10;
        const size_t count = size_t(6 * 5 * 4 * s.dim[4]);
        for (size_t i = 0; i < count; ++i) {
          const double x = double(i % 6) - 2.5, y = double(i / 6 % 5) - 2, z = double(i / 30 % 4) - 1.5;
          s.samples.push_back(100 - 10 * (x * x + y * y + z * z));
        }
        const std::string bytes = isoform::vdbio::test::nifti_bytes(s);
        const bool gzip = n % 2 == 1;
        isoform::vdbio::test::write_file((dir / ("seed" + std::to_string(n++) + ".nii")).string(), bytes, gzip);
      }
}

void raw_seeds(const fs::path& dir) {
  const struct {
    uint8_t dims[3], type, big_endian, header;
  } layouts[] = {{{8, 8, 8}, 0, 0, 0}, {{5, 6, 7}, 6, 0, 16}, {{4, 4, 9}, 2, 1, 0}, {{3, 9, 2}, 7, 0, 3}};
  const size_t sample_bytes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
  int n = 0;
  for (const auto& l : layouts) {
    std::string bytes = {char(l.dims[0] - 1), char(l.dims[1] - 1), char(l.dims[2] - 1), char(l.type),
                         char(l.big_endian), char(l.header), 3, 3, 3, 0, 0, 0};
    bytes += std::string(l.header, 'h');
    const size_t count = size_t(l.dims[0]) * l.dims[1] * l.dims[2];
    for (size_t i = 0; i < count * sample_bytes[l.type]; ++i) bytes += char((i * 37) % 251);
    write(dir / ("seed" + std::to_string(n++)), bytes);
  }
}

// A contour of the phantom in every format isoform writes, and small
// hand-written files of what other writers produce.
void mesh_seeds(const fs::path& ply, const fs::path& obj, const fs::path& stl) {
  isoform_volume* volume = nullptr;
  isoform_mesh* mesh = nullptr;
  isoform_contour_options options;
  isoform_contour_options_default(&options);
  options.auto_isovalue = 0;
  options.isovalue = 0.5;
  if (isoform_volume_phantom(12, &volume) == ISOFORM_OK && isoform_contour(volume, 0, &options, nullptr, &mesh) == ISOFORM_OK) {
    isoform_mesh_save(mesh, (ply / "contour.ply").c_str());
    isoform_mesh_save(mesh, (obj / "contour.obj").c_str());
    isoform_mesh_save(mesh, (stl / "contour.stl").c_str());
  }
  isoform_mesh_free(mesh);
  isoform_volume_free(volume);
  const std::string octahedron_points = "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n";
  const std::string octahedron_faces = "0 2 4\n2 1 4\n1 3 4\n3 0 4\n2 0 5\n1 2 5\n3 1 5\n0 3 5\n";
  write(ply / "ascii.ply", "ply\nformat ascii 1.0\ncomment octahedron\nelement vertex 6\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 8\nproperty list uchar int "
                           "vertex_indices\nend_header\n" + octahedron_points +
                           [&] {
                             std::string f;
                             for (size_t at = 0; at < octahedron_faces.size();) {
                               const size_t eol = octahedron_faces.find('\n', at);
                               f += "3 " + octahedron_faces.substr(at, eol - at + 1);
                               at = eol + 1;
                             }
                             return f;
                           }());
  write(ply / "quads_big_endian.ply",
        std::string("ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                    "property double z\nproperty uchar red\nelement face 1\nproperty list uint short vertex_indices\n"
                    "end_header\n") +
            [] {
              std::string b;
              const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
              for (const auto& v : p) {
                for (double c : v) {
                  uint64_t bits;
                  std::memcpy(&bits, &c, 8);
                  for (int k = 7; k >= 0; --k) b += char(bits >> (8 * k));
                }
                b += char(200);
              }
              b += std::string("\0\0\0\4\0\0\0\1\0\2\0\3", 12);
              return b;
            }());
  write(obj / "quads.obj", "# a square and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                           "vn 0 0 1\nvt 0 0\nf 1/1/1 2//1 3 4\nf -1 -4 -5\n");
  std::string ascii_stl = "solid octahedron\n";
  const float p[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& t : f) {
    ascii_stl += "facet normal 0 0 0\nouter loop\n";
    for (int c : t)
      ascii_stl += "vertex " + std::to_string(p[c][0]) + " " + std::to_string(p[c][1]) + " " +
                   std::to_string(p[c][2]) + "\n";
    ascii_stl += "endloop\nendfacet\n";
  }
  write(stl / "ascii.stl", ascii_stl + "endsolid octahedron\n");
  std::string solid_binary = read(stl / "contour.stl");
  if (solid_binary.size() > 5) solid_binary.replace(0, 5, "solid");  // a binary header saying "solid"
  write(stl / "solid_binary.stl", solid_binary);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const fs::path root = argv[1];
  for (const char* target : {"vdb", "nrrd", "nifti", "raw", "ply", "obj", "stl"})
    fs::create_directories(root / target);
  vdb_seeds(root / "vdb");
  nrrd_seeds(root / "nrrd");
  nifti_seeds(root / "nifti");
  raw_seeds(root / "raw");
  mesh_seeds(root / "ply", root / "obj", root / "stl");
  return 0;
}
