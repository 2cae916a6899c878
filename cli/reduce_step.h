// The reduction step that `reduce` and `contour --reduce` share: the keep
// fraction as the user writes it, the call with a progress bar, the summary.
#pragma once

#include <ostream>
#include <string>

#include "cli.h"
#include "progress.h"
#include "report.h"

namespace isoform::cli {

struct ReduceSettings {
  double keep_fraction = 0.1;
  double tolerance = 0.0;
  bool lock_boundary = false;
  std::string point = "quadratic";  // quadratic | quadric
  bool refine_point = true;          // false: the seed's point on the fitted surface
  bool manifold_parts = false;       // reduce the parts that pass the checks, copy the others
  bool prevent_overlap = false;      // refuse removals whose triangles would cross others
  bool graph = false;                // a height field z = f(x, y) (Table 5.1's graph mode)
  double rms_tolerance = 0.0;        // graph: stop before the RMS height error exceeds it (0: off)
};

// "10%" or "0.1" as a number (no range checked); Failure naming `flag` when
// the text is neither.
double parse_share(const std::string& text, const std::string& flag);
// The same as a fraction in (0, 1]; Failure naming `flag` otherwise.
double parse_fraction(const std::string& text, const std::string& flag);

// Runs isoform_reduce on mesh (the error measured as well) and returns the
// seconds it took. Failures name `input` (in place of the library's
// "reduce: ").
double reduce_mesh(isoform_mesh* mesh, const ReduceSettings& settings, const std::string& input,
                   const ProgressOptions& progress);

Json reduce_json(const isoform_mesh* mesh, double seconds);
// The RMS height error at the original vertices of a graph-mode reduction.
double graph_rms(const isoform_mesh* mesh);
void print_reduce(std::ostream& out, const isoform_mesh* mesh, double seconds);

}  // namespace isoform::cli
