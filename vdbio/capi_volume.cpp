// The C API's entry points that need vdbio: opening OpenVDB, NRRD, NIfTI
// and raw files as volumes, and saving a volume as OpenVDB. Each body runs inside
// isoform::capi::guarded, which turns exceptions into a status and message.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "dense_read.h"
#include "input_file.h"
#include "libcore/capi/handles.h"
#include "libcore/errors.h"
#include "nifti_read.h"
#include "vdb_file.h"
#include "vdb_layout.h"
#include "vdb_write.h"

namespace {

using isoform::InvalidArgument;

static_assert(int(isoform::vdbio::ScalarType::U8) == ISOFORM_U8 &&
                  int(isoform::vdbio::ScalarType::U16) == ISOFORM_U16 &&
                  int(isoform::vdbio::ScalarType::F64) == ISOFORM_F64,
              "ScalarType follows isoform_scalar_type");

void require(bool ok, const char* message) {
  if (!ok) throw InvalidArgument(message);
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The extension decides; for any other extension the content does.
std::shared_ptr<isoform::VolumeFile> open_by_format(const std::string& path,
                                                    const isoform_open_options& options) {
  namespace vdbio = isoform::vdbio;
  const std::string ext = lower_extension(path);
  if (ext == ".vdb") return vdbio::open_vdb(path);
  if (ext == ".nrrd" || ext == ".nhdr") return vdbio::read_nrrd(path);
  if (vdbio::has_nifti_name(path)) return vdbio::read_nifti(path, options.volume);
  if (vdbio::has_nrrd_magic(path)) return vdbio::read_nrrd(path);
  if (vdbio::has_vdb_magic(path)) return vdbio::open_vdb(path);
  if (vdbio::has_nifti_magic(path)) return vdbio::read_nifti(path, options.volume);
  throw isoform::FormatError(path +
                             ": not an OpenVDB, NRRD or NIfTI file (headerless raw scans open "
                             "with isoform_volume_open_raw)");
}

// The caller's options, up to the fields its struct_size covers; the
// defaults for the rest.
isoform_open_options known_options(const isoform_open_options* given) {
  isoform_open_options options;
  isoform_open_options_default(&options);
  if (!given) return options;
  require(given->struct_size >= offsetof(isoform_open_options, volume) + sizeof(int),
          "isoform_volume_open_with: options.struct_size is not set (call isoform_open_options_default)");
  std::memcpy(&options, given, std::min(given->struct_size, sizeof options));
  options.struct_size = sizeof options;
  require(options.volume >= -1, "isoform_volume_open_with: options.volume must be -1 or a volume index");
  return options;
}

isoform::vdbio::RawLayout layout_of(const isoform_raw_options& options) {
  require(options.scalar_type >= ISOFORM_U8 && options.scalar_type <= ISOFORM_F64,
          "isoform_volume_open_raw: scalar_type is not an isoform_scalar_type");
  require(options.big_endian == 0 || options.big_endian == 1,
          "isoform_volume_open_raw: big_endian must be 0 or 1");
  isoform::vdbio::RawLayout layout;
  layout.type = isoform::vdbio::ScalarType(options.scalar_type);
  layout.big_endian = options.big_endian == 1;
  layout.header_bytes = options.header_bytes;
  for (int a = 0; a < 3; ++a) {
    layout.dims[a] = options.dims[a];
    layout.spacing[a] = options.spacing[a];
    layout.origin[a] = options.origin[a];
  }
  return layout;
}

isoform_status hand_out(std::shared_ptr<isoform::VolumeFile> file, isoform_volume** out) {
  auto volume = std::make_unique<isoform_volume>();
  volume->file = std::move(file);
  *out = volume.release();
  return ISOFORM_OK;
}

}  // namespace

isoform_status isoform_volume_open(const char* path, isoform_volume** out) {
  return isoform_volume_open_with(path, nullptr, out);
}

void isoform_open_options_default(isoform_open_options* options) {
  if (!options) return;
  *options = isoform_open_options{};
  options->struct_size = sizeof *options;
  options->volume = -1;
}

isoform_status isoform_volume_open_with(const char* path, const isoform_open_options* options,
                                        isoform_volume** out) {
  return isoform::capi::guarded([&] {
    require(out != nullptr, "isoform_volume_open: out is NULL");
    *out = nullptr;
    require(path != nullptr, "isoform_volume_open: path is NULL");
    return hand_out(open_by_format(path, known_options(options)), out);
  });
}

void isoform_set_memory_budget(unsigned long long bytes) { isoform::vdbio::set_memory_budget(bytes); }

unsigned long long isoform_memory_budget(void) { return isoform::vdbio::memory_budget(); }

void isoform_raw_options_default(isoform_raw_options* options) {
  if (!options) return;
  *options = isoform_raw_options{};
  options->scalar_type = ISOFORM_U16;
  for (int a = 0; a < 3; ++a) options->spacing[a] = 1.0;
}

isoform_status isoform_volume_open_raw(const char* path, const isoform_raw_options* options,
                                       isoform_volume** out) {
  return isoform::capi::guarded([&] {
    require(out != nullptr, "isoform_volume_open_raw: out is NULL");
    *out = nullptr;
    require(path != nullptr, "isoform_volume_open_raw: path is NULL");
    require(options != nullptr, "isoform_volume_open_raw: options is NULL");
    return hand_out(isoform::vdbio::read_raw(path, layout_of(*options)), out);
  });
}

isoform_status isoform_volume_save_vdb(const isoform_volume* volume, const char* path) {
  return isoform::capi::guarded([&] {
    require(volume != nullptr && volume->file != nullptr,
            "isoform_volume_save_vdb: volume is NULL");
    require(path != nullptr, "isoform_volume_save_vdb: path is NULL");
    isoform::vdbio::write_vdb(*volume->file, path);
    return ISOFORM_OK;
  });
}
