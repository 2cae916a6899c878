/*
 * isoform.h -- the one public interface of isoform.
 *
 * isoform turns scalar volumes into surfaces: it reads OpenVDB grids and dense
 * scans, extracts a contour (isosurface) as a watertight triangle mesh with the
 * trilinear-consistent cell method of Hamann (1991, Ch. 3) or a six-tetrahedra
 * split, and gives the mesh's neighbours, connected parts and normals.
 *
 * Conventions
 * - Every fallible call returns an isoform_status; on failure
 *   isoform_last_error() returns a thread-local message naming the input and
 *   the problem. Nothing throws or aborts across this boundary.
 * - Handles (isoform_volume, isoform_mesh) are owned by the library; free each
 *   with its *_free function (NULL is accepted). A handle may be read from
 *   several threads at once; calls that modify a handle need exclusive access.
 * - Bulk data leaves through count queries plus copy-into-caller-buffer calls.
 * - Options are plain structs: call isoform_*_options_default() first.
 * - Coordinates written to meshes are world coordinates (the grid's transform
 *   applied); "voxel units" means index space.
 */
#ifndef ISOFORM_H
#define ISOFORM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(ISOFORM_BUILDING_LIBRARY)
#define ISOFORM_API __attribute__((visibility("default")))
#else
#define ISOFORM_API
#endif

/* Version: major * 10000 + minor * 100 + patch. */
#define ISOFORM_VERSION 300

/* Returns ISOFORM_VERSION of the library actually loaded. */
ISOFORM_API int isoform_version(void);

typedef enum isoform_status {
  ISOFORM_OK = 0,
  ISOFORM_ERR_INVALID_ARGUMENT = 1, /* a NULL handle, a bad option, an unknown grid */
  ISOFORM_ERR_IO = 2,               /* a file cannot be opened, read or written */
  ISOFORM_ERR_FORMAT = 3,           /* a file is not what it claims, or is damaged */
  ISOFORM_ERR_UNSUPPORTED = 4,      /* a valid input this version cannot handle */
  ISOFORM_ERR_OUT_OF_MEMORY = 5,
  ISOFORM_ERR_CANCELLED = 6,        /* the caller set the progress cancel flag */
  ISOFORM_ERR_INTERNAL = 7          /* a bug in isoform: please report it */
} isoform_status;

/* The message of the last failed call on this thread ("" if none). The
 * pointer stays valid until the next isoform call on the same thread. */
ISOFORM_API const char* isoform_last_error(void);

/* A short constant name for a status, such as "io error". */
ISOFORM_API const char* isoform_status_name(isoform_status status);

/* ------------------------------------------------------------------ */
/* Progress and cancellation                                          */
/* ------------------------------------------------------------------ */

/* A progress sink the caller owns and polls (for example from a UI timer).
 * The library stores into fraction and stage with relaxed atomic writes while
 * a long call runs on the calling thread, and polls cancel; when cancel
 * becomes non-zero the call returns ISOFORM_ERR_CANCELLED soon after and
 * leaves no partial result. Pass NULL where no progress is wanted. */
typedef struct isoform_progress {
  volatile float fraction; /* 0..1 within the current stage */
  volatile int stage;      /* an isoform_stage value */
  volatile int cancel;     /* set non-zero by the caller to cancel */
} isoform_progress;

typedef enum isoform_stage {
  ISOFORM_STAGE_IDLE = 0,
  ISOFORM_STAGE_LOAD = 1,     /* reading a grid */
  ISOFORM_STAGE_CONTOUR = 2,  /* cells to triangles */
  ISOFORM_STAGE_MERGE = 3,    /* shared vertices, triangle table */
  ISOFORM_STAGE_TOPOLOGY = 4, /* neighbours, parts */
  ISOFORM_STAGE_DONE = 5,
  ISOFORM_STAGE_CURVATURE = 6, /* fitting each vertex's platelet */
  ISOFORM_STAGE_REDUCE = 8,    /* isoform_reduce removing triangles (after
                                  ISOFORM_STAGE_CURVATURE when the mesh had none) */
  ISOFORM_STAGE_PATCH = 10,    /* isoform_patch_tessellate */
  ISOFORM_STAGE_COMPARE = 16   /* isoform_compare sampling the surfaces */
} isoform_stage;

/* ------------------------------------------------------------------ */
/* Volumes                                                            */
/* ------------------------------------------------------------------ */

typedef struct isoform_volume isoform_volume;

typedef enum isoform_grid_class {
  ISOFORM_CLASS_OTHER = 0,
  ISOFORM_CLASS_LEVEL_SET = 1, /* signed distance, negative inside */
  ISOFORM_CLASS_FOG = 2        /* density, dense inside (fog volumes, scans) */
} isoform_grid_class;

/* Facts about one grid. Value range and active count cover active voxels
 * and active tiles. transform maps index (i, j, k, 1) to world coordinates:
 * world = transform * (i, j, k, 1), row-major 4x4. */
typedef struct isoform_grid_info {
  char name[256];
  char value_type[32];       /* "float", "double", "half", "int32", "vec3s", ... */
  int grid_class;            /* isoform_grid_class */
  int is_scalar;             /* 1 if isoform can contour it */
  double value_min, value_max;
  double background;
  long long active_voxels;   /* voxels in active leaves and active tiles */
  int bbox_min[3], bbox_max[3]; /* inclusive index bounding box of active values */
  double voxel_size[3];      /* world units per voxel along i, j, k */
  double transform[16];
  char space[8];  /* the patient frame world coordinates are in, by where +x,
                     +y, +z point: "RAS" (NIfTI), "LPS" (DICOM), "LAS"; ""
                     when the file does not say (OpenVDB, raw) */
  char unit[8];   /* world unit: "mm", "m", "um"; "" when the file does not say */
} isoform_grid_info;

/* Opens a volume file: OpenVDB (.vdb), NRRD (.nrrd, .nhdr; raw or gzip
 * encoding) or NIfTI-1/NIfTI-2 (.nii, .nii.gz, .hdr with its .img). The
 * extension decides; other names are recognised by their first bytes. Grid
 * metadata is read at once; voxel data when a grid is first used (dense
 * scans: at once). Errors name the file: missing, not a VDB, truncated, and
 * so on. Same as isoform_volume_open_with and default options. */
ISOFORM_API isoform_status isoform_volume_open(const char* path, isoform_volume** out);

/* Choices for opening a volume file. Growable: later versions add fields at
 * the end, and struct_size tells the library which ones the caller knows. */
typedef struct isoform_open_options {
  size_t struct_size; /* sizeof(isoform_open_options); set by _default() */
  int volume;         /* the 0-based volume of a 4-D NIfTI; -1 (default)
                         opens 3-D files only and refuses 4-D ones */
} isoform_open_options;

ISOFORM_API void isoform_open_options_default(isoform_open_options* options);

/* isoform_volume_open with choices; options NULL means the defaults. */
ISOFORM_API isoform_status isoform_volume_open_with(const char* path,
                                                    const isoform_open_options* options,
                                                    isoform_volume** out);

/* The most memory one input file's data may take once decoded, in bytes.
 * Every reader checks a file's sizes against it before allocating anything
 * for the file, and refuses a file that claims more with a message naming
 * the file, the size and the budget. Process-wide, for the calls that follow;
 * 0 restores the default, half the machine's physical memory. */
ISOFORM_API void isoform_set_memory_budget(unsigned long long bytes);
ISOFORM_API unsigned long long isoform_memory_budget(void);

