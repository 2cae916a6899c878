// The Volume that libcore sees: grids of scalar samples visited as bricks.
//
// A brick is a dense block of samples in index space around a block of cells,
// with a halo: the cells whose lower corner lies in [origin, origin + cells)
// need the samples [origin, origin + cells] (corners) and one more on each
// side for the 3x3x3 gradient operator, so a brick stores the samples
// [origin - 1, origin + cells + 1] along each axis. vdbio makes bricks from an
// OpenVDB tree; dense arrays are cut into bricks here. libcore never sees
// OpenVDB.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace isoform {

using Index3 = std::array<int, 3>;
using Vec3d = std::array<double, 3>;

// Affine map from index space to world space: world = m * (i, j, k, 1).
struct Affine {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  Vec3d apply(const Vec3d& p) const;
  // The linear part only (for tangent vectors).
  Vec3d apply_linear(const Vec3d& v) const;
  // The inverse transpose of the linear part (for normals), not normalised.
  Vec3d apply_normal(const Vec3d& n) const;
  // The cofactor matrix of the linear part: the inverse transpose times the
  // determinant (what apply_normal multiplies by, before the sign).
  void cofactors(double c[3][3]) const;
  // The determinant of the linear part; negative flips orientation.
  double determinant() const;
  // Length of each index axis in world units.
  Vec3d voxel_size() const;
  static Affine scale_translate(const Vec3d& scale, const Vec3d& translate);
};

struct Brick {
  Index3 origin{0, 0, 0};  // index of the first cell (and first owned sample)
  Index3 cells{0, 0, 0};   // cells per axis whose lower corner is in the brick
  // Samples for index origin - 1 .. origin + cells + 1 per axis, x fastest;
  // dims() = cells + 3.
  std::vector<float> samples;
  // One flag per sample, 1 where the sample is defined. Empty means all are.
  // Cells with an undefined corner are not contoured (dense arrays end there).
  std::vector<uint8_t> defined;

  Index3 dims() const { return {cells[0] + 3, cells[1] + 3, cells[2] + 3}; }
  // Linear position of sample (i, j, k), each in [-1, cells + 1], relative to origin.
  size_t at(int i, int j, int k) const {
    const Index3 d = dims();
    return (size_t(k + 1) * size_t(d[1]) + size_t(j + 1)) * size_t(d[0]) + size_t(i + 1);
  }
  float value(int i, int j, int k) const { return samples[at(i, j, k)]; }
  bool is_defined(int i, int j, int k) const { return defined.empty() || defined[at(i, j, k)]; }
  void resize(const Index3& origin_, const Index3& cells_, bool with_defined);
};

// Visits the bricks of one grid. fill() must be safe to call from several
// threads at once with different Brick objects.
class BrickSource {
 public:
  virtual ~BrickSource() = default;
  virtual size_t brick_count() const = 0;
  virtual void fill(size_t index, Brick& out) const = 0;
  // A dense resample of the region: out[(k * dims[1] + j) * dims[0] + i]
  // becomes the sample at lo + (i, j, k), x fastest. The default visits
  // every brick and copies the samples each holds (its cells' corners);
  // samples no brick holds, or only as undefined, become `outside`. A
  // sparse source overrides it to read its tree directly (tiles and
  // background included). Thread-safe like fill().
  virtual void fill_region(const Index3& lo, const Index3& dims, float outside,
                           std::vector<float>& out) const;
  // False only when no cell of brick `index` can cross `isovalue`: every
  // corner sample of its cells (origin .. origin + cells) is >= isovalue, or
  // every one is below it. A source that knows value ranges says so without
  // filling the brick; true when unsure (the default). Thread-safe.
  virtual bool may_cross(size_t /*index*/, double /*isovalue*/) const { return true; }
};

enum class GridClass { Other = 0, LevelSet = 1, Fog = 2 };

// One scalar grid, ready for contouring.
struct ScalarGrid {
  std::string name;
  GridClass grid_class = GridClass::Other;
  Affine index_to_world;
  double background = 0.0;
  double value_min = 0.0, value_max = 0.0;  // over active values
  std::shared_ptr<const BrickSource> bricks;
  // The same samples with `defined` set exactly at the active voxels (a
  // sparse file's active set), or null when every defined sample is active
  // (dense arrays). The curvature of graphs reads this one when it is set.
  std::shared_ptr<const BrickSource> active_bricks;
  // True when the defined own samples of `bricks` are the grid's active set
  // even where they equal the background (curvature results, where 0 is a
  // value): writers keep them active instead of dropping background values.
  bool defined_is_active = false;
};

// Facts about a grid of a volume file, known before or after loading.
struct GridFacts {
  std::string name;
  std::string value_type;  // "float", "double", "half", "int32", "vec3s", ...
  GridClass grid_class = GridClass::Other;
  bool is_scalar = false;
  double value_min = 0.0, value_max = 0.0, background = 0.0;
  long long active_voxels = 0;
  Index3 bbox_min{0, 0, 0}, bbox_max{-1, -1, -1};
  Affine index_to_world;
  // The patient frame the transform maps into, as the file states it, named
  // by where +x, +y, +z point: "RAS" (right, anterior, superior: NIfTI's),
  // "LPS" (left, posterior, superior: DICOM's), "LAS", or "" when the file
  // does not say.
  std::string space;
  // The world unit: "mm", "m", "um", or "" when the file does not say.
  std::string unit;
};

// A source of grids: an OpenVDB file (vdbio), a dense array, a phantom.
class VolumeFile {
 public:
  virtual ~VolumeFile() = default;
  // The path the volume came from ("" when generated in memory).
  virtual std::string path() const = 0;
  virtual int grid_count() const = 0;
  // Facts about grid i, loading it first if the value range needs the data.
  virtual GridFacts facts(int i) const = 0;
  // The grid ready for contouring; throws Unsupported for non-scalar grids.
  virtual std::shared_ptr<const ScalarGrid> load(int i) const = 0;
};

// A dense array of samples, x fastest, as a BrickSource: the samples outside
// the array are undefined, so contours stop at its faces.
class DenseBricks : public BrickSource {
 public:
  DenseBricks(std::shared_ptr<const std::vector<float>> values, const Index3& dims,
              int brick_cells = 16);
  size_t brick_count() const override;
  void fill(size_t index, Brick& out) const override;
  const Index3& dims() const { return dims_; }
  const std::vector<float>& values() const { return *values_; }

 private:
  std::shared_ptr<const std::vector<float>> values_;
  Index3 dims_;
  int brick_cells_;
  Index3 brick_counts_;
};

// A VolumeFile of one dense grid held in memory.
class DenseVolume : public VolumeFile {
 public:
  DenseVolume(std::string name, GridClass grid_class, std::vector<float> values,
              const Index3& dims, const Affine& index_to_world, std::string path = "");
  std::string path() const override { return path_; }
  int grid_count() const override { return 1; }
  GridFacts facts(int i) const override;
  std::shared_ptr<const ScalarGrid> load(int i) const override;
  // The world frame and unit the file states (GridFacts::space, ::unit).
  void set_frame(std::string space, std::string unit);

 private:
  std::string path_;
  std::string space_, unit_;
  std::shared_ptr<ScalarGrid> grid_;
  Index3 dims_;
  long long active_ = 0;
};

// Throws FormatError naming `what` if any sample is NaN or infinite.
void check_finite(const std::vector<float>& values, const std::string& what);

}  // namespace isoform
