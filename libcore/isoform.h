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
#define ISOFORM_VERSION 100

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
  ISOFORM_STAGE_DONE = 5
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
} isoform_grid_info;

/* Opens a volume file: OpenVDB (.vdb) or NRRD (.nrrd, .nhdr; raw or gzip
 * encoding). Grid metadata is read at once; voxel data when a grid is first
 * used. Errors name the file: missing, not a VDB, truncated, and so on. */
ISOFORM_API isoform_status isoform_volume_open(const char* path, isoform_volume** out);

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
 * STL corners are welded. Normals are read from PLY/OBJ when present,
 * otherwise estimated as in isoform_mesh_from_arrays. */
ISOFORM_API isoform_status isoform_mesh_load(const char* path, isoform_mesh** out);

/* Writes binary PLY (x y z nx ny nz per vertex; vertex_indices and part per
 * face), OBJ (v, vn, f) or binary STL, chosen by the extension of path.
 * Written to a temporary file beside path and renamed, so a failure never
 * leaves half a file. */
ISOFORM_API isoform_status isoform_mesh_save(const isoform_mesh* mesh, const char* path);

ISOFORM_API void isoform_mesh_free(isoform_mesh* mesh);

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

#ifdef __cplusplus
}
#endif

#endif /* ISOFORM_H */