typedef enum isoform_scalar_type {
  ISOFORM_U8 = 0, ISOFORM_I8, ISOFORM_U16, ISOFORM_I16, ISOFORM_U32, ISOFORM_I32,
  ISOFORM_F32, ISOFORM_F64
} isoform_scalar_type;

/* How to read a headerless raw file. */
typedef struct isoform_raw_options {
  int dims[3];          /* samples along x (fastest), y, z; no default: required */
  int scalar_type;      /* isoform_scalar_type; default ISOFORM_U16 */
  int big_endian;       /* 0 = little endian (default), 1 = big endian */
  double spacing[3];    /* world units between samples; default 1, 1, 1 */
  double origin[3];     /* world position of sample (0,0,0); default 0, 0, 0 */
  size_t header_bytes;  /* bytes to skip at the start; default 0 */
} isoform_raw_options;

ISOFORM_API void isoform_raw_options_default(isoform_raw_options* options);

/* Opens a headerless raw scan as a one-grid volume named "density" (class
 * fog). The file size must equal header_bytes + dims product * sample size. */
ISOFORM_API isoform_status isoform_volume_open_raw(const char* path,
                                                   const isoform_raw_options* options,
                                                   isoform_volume** out);

/* Wraps a dense caller array (x fastest, nx*ny*nz floats, copied) as a
 * one-grid volume with the given name (NULL = "density") and class. spacing
 * and origin may be NULL (1,1,1 and 0,0,0). The contour of a dense volume
 * stops at the array's faces (open there), as the seed restricts f to a box.
 * NaN or Inf samples are refused. */
ISOFORM_API isoform_status isoform_volume_from_dense(const float* values, int nx, int ny, int nz,
                                                     const double spacing[3],
                                                     const double origin[3], const char* name,
                                                     int grid_class, isoform_volume** out);

/* Generates the built-in sample: a 3-D Shepp-Logan style head phantom of
 * nested ellipsoids with densities 0..1, n samples per axis (n >= 16; 128 is
 * the usual size), voxel size 2/(n-1) world units, spanning [-1, 1]^3. */
ISOFORM_API isoform_status isoform_volume_phantom(int n, isoform_volume** out);

/* Writes every grid of the volume to an OpenVDB file: scalar grids as float
 * grids (from a dense array, samples equal to the background 0 stay
 * inactive, so scans become sparse), other grids of a VDB input unchanged;
 * names, classes and transforms kept. Written to a temporary file and
 * renamed; refuses to overwrite the volume's own source file. */
ISOFORM_API isoform_status isoform_volume_save_vdb(const isoform_volume* volume, const char* path);

ISOFORM_API void isoform_volume_free(isoform_volume* volume);

/* Number of grids (scalar or not) in the volume. */
ISOFORM_API int isoform_volume_grid_count(const isoform_volume* volume);

/* Facts about grid `index` (0-based). Loads the grid's data the first time,
 * to compute its value range. */
ISOFORM_API isoform_status isoform_volume_grid_info(const isoform_volume* volume, int index,
                                                    isoform_grid_info* out);

/* Index of the grid called name, or -1 (and a message listing the names that
 * exist, in isoform_last_error). name NULL or "" gives the first scalar grid. */
ISOFORM_API int isoform_volume_find_grid(const isoform_volume* volume, const char* name);

/* ------------------------------------------------------------------ */
/* Contours                                                           */
/* ------------------------------------------------------------------ */

typedef struct isoform_mesh isoform_mesh;

typedef enum isoform_contour_method {
  ISOFORM_METHOD_CELLS = 0, /* trilinear-consistent cells, Section 3.2 (default) */
  ISOFORM_METHOD_TETRA = 1  /* six tetrahedra per cell, Section 3.2 */
} isoform_contour_method;

typedef enum isoform_orientation {
  ISOFORM_ORIENT_AUTO = 0,       /* level set: toward increasing f; else decreasing */
  ISOFORM_ORIENT_INCREASING = 1, /* normals point toward increasing f */
  ISOFORM_ORIENT_DECREASING = 2  /* normals point toward decreasing f */
} isoform_orientation;

typedef struct isoform_contour_options {
  double isovalue;     /* contour level, in the grid's value units; default 0 */
  int auto_isovalue;   /* 1 (default): level set -> 0, other grids -> midpoint
                          of the value range; 0: use isovalue */
  int method;          /* isoform_contour_method; default ISOFORM_METHOD_CELLS */
  int orientation;     /* isoform_orientation; default ISOFORM_ORIENT_AUTO */
  int threads;         /* worker threads; 0 (default) = all cores, 1 = serial */
} isoform_contour_options;

ISOFORM_API void isoform_contour_options_default(isoform_contour_options* options);

/* Contours grid `grid` (an index from isoform_volume_find_grid) into a new
 * mesh. The mesh is closed where the grid's values are defined on both sides
 * (sparse grids: everywhere; dense arrays: open at the array faces), manifold,
 * consistently oriented, in world coordinates, with unit normals from the
 * Zucker-Hummel operator. An isovalue outside the value range gives an empty
 * mesh and ISOFORM_OK. Time and memory grow with the active voxels. */
ISOFORM_API isoform_status isoform_contour(const isoform_volume* volume, int grid,
                                           const isoform_contour_options* options,
                                           isoform_progress* progress, isoform_mesh** out);

/* ------------------------------------------------------------------ */
/* Meshes                                                             */
/* ------------------------------------------------------------------ */

/* Facts about a mesh, all computed when it was made. */
typedef struct isoform_mesh_stats {
  long long vertices, triangles, parts;
  long long boundary_edges;     /* edges with one triangle */
  long long nonmanifold_edges;  /* edges with three or more triangles */
  long long inconsistent_edges; /* interior edges both triangles traverse the same way */
  long long degenerate_triangles; /* zero area or repeated vertex */
  long long euler_characteristic; /* V - E + F */
  double isovalue;              /* the level contoured (contours only) */
  int isovalue_was_auto;        /* 1 if the isovalue came from auto_isovalue */
  long long ambiguous_faces;    /* faces resolved by the asymptotic decider */
  long long degenerate_saddles; /* of those, saddle value equal to the isovalue */
  long long extra_points;       /* Theorem 3.6 points on the trilinear contour */
  long long centroid_points;    /* Remark 3.9 centroid fallbacks */
  long long near_sample_points; /* crossings held 1/1000 of an edge off a sample */
  double bbox_min[3], bbox_max[3]; /* world bounding box of the vertices */
} isoform_mesh_stats;

ISOFORM_API isoform_status isoform_mesh_stats_get(const isoform_mesh* mesh, isoform_mesh_stats* out);

ISOFORM_API size_t isoform_mesh_vertex_count(const isoform_mesh* mesh);
ISOFORM_API size_t isoform_mesh_triangle_count(const isoform_mesh* mesh);
ISOFORM_API size_t isoform_mesh_part_count(const isoform_mesh* mesh);

/* Which parts of a mesh to keep: a noisy scan's contour comes with
 * thousands of specks. Growable like isoform_open_options. A part is kept
 * when it passes every test set. */
typedef struct isoform_part_filter {
  size_t struct_size;       /* sizeof(isoform_part_filter); set by _default() */
  long long min_triangles;  /* drop parts of fewer triangles; 0 (default) keeps all */
  double min_volume;        /* drop closed parts that enclose less, in world units
                               cubed; parts with a boundary pass; 0 keeps all */
  long long largest;        /* keep only the K parts of most triangles; 0 keeps all */
} isoform_part_filter;

typedef struct isoform_part_filter_stats {
  long long parts_before, parts_after;
  long long triangles_before, triangles_after;
} isoform_part_filter_stats;

ISOFORM_API void isoform_part_filter_default(isoform_part_filter* filter);

/* Removes the parts the filter drops, with the vertices only they used; the
 * other vertices keep their normals, colours and curvature. Neighbours, parts
 * (renumbered, 0 the largest) and statistics are computed again. stats may
 * be NULL. */
ISOFORM_API isoform_status isoform_mesh_filter_parts(isoform_mesh* mesh,
                                                     const isoform_part_filter* filter,
                                                     isoform_part_filter_stats* stats);

/* Moves the mesh by an affine map, row-major 4x4 (world = matrix * (x, y,
 * z, 1); the last row must be 0 0 0 1): points by the map, normals by its
 * inverse transpose, and where the map mirrors (negative determinant) each
 * triangle's winding reversed, so normals and winding still agree.
 * Curvature is kept (directions turned) under rotations and mirrors, and
 * dropped under any other map. Refuses a map that flattens space. From RAS
 * to LPS and back: diag(-1, -1, 1, 1). */
ISOFORM_API isoform_status isoform_mesh_transform(isoform_mesh* mesh, const double matrix[16]);

/* Copy-out calls. out must hold 3 * vertex_count floats (points, normals),
 * 3 * triangle_count int32 (triangles: vertex indices, counter-clockwise seen
 * from the side the normals point to; neighbours: for triangle t, entry 3t+i
 * is the triangle across the edge from vertex i to vertex i+1, or -1 on a
 * boundary), or triangle_count int32 (parts: 0 is the largest part). */
ISOFORM_API isoform_status isoform_mesh_copy_points(const isoform_mesh* mesh, float* out);
ISOFORM_API isoform_status isoform_mesh_copy_normals(const isoform_mesh* mesh, float* out);
ISOFORM_API isoform_status isoform_mesh_copy_triangles(const isoform_mesh* mesh, int32_t* out);
ISOFORM_API isoform_status isoform_mesh_copy_neighbours(const isoform_mesh* mesh, int32_t* out);
ISOFORM_API isoform_status isoform_mesh_copy_parts(const isoform_mesh* mesh, int32_t* out);

/* Builds a mesh from caller arrays (copied): points 3*n floats, triangles
 * 3*m vertex indices. Neighbours, parts and statistics are computed; normals
 * are estimated from the mesh alone (Remark 3.15: least squares on the
 * one-ring). Indices out of range are refused. */
ISOFORM_API isoform_status isoform_mesh_from_arrays(const float* points, size_t n,
                                                    const int32_t* triangles, size_t m,
                                                    isoform_mesh** out);

/* Reads PLY (ascii or binary), OBJ or STL, chosen by extension. Coincident
 * STL corners are welded; polygons are split into triangles (concave ones by
 * ear clipping). Normals are read from PLY/OBJ when present, otherwise
 * estimated as in isoform_mesh_from_arrays. A PLY also gives back what
 * isoform_mesh_save writes: curvature, colours, edges, and double-precision
 * points, kept in double as isoform_mesh_from_arrays_f64 keeps them. */
ISOFORM_API isoform_status isoform_mesh_load(const char* path, isoform_mesh** out);

/* Writes binary PLY (x y z, in double when the mesh's double-precision
 * points would move in float by more than a millionth of its size; nx ny nz
 * per vertex, then k1 k2 mean gauss
 * absolute d1x d1y d1z d2x d2y d2z curvature_flags when the mesh has
 * curvature, red green blue alpha when it has colours; vertex_indices and
 * part per face; an edge element when it has loose edges), OBJ (v, vn, f, l)
 * or binary STL, chosen by the extension of path.
 * Written to a temporary file beside path and renamed, so a failure never
 * leaves half a file. */
ISOFORM_API isoform_status isoform_mesh_save(const isoform_mesh* mesh, const char* path);

/* isoform_mesh_save that stops when progress->cancel is set while the file is
 * written (progress may be NULL): ISOFORM_ERR_CANCELLED, the temporary file
 * removed and path untouched. */
ISOFORM_API isoform_status isoform_mesh_save_progress(const isoform_mesh* mesh, const char* path,
                                                      isoform_progress* progress);

ISOFORM_API void isoform_mesh_free(isoform_mesh* mesh);

/* ------------------------------------------------------------------ */
/* Curvature of surfaces (Chapter 4, Section 4.2)                     */
/* ------------------------------------------------------------------ */

/* How each vertex's platelet is fitted by a height field over the tangent
 * plane of its normal. The seed's fit trusts the normal; the others add
 * linear terms, which absorb normal error, and higher orders. */
typedef enum isoform_curvature_method {
  ISOFORM_CURVATURE_SEED = 0,    /* (4.28): 3 quadratic terms, one-ring, as printed */
  ISOFORM_CURVATURE_QUADRIC = 1, /* linear + quadratic terms, one-ring */
  ISOFORM_CURVATURE_CUBIC = 2,   /* up to cubic, two-ring */
  ISOFORM_CURVATURE_QUARTIC = 3  /* up to quartic, three-ring (default: the most accurate
                                    measured, docs/curvature-surface.md) */
} isoform_curvature_method;

/* Per-vertex quantities. Sign: positive where the surface bends away from
 * its normal (a sphere with outward normals has k1 = k2 = 1/r); k1 >= k2;
 * units 1/world unit (K: 1/world unit^2). */
typedef enum isoform_curvature_quantity {
  ISOFORM_CURVATURE_K1 = 0,
  ISOFORM_CURVATURE_K2 = 1,
  ISOFORM_CURVATURE_MEAN = 2,     /* H = (k1 + k2) / 2 */
  ISOFORM_CURVATURE_GAUSS = 3,    /* K = k1 k2 */
  ISOFORM_CURVATURE_ABSOLUTE = 4, /* |k1| + |k2| */
  ISOFORM_CURVATURE_DIR1 = 5,     /* unit direction of k1: 3 floats per vertex */
  ISOFORM_CURVATURE_DIR2 = 6      /* unit direction of k2: 3 floats per vertex */
} isoform_curvature_quantity;

/* Bits of the per-vertex curvature flags: what the fit had to do. */
#define ISOFORM_CURVATURE_FLAG_BOUNDARY 1       /* boundary vertex: a wider one-sided platelet */
#define ISOFORM_CURVATURE_FLAG_WIDENED 2        /* too few or badly placed points: more rings */
#define ISOFORM_CURVATURE_FLAG_LOWER_ORDER 4    /* a lower-order fit than the method's */
#define ISOFORM_CURVATURE_FLAG_NONMANIFOLD 8    /* the vertex's triangles are not one fan */
#define ISOFORM_CURVATURE_FLAG_ISOLATED 16      /* no triangle uses it: curvature 0 */
#define ISOFORM_CURVATURE_FLAG_FAILED 32        /* no fit possible: curvature 0 */
#define ISOFORM_CURVATURE_FLAG_NORMAL_REPAIRED 64 /* its normal was unusable: one from the points */

typedef struct isoform_curvature_options {
  int method;        /* isoform_curvature_method; default ISOFORM_CURVATURE_QUARTIC */
  int extra_rings;   /* rings added to the method's platelet, 0..8; default 0 (more
                        smooth noisy meshes at the cost of detail) */
  int color_by;      /* quantity ISOFORM_CURVATURE_K1..ABSOLUTE the vertex colours show;
                        default ISOFORM_CURVATURE_MEAN */
  int update_normals;/* 1: replace the mesh's normals by the fitted surface's; default 0 */
  int threads;       /* worker threads; 0 (default) = all cores, 1 = serial */
} isoform_curvature_options;

ISOFORM_API void isoform_curvature_options_default(isoform_curvature_options* options);

/* What isoform_curvature met: vertex counts per flag, and the robust colour
 * range (2nd to 98th percentile; symmetric about 0 for signed quantities). */
typedef struct isoform_curvature_stats {
  int method;             /* isoform_curvature_method used */
  int color_by;           /* isoform_curvature_quantity the colours show */
  long long vertices;
  long long boundary, widened, lower_order, nonmanifold, isolated, failed, normal_repaired;
  double color_min, color_max;
} isoform_curvature_stats;

/* Computes the principal curvatures and directions of every vertex of mesh
 * (Section 4.2), from its points, triangles and normals (contours carry the
 * volume's gradient normals; loaded meshes their file's or estimated ones),
 * and vertex colours; replaces earlier results. Every vertex gets a finite
 * value; see the flags for those that needed a fallback. O(n), parallel,
 * deterministic for any thread count. On failure the mesh is unchanged. */
ISOFORM_API isoform_status isoform_curvature(isoform_mesh* mesh, const isoform_curvature_options* options,
                                             isoform_progress* progress);

/* 1 if the mesh carries curvature (isoform_curvature ran on it), else 0. */
ISOFORM_API int isoform_mesh_has_curvature(const isoform_mesh* mesh);

/* Statistics of the last isoform_curvature; ISOFORM_ERR_INVALID_ARGUMENT
 * when the mesh has none. */
ISOFORM_API isoform_status isoform_mesh_curvature_stats(const isoform_mesh* mesh, isoform_curvature_stats* out);

/* Copies one quantity: vertex_count floats, or 3 * vertex_count for the
 * directions. ISOFORM_ERR_INVALID_ARGUMENT when the mesh has no curvature. */
ISOFORM_API isoform_status isoform_mesh_copy_curvature(const isoform_mesh* mesh, int quantity, float* out);

/* Copies vertex_count flag bytes (ISOFORM_CURVATURE_FLAG_* bits). */
ISOFORM_API isoform_status isoform_mesh_copy_curvature_flags(const isoform_mesh* mesh, uint8_t* out);

/* The colours isoform_curvature sets are read with isoform_mesh_color_count
 * and isoform_mesh_copy_colors (Volume visualisation, below). */

/* As isoform_mesh_from_arrays, with double-precision points, which the mesh
 * keeps beside its float copy for curvature fits (float coordinates alone
 * limit curvature accuracy to about 1e-7 / h^2 for edge length h). */
ISOFORM_API isoform_status isoform_mesh_from_arrays_f64(const double* points, size_t n,
                                                        const int32_t* triangles, size_t m,
                                                        isoform_mesh** out);

/* Replaces the mesh's normals by 3 * vertex_count floats (x y z per vertex),
 * e.g. a surface's exact normals; each is scaled to unit length. They orient
 * and frame later isoform_curvature calls (earlier results stay until then)
 * and are saved with the mesh. ISOFORM_ERR_INVALID_ARGUMENT, with the mesh
 * unchanged, when a normal is zero or not finite. */
ISOFORM_API isoform_status isoform_mesh_set_normals(isoform_mesh* mesh, const float* normals);

/* ------------------------------------------------------------------ */
/* Volume visualisation (Hamann 1991, Chapter 2)                      */
/* ------------------------------------------------------------------ */

/* The domain of a grid is its active index bounding box (bbox_min..bbox_max
 * of isoform_grid_info), mapped to world coordinates by the grid's
 * transform; values inside it are trilinear in the grid's samples
 * (inactive samples and tiles count with their stored value). Meshes made
 * here carry per-vertex colours with alpha, which isoform_mesh_save writes as
 * PLY properties red green blue alpha (uchar); curve networks are PLY edges.
 * Axis 0, 1, 2 means the plane x = c1, y = c2, z = c3 of Section 2.3. */

typedef enum isoform_colour_map_id {
  ISOFORM_MAP_VIRIDIS = 0,     /* perceptually uniform, dark blue to yellow */
  ISOFORM_MAP_DIVERGING = 1,   /* blue, white at 0, red; range symmetric about 0 */
  ISOFORM_MAP_GREEN_WHITE = 2  /* low green to high white (Figures 2.2-2.4) */
} isoform_colour_map_id;

/* How function values become colours: the linear colour-index map of
 * Section 2.2, c = ceil(((f_max - f) c_min + (f - f_min) c_max) / (f_max - f_min)),
 * with c_min = 0 and c_max = levels - 1, then the map's colour of index c. */
typedef struct isoform_colour_options {
  int map;           /* isoform_colour_map_id; default ISOFORM_MAP_VIRIDIS
                        (boxes: ISOFORM_MAP_GREEN_WHITE) */
  int levels;        /* colour indices c_min..c_max = 0..levels-1, 2..65536; default 256 */
  int fixed_range;   /* 0 (default): f_min, f_max are the least and greatest
                        value sampled (diverging: -m..m, m = max |f|);
                        1: use range_min, range_max */
  double range_min;  /* f_min in the grid's value units when fixed_range; default 0 */
  double range_max;  /* f_max when fixed_range, > range_min; default 1 */
} isoform_colour_options;

ISOFORM_API void isoform_colour_options_default(isoform_colour_options* options);

/* An RGBA image made by the library (8 bits per channel, rows top to bottom). */
typedef struct isoform_image isoform_image;

typedef struct isoform_slice_options {
  double position[3];  /* c1, c2, c3: where the planes x = c1, y = c2, z = c3
                          cut the domain; default 0.5, 0.5, 0.5 */
  int world;           /* 0 (default): position is normalised, 0..1 across the
                          domain's extent per axis; 1: position is in world units */
  int resolution;      /* samples along the longer side of each slice (k+1 or
                          l+1 of Section 2.3), 2..16384; the shorter side in
                          proportion to the domain (at least 2); default 256 */
  int colour_bar;      /* images only: 1 (default) adds a colour bar on the right */
  double height;       /* graphs only: the largest displacement of the graph
                          from its plane, as a fraction of the domain's largest
                          world extent; default 0.25 */
  isoform_colour_options colour; /* default viridis, range over all three slices */
} isoform_slice_options;

ISOFORM_API void isoform_slice_options_default(isoform_slice_options* options);

/* Samples slice `axis` (0, 1, 2) of grid `grid` into a new image: pixel
 * (column, row) of the slice part is the trilinear value at sample point
 * (column, res_v - 1 - row) of the slice's grid, whose horizontal axis is
 * y, x, x and vertical axis z, z, y for axis 0, 1, 2. The colour range spans
 * all three slices unless fixed. Errors: no such grid, a position outside
 * the domain, a resolution out of range. Time O(resolution^2). */
ISOFORM_API isoform_status isoform_slice_image(const isoform_volume* volume, int grid, int axis,
                                               const isoform_slice_options* options,
                                               isoform_image** out);

typedef enum isoform_slice_kind {
  ISOFORM_SLICE_PLANE = 0,   /* Gouraud-coloured rectangles in the domain (Fig. 2.7) */
  ISOFORM_SLICE_SURFACE = 1, /* graphs of the slice functions, triangles I1, I2 (Fig. 2.9) */
  ISOFORM_SLICE_CURVES = 2   /* the same graphs as curve networks: edges, no triangles */
} isoform_slice_kind;

/* Makes the slices of axis 0, 1 or 2, or of all three when axis is 3, as a
 * new coloured mesh in world coordinates. Planes also get the 12 edges of
 * the domain box. A graph lies over its plane, displaced along the plane's
 * normal by height * extent * (f - f_min) / (f_max - f_min). Vertices carry
 * colours (alpha 255) and normals; errors as for isoform_slice_image. */
ISOFORM_API isoform_status isoform_slice_mesh(const isoform_volume* volume, int grid, int axis,
                                              int kind, const isoform_slice_options* options,
                                              isoform_mesh** out);

typedef enum isoform_domain_kind {
  ISOFORM_DOMAIN_BOX = 0,      /* the grid's domain itself */
  ISOFORM_DOMAIN_SPHERICAL = 1 /* (x,y,z) = centre + (u cos v, u sin v cos w, u sin v sin w) */
} isoform_domain_kind;

typedef struct isoform_boxes_options {
  int q[3];             /* q_x, q_y, q_z (or q_u, q_v, q_w): subvolumes per axis, >= 1; default 5, 5, 5 */
  double gap[3];        /* alpha per axis: gap between subvolumes over their edge, >= 0; default 1, 1, 1 */
  int face_cells[2];    /* k, l: each face is a k x l grid of Gouraud cells; default 1, 1 (corners only) */
  int centroid_lines;   /* 1: edges between centroids of neighbouring subvolumes; default 0 */
  int domain;           /* isoform_domain_kind; default ISOFORM_DOMAIN_BOX */
  double uvw_min[3];    /* spherical: u, v, w lower limits; default 0, 0, 0 */
  double uvw_max[3];    /* spherical: upper limits (u in world units, v and w in
                           radians); default 1, pi, 3 pi / 2 (Figure 2.4) */
  double centre[3];     /* spherical: world position of u = 0; default 0, 0, 0 */
  isoform_colour_options colour; /* default green-white, range over all face points */
} isoform_boxes_options;

ISOFORM_API void isoform_boxes_options_default(isoform_boxes_options* options);

/* The domain-subdivision method of Section 2.2 as a new mesh: subvolume
 * V_rst has corner x_r = x_min + r (1 + alpha_x) dx, dx = (x_max - x_min) /
 * (q_x + alpha_x (q_x - 1)) (likewise y, z; over uvw for a spherical domain),
 * and six faces of (k+1)(l+1) vertices each, coloured from the trilinear
 * value there, with outward normals. 6 q_x q_y q_z k l quads, 2 triangles
 * each. Errors: no such grid, q < 1 (q = 0), a negative gap, a spherical
 * domain that leaves the grid's domain. */
ISOFORM_API isoform_status isoform_boxes(const isoform_volume* volume, int grid,
                                         const isoform_boxes_options* options, isoform_mesh** out);

typedef struct isoform_stack_options {
  int n[3];             /* n_x, n_y, n_z: cells of the evaluation grid, >= 1; default 8, 8, 8 */
  double transparency;  /* t of Section 2.2 in [0, 1]: c_new = (1 - t) c_poly + t c_old,
                           so alpha = 1 - t; default 0.5 */
  double view[3];       /* viewing direction, world, from the eye into the scene,
                           not zero; default -1, -1, -1 */
  isoform_colour_options colour; /* default viridis, range over the grid points */
} isoform_stack_options;

ISOFORM_API void isoform_stack_options_default(isoform_stack_options* options);

/* The transparency method of Section 2.2 as a new mesh: the rectangles
 * parallel to the xy-, xz- and yz-planes of an (n_x+1)(n_y+1)(n_z+1) grid
 * over the domain, 3 n_x n_y n_z + n_x n_y + n_x n_z + n_y n_z of them, 4
 * own vertices and 2 triangles each, coloured with alpha = 1 - t, and
 * ordered back to front along view: by the depth of each rectangle's corner
 * nearest the eye, farthest first. Triangles 2r and 2r+1 are rectangle r. */
ISOFORM_API isoform_status isoform_stack(const isoform_volume* volume, int grid,
                                         const isoform_stack_options* options, isoform_mesh** out);

/* Colours of a mesh made above: out must hold 4 * vertex_count bytes (red,
 * green, blue, alpha per vertex). A mesh without colours copies nothing. */
ISOFORM_API size_t isoform_mesh_color_count(const isoform_mesh* mesh);
ISOFORM_API isoform_status isoform_mesh_copy_colors(const isoform_mesh* mesh, uint8_t* out);
/* Loose edges (curve networks, centroid lines, the domain box): out must
 * hold 2 * edge_count int32 vertex indices. */
ISOFORM_API size_t isoform_mesh_edge_count(const isoform_mesh* mesh);
ISOFORM_API isoform_status isoform_mesh_copy_edges(const isoform_mesh* mesh, int32_t* out);

ISOFORM_API int isoform_image_width(const isoform_image* image);
ISOFORM_API int isoform_image_height(const isoform_image* image);
/* The value range behind the colours (f_min, f_max of Section 2.2). */
ISOFORM_API isoform_status isoform_image_range(const isoform_image* image, double* f_min,
                                               double* f_max);
/* out must hold 4 * width * height bytes: RGBA, rows top to bottom. */
ISOFORM_API isoform_status isoform_image_copy_rgba(const isoform_image* image, uint8_t* out);
/* out must hold width * height floats: the sampled value of each pixel of the
 * slice, NaN for the colour bar and its margin. */
ISOFORM_API isoform_status isoform_image_copy_values(const isoform_image* image, float* out);
/* Writes the image as an 8-bit RGBA PNG (libpng), with the value range in a
 * text chunk; to a temporary file beside path, then renamed. */
ISOFORM_API isoform_status isoform_image_save_png(const isoform_image* image, const char* path);
ISOFORM_API void isoform_image_free(isoform_image* image);

/* ------------------------------------------------------------------ */
/* Curvature of trivariate graphs                                     */
/* ------------------------------------------------------------------ */

/* The graph of a grid's f, (x, y, z, f(x, y, z)) in four dimensions, is a
 * hypersurface with three principal curvatures k1 >= k2 >= k3 at each point
 * (Hamann 1991, Section 4.3); H is their mean, K their product. World
 * coordinates are used: the grid's transform maps sample positions, and f's
 * values count as lengths along the fourth axis, so curvatures are in
 * inverse world units and do not change when the grid is rotated or moved. */

typedef enum isoform_volume_curvature_method {
  ISOFORM_VOLUME_CURVATURE_DEFAULT = 0, /* degree-6 least-squares fit of f on a
                                           7x7x7 box (moved inward at the data's
                                           edge), exact 4.36 curvature of the fit */
  ISOFORM_VOLUME_CURVATURE_SEED = 1     /* the seed's method: 14-point platelet,
                                           tangent space of the central-difference
                                           gradient, 6x6 normal equations (4.48) */
} isoform_volume_curvature_method;

/* Which fit gave a point its curvature; counted in the stats. */
typedef enum isoform_graph_fit {
  ISOFORM_GRAPH_FIT_JET_CENTRED = 0,     /* degree 6 on the centred 7x7x7 box */
  ISOFORM_GRAPH_FIT_JET_SHIFTED = 1,     /* degree 6 on a box moved or cut where
                                            the defined samples end */
  ISOFORM_GRAPH_FIT_JET_REDUCED = 2,     /* degree 2 on a box with undefined samples */
  ISOFORM_GRAPH_FIT_PLATELET = 3,        /* the seed's fit on the full platelet */
  ISOFORM_GRAPH_FIT_PLATELET_PARTIAL = 4, /* the seed's fit on a one-sided platelet */
  ISOFORM_GRAPH_FIT_NONE = 5,            /* too few defined neighbours for any fit:
                                            all five results are 0 */
  ISOFORM_GRAPH_FIT_COUNT = 6
} isoform_graph_fit;

typedef struct isoform_volume_curvature_options {
  int method;  /* isoform_volume_curvature_method; default ..._DEFAULT */
  int threads; /* worker threads; 0 (default) = all cores, 1 = serial */
} isoform_volume_curvature_options;

ISOFORM_API void isoform_volume_curvature_options_default(isoform_volume_curvature_options* options);

/* Distribution of one result grid over its active voxels. Percentiles are
 * nearest-rank (p50 is the median). */
typedef struct isoform_curvature_summary {
  double min, max, mean;
  double p01, p05, p25, p50, p75, p95, p99;
} isoform_curvature_summary;

/* Facts about a curvature result. grids[] follows the result's grid order:
 * mean, gauss, k1, k2, k3. fits[f] counts the points whose curvature came
 * from fit f (an isoform_graph_fit); they add up to points. */
typedef struct isoform_volume_curvature_stats {
  int method;                                 /* the method used */
  long long points;                           /* active voxels with a result */
  long long fits[ISOFORM_GRAPH_FIT_COUNT];
  isoform_curvature_summary grids[5];
} isoform_volume_curvature_stats;

/* Principal curvatures of the graph of grid `grid` (from
 * isoform_volume_find_grid) at each active voxel (dense arrays: every sample),
 * from active neighbours only (one-sided at the data's edge). *out gets a new
 * volume of five float grids "mean", "gauss", "k1", "k2", "k3" (class other,
 * the input's transform), active at exactly those voxels, zeros included;
 * isoform_volume_save_vdb writes it and refuses the input's path. Non-scalar
 * grids give ISOFORM_ERR_UNSUPPORTED. Linear in the active voxels; the same
 * bits for any thread count. options and progress may be NULL (defaults). */
ISOFORM_API isoform_status isoform_volume_curvature(const isoform_volume* volume, int grid,
                                                    const isoform_volume_curvature_options* options,
                                                    isoform_progress* progress, isoform_volume** out);

/* The stats of a volume made by isoform_volume_curvature; other volumes give
 * ISOFORM_ERR_INVALID_ARGUMENT. */
ISOFORM_API isoform_status isoform_volume_curvature_stats_get(const isoform_volume* result,
                                                              isoform_volume_curvature_stats* out);

/* A short constant description of an isoform_graph_fit value, such as
 * "seed's platelet fit"; "unknown" for others. */
ISOFORM_API const char* isoform_graph_fit_name(int fit);

/* ------------------------------------------------------------------ */
/* Comparison with the Loop limit surface                             */
/* ------------------------------------------------------------------ */

/* isoform_compare samples several smooth surfaces over the same base
 * triangles at the same barycentric points (weight 1-u-v, u, v on the
 * triangle's vertices t0, t1, t2): "linear" (the flat triangles), "loop"
 * (the Loop limit surface, evaluated with OpenSubdiv: adaptive refinement,
 * Gregory end caps, double precision) and "side-vertex" (Chapter 6, from the
 * mesh's points and normals, default patch options). Measures: deviation from a reference,
 * error at the data points (the base vertices), normal gap and
 * mean-curvature jump across edges, curvature spread, time per million
 * samples, and the triangles of each surface's tessellation. */

typedef enum isoform_reference_kind {
  ISOFORM_REFERENCE_NONE = 0,   /* no deviation measured */
  ISOFORM_REFERENCE_SPHERE = 1, /* exact distance from a sphere, world units */
  ISOFORM_REFERENCE_TORUS = 2,  /* exact distance from a torus around the z axis, world units */
  ISOFORM_REFERENCE_VOLUME = 3  /* |f(x) - iso| / |grad f| of a grid's trilinear interpolant, voxels;
                                   samples where grad f = 0 (flat cells) are left out */
} isoform_reference_kind;

typedef struct isoform_compare_options {
  int level;             /* lattice level k, 1..64: (k+1)(k+2)/2 samples and k^2 tessellation
                            triangles per base triangle, k samples per edge; default 8 */
  int reference;         /* isoform_reference_kind; default ISOFORM_REFERENCE_NONE (VOLUME
                            is implied when a volume is passed) */
  int fit_reference;     /* sphere, torus: 1 (default) takes the centre as the triangles'
                            area-weighted centroid and the radii as mean distances (torus: from the z axis
                            through the centre, then from that circle); 0 uses the fields below */
  double centre[3];      /* sphere, torus: centre, world units; default 0, 0, 0 */
  double radius;         /* sphere radius or torus major radius, world units; default 1 */
  double minor_radius;   /* torus tube radius, world units; default 0.25 */
  int grid;              /* volume: grid index (isoform_volume_find_grid); default -1 = the
                            first scalar grid */
  double isovalue;       /* volume: the level f = iso that is the reference; default 0 */
  int loop_isolation;    /* Loop: adaptive isolation of irregular vertices, 1..10; default 6 */
  int loop_sharp_corners;/* Loop boundary rule: 1 (default) boundary edges are B-spline curves
                            and valence-2 boundary vertices corners; 0 corners are smoothed */
  long long table_triangles; /* base triangles whose samples go into samples.csv, evenly
                            spaced; default 2000; 0 = none */
  const char* input_name;/* names the base mesh in the report's texts (copied); default NULL */
  int side_vertex;       /* 1 (default): also the side-vertex surface; when the mesh cannot
                            carry it (zero normals, degenerate triangles) it is left out and
                            the report's notes say why; 0: linear and loop only */
} isoform_compare_options;

ISOFORM_API void isoform_compare_options_default(isoform_compare_options* options);

typedef struct isoform_compare_report isoform_compare_report;

/* |x| statistics over samples: count, largest, root mean square, mean. */
typedef struct isoform_compare_stats {
  long long count;
  double max, rms, mean;
} isoform_compare_stats;

/* A signed quantity's distribution: nearest-rank percentiles, mean, standard deviation. */
typedef struct isoform_compare_spread {
  long long count;
  double p05, p50, p95, mean, stddev;
} isoform_compare_spread;

typedef struct isoform_compare_metrics {
  long long samples;                 /* lattice samples evaluated */
  long long failed_samples;          /* of those, where the surface is undefined */
  isoform_compare_stats deviation;   /* from the reference, in its unit; count 0 without one */
  isoform_compare_stats data_point_error;   /* |surface at a vertex - the vertex|, world units */
  isoform_compare_stats normal_gap;         /* angle of the two sides' normals at edge samples, radians */
  isoform_compare_stats position_gap;       /* distance of the two sides' points there, world units */
  isoform_compare_stats mean_curvature_jump;  /* |H left - H right| there, 1/world unit */
  isoform_compare_stats mean_curvature_error; /* |H - H of the reference| (sphere, torus only) */
  isoform_compare_spread mean_curvature;    /* H over the lattice samples, 1/world unit */
  isoform_compare_spread gauss_curvature;   /* K over the lattice samples, 1/world unit^2 */
  double evaluation_seconds;         /* evaluating the lattice samples, one thread */
  double seconds_per_million;        /* the same per million samples */
  long long tessellation_triangles;  /* triangles of the surface's tessellation at the level */
} isoform_compare_metrics;

/* Builds the surfaces over mesh and measures them. reference_or_NULL is the
 * volume whose grid options->grid at options->isovalue is the reference (it
 * implies ISOFORM_REFERENCE_VOLUME); NULL with reference VOLUME is an error.
 * Needs a triangle mesh OpenSubdiv accepts (manifold enough to refine).
 * Single-threaded; time O(triangles * level^2). options and progress may be
 * NULL. On failure *out is NULL. */
ISOFORM_API isoform_status isoform_compare(const isoform_mesh* mesh, const isoform_volume* reference_or_NULL,
                                           const isoform_compare_options* options,
                                           isoform_progress* progress, isoform_compare_report** out);

/* Number of surfaces measured ("linear", "loop", then "side-vertex" when
 * built), or 0 for NULL. */
ISOFORM_API int isoform_compare_report_surface_count(const isoform_compare_report* report);
/* The name of surface index, valid as long as the report; NULL when index is out of range. */
ISOFORM_API const char* isoform_compare_report_surface_name(const isoform_compare_report* report, int index);
/* Copies the measures of surface index. */
ISOFORM_API isoform_status isoform_compare_report_metrics(const isoform_compare_report* report, int index,
                                                          isoform_compare_metrics* out);
/* What deviation was measured from ("" without a reference) and its unit
 * ("world units" or "voxels"; "" without one); valid as long as the report. */
ISOFORM_API const char* isoform_compare_report_reference(const isoform_compare_report* report);
ISOFORM_API const char* isoform_compare_report_deviation_unit(const isoform_compare_report* report);
/* What the comparison had to leave out, one sentence per line ("" if
 * nothing); valid as long as the report. */
ISOFORM_API const char* isoform_compare_report_notes(const isoform_compare_report* report);

/* A new mesh: the tessellation of surface index at the report's level
 * (lattice points as vertices, shared along base edges, the surface's unit
 * normals; where a surface is undefined, the flat triangle's point). Free it
 * with isoform_mesh_free; it may be saved or copied out like any mesh. */
ISOFORM_API isoform_status isoform_compare_report_tessellation(const isoform_compare_report* report, int index,
                                                               isoform_mesh** out);

/* Writes report.json (every measure), samples.csv (the sample table: triangle,
 * u, v, then x y z deviation mean gauss per surface) and report.md (the table)
 * into directory, which must exist. Each file is written to a temporary name
 * and renamed once all three are complete; a failure leaves none of them
 * half-written (a failure between two renames can leave the earlier ones). */
ISOFORM_API isoform_status isoform_compare_report_write(const isoform_compare_report* report,
                                                        const char* directory);

ISOFORM_API void isoform_compare_report_free(isoform_compare_report* report);
/* Reduction (Hamann 1991, Chapter 5)                                 */
/* ------------------------------------------------------------------ */

/* How the point that replaces a removed triangle is made. */
typedef enum isoform_reduce_point {
  ISOFORM_REDUCE_POINT_QUADRATIC = 0, /* bivariate quadratic least squares in the triangle's
                                         plane (5.26-5.29), curvature by Theorem 5.5 */
  ISOFORM_REDUCE_POINT_QUADRIC = 1    /* implicit quadric through the platelet cut by the
                                         normal line (5.30-5.33), curvature by Theorem 5.6 */
} isoform_reduce_point;

typedef struct isoform_reduce_options {
  double keep_fraction;  /* fraction of the input's triangles to keep, (0, 1]; default 0.1.
                            1 leaves the mesh unchanged */
  double tolerance;      /* world units; 0 = off (default). A removal is refused when an
                            original vertex would lie farther than this from the triangle it
                            is tracked on, or the new point farther from the original
                            triangles around those vertices (docs/reduce.md); the reduction
                            then stops when nothing else can go */
  int lock_boundary;     /* 1: never remove a triangle touching the mesh boundary, so every
                            boundary vertex stays (Remark 5.8); default 0 */
  int point_method;      /* isoform_reduce_point; default ISOFORM_REDUCE_POINT_QUADRATIC */
  int graph;             /* 1: the mesh is a graph z = f(x, y); its (x, y) domain stays
                            covered (boundary points stay on straight boundary lines).
                            Every triangle must turn counterclockwise seen from +z (else
                            ISOFORM_ERR_INVALID_ARGUMENT names the first that does not);
                            default 0 */
  double graph_rms_tolerance; /* graph only, world units: stop before the RMS height error at
                            the original vertices (5.41) exceeds it (Remark 5.10); 0 = off */
  int swaps;             /* 1 (default): diagonal swaps after the fan (Definition 5.15) */
  int measure_error;     /* 1: report the distance between the input and the result in
                            isoform_reduce_stats.max_distance without bounding it (with
                            tolerance 0: measured once on the result, a few point-triangle
                            tests per original vertex); default 0 */
  int refine_point;      /* 1 (default): beyond the seed, move each new point along its
                            normal (graph: vertically) to the least-squares best place for
                            the original vertices under its triangles; 0: the seed's point */
  int vertex_fallback;   /* 1 (default): beyond the seed, when the fitted point fails the
                            half-plane test or a guard on a closed corona, try T's vertices in
                            its place (nearest first), then a point at the fitted height
                            above the platelet polygon's kernel (where the polygon is
                            star-shaped), as near the fitted point as the kernel allows;
                            0: refuse as the seed does */
  int manifold_parts_only; /* 1: instead of failing on bad input, reduce the parts (triangles
                            joined by shared edges) that pass every check of isoform_reduce and
                            copy the others unchanged; keep_fraction then applies to the
                            reducible parts' triangles (isoform_mesh_reduce_left_alone says
                            why each other part was left); default 0 */
  int prevent_overlap;   /* 1: beyond the seed, refuse a removal whose new triangles would
                            cross a triangle outside its neighbourhood, so that the result does
                            not overlap itself where two sheets of the input lie close (thin
                            bone, say) and can be reduced again; about 3 times the time;
                            default 0 */
} isoform_reduce_options;

ISOFORM_API void isoform_reduce_options_default(isoform_reduce_options* options);

/* What the last isoform_reduce on a mesh did. */
typedef struct isoform_reduce_stats {
  long long triangles_before, triangles_after;
  long long vertices_before, vertices_after;
  long long removals;       /* triangles replaced by a point */
  long long swaps;          /* diagonal swaps made */
  long long vertex_points;  /* removals whose new point is a vertex of T (vertex_fallback) */
  int passes;               /* passes of Remark 5.9 */
  int curvature_computed;   /* 1: the mesh had no curvature, Chapter 4 ran first */
  int stop_reason;          /* 0 target reached, 1 nothing more removable, 2 tolerance,
                               3 graph RMS tolerance */
  double max_distance;      /* world units, an upper bound of the distance of every input
                               vertex to the result and of every result vertex to the
                               input: with a tolerance the largest tracked in the
                               removals, else (measure_error) measured on the result;
                               0 when neither is on */
  double graph_rms;         /* RMS height error at the original vertices (graph RMS on) */
  /* Candidates refused when their turn came, by reason: */
  long long refused_corona;      /* corona discontinuous, cyclic or too small (Def. 5.3, 5.4) */
  long long refused_half_plane;  /* the inserted point fails the half-plane test (Thm 5.3) */
  long long refused_flip;        /* a new triangle would turn over or be degenerate */
  long long refused_nonmanifold; /* an edge of three triangles or a duplicate triangle */
  long long refused_boundary;    /* boundary locked, or (graph) the domain would shrink */
  long long refused_tolerance;   /* a tolerance would be exceeded */
  long long parts_left_alone;    /* manifold_parts_only: parts copied unchanged (else 0) */
  long long triangles_left_alone;/* the triangles of those parts */
  long long refused_overlap;     /* a new triangle would cross another (prevent_overlap) */
  long long kernel_points;       /* removals whose new point lies above the platelet
                                    polygon's kernel (vertex_fallback, tried last) */
} isoform_reduce_stats;

/* Reduces mesh in place by iterative triangle removal (Chapter 5): the
 * lightest triangle (angle weight times absolute curvature at its vertices)
 * that passes the tests is replaced by one point, until keep_fraction of the
 * triangles remain or a tolerance stops it. Curvature is computed first
 * (isoform_curvature with ISOFORM_CURVATURE_CUBIC) when the mesh has none. Keeps the Euler
 * characteristic, genus and parts; recomputes neighbours, parts and stats;
 * drops colours and loose edges. A non-manifold or inconsistently oriented
 * mesh, NaN coordinates, a triangle using a vertex twice, or two triangles
 * that intersect beyond the vertices they share give
 * ISOFORM_ERR_INVALID_ARGUMENT naming the first offending edge, vertex or
 * triangles (unless manifold_parts_only); on any failure or cancel the mesh
 * is unchanged. About O(n log n); options and progress may be NULL. */
ISOFORM_API isoform_status isoform_reduce(isoform_mesh* mesh, const isoform_reduce_options* options,
                                          isoform_progress* progress);

/* The stats of the last isoform_reduce on mesh; ISOFORM_ERR_INVALID_ARGUMENT
 * when it was never reduced. */
ISOFORM_API isoform_status isoform_mesh_reduce_stats(const isoform_mesh* mesh, isoform_reduce_stats* out);

/* Why part index (0 to parts_left_alone - 1) was left alone by the last
 * isoform_reduce with manifold_parts_only: "part of N triangles from
 * triangle T: <its first problem>", triangle numbers of the input. Valid
 * until the mesh is next reduced or freed; NULL when index is out of range
 * or mesh is NULL. */
ISOFORM_API const char* isoform_mesh_reduce_left_alone(const isoform_mesh* mesh, long long index);

/* ------------------------------------------------------------------ */
/* Side-vertex surfaces (Hamann 1991, Chapter 6)                      */
/* ------------------------------------------------------------------ */

/* A smooth surface over a triangle mesh with vertex normals: over each
 * triangle, three building blocks made by radial projection from each vertex
 * to a conic on the opposite edge, blended. It passes through every vertex
 * with the given normal there and is tangent-plane continuous across every
 * edge (neighbouring patches share each edge's conic and the normals along
 * it). Parameters: triangle t of the mesh's triangle table and barycentric
 * (u, v), weight 1-u-v on its first vertex, u on its second, v on its third;
 * u, v >= 0, u + v <= 1. Coordinates are the mesh's (world units). */
typedef struct isoform_patch isoform_patch;

typedef enum isoform_patch_blend {
  ISOFORM_PATCH_BLEND_PRINTED = 0, /* w_i ~ u_j u_k, as printed in (6.2)-(6.3) */
  ISOFORM_PATCH_BLEND_SQUARED = 1  /* w_i ~ (u_j u_k)^2: Theorem 6.1 (iii) holds (default:
                                      fewer sharp turns near edges, docs/patch.md) */
} isoform_patch_blend;

typedef struct isoform_patch_options {
  int blend;        /* isoform_patch_blend; default ISOFORM_PATCH_BLEND_SQUARED */
  double tension;   /* weight omega of every conic, > 0 (about omega where it is below
                       the automatic sin(gamma/2), never above it; lower pulls the
                       surface toward the triangles); 0 (default) = automatic,
                       sin(gamma/2) of Theorem 6.3 */
  size_t edge_tension_count;            /* per-edge weights given below; default 0 */
  const int32_t* edge_tension_vertices; /* 2 per edge: its vertex indices (either order);
                                           default NULL; copied at create */
  const double* edge_tension_values;    /* 1 per edge: omega > 0 (as tension); default NULL */
} isoform_patch_options;

ISOFORM_API void isoform_patch_options_default(isoform_patch_options* options);

/* What isoform_patch_create met. */
typedef struct isoform_patch_stats {
  long long triangles, edges;
  long long nonconvex_edges;       /* edge conics with an inflection (Definition 6.3) */
  long long opposite_normal_edges; /* edges whose end normals are opposite: a finite curve
                                      in the plane of the chord and the first normal */
  long long fallback_plane_edges;  /* edges whose data define no conic plane */
} isoform_patch_stats;

/* Builds the surface over mesh (copied: the mesh may be freed after) from
 * its points, triangles and normals. options may be NULL (defaults). Errors
 * (ISOFORM_ERR_INVALID_ARGUMENT, naming the vertex or triangle): normals
 * missing, zero or not finite; a triangle with a repeated or coincident
 * vertex; bad options or an edge weight for an edge the mesh lacks.
 * Non-manifold and open meshes are accepted. O(n log n). */
ISOFORM_API isoform_status isoform_patch_create(const isoform_mesh* mesh, const isoform_patch_options* options,
                                                isoform_patch** out);

ISOFORM_API void isoform_patch_free(isoform_patch* patch);

ISOFORM_API isoform_status isoform_patch_stats_get(const isoform_patch* patch, isoform_patch_stats* out);

/* Evaluates count samples: sample k is triangle triangles[k] at
 * (uv[2k], uv[2k+1]). Writes 3 doubles per sample to points and to normals
 * (the exact unit normal, du x dv, oriented like the triangle's winding;
 * NULL skips them). ISOFORM_ERR_INVALID_ARGUMENT, naming the first bad
 * sample, for a triangle out of range, (u, v) outside the triangle, or data
 * that leave the surface undefined there; outputs are then unspecified.
 * Runs on all cores (TBB) for large counts; thread-safe on one patch. */
ISOFORM_API isoform_status isoform_patch_evaluate(const isoform_patch* patch, size_t count, const int32_t* triangles,
                                                  const double* uv, double* points, double* normals);

/* Tessellates the surface into a new mesh: each triangle into 4^level
 * triangles (2^level steps per edge), level 0..10. Samples on a mesh edge
 * are computed once from its shared curve, so the result is closed and
 * manifold wherever the input is. Vertex normals are the exact normals,
 * turned to the side of the input normals; no vertex is NaN (where the data
 * leave the surface undefined, the flat triangle's point). progress may be
 * NULL; stage ISOFORM_STAGE_PATCH. */
ISOFORM_API isoform_status isoform_patch_tessellate(const isoform_patch* patch, int level,
                                                    isoform_progress* progress, isoform_mesh** out);

/* 1 when the mesh's normals were estimated from its points (it was read from
 * a file without normals, or made from arrays), 0 when they came from the
 * file, a contour or isoform_mesh_set_normals. */
ISOFORM_API int isoform_mesh_normals_estimated(const isoform_mesh* mesh);

#ifdef __cplusplus
}
#endif

#endif /* ISOFORM_H */
