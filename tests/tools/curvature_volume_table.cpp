// Writes Table 4.2 of Hamann (1991) as isoform measures it into the table
// section of docs/curvature-volume.md (between the markers), the seed's
// printed value beside each of isoform's. Run by hand after changing a method:
//   build/tests/tools/curvature_volume_table docs/curvature-volume.md
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "graph_table.h"

namespace {

using namespace isoform::table42;

const char* const kBegin = "<!-- table-4.2 begin: written by tests/tools/curvature_volume_table -->";
const char* const kEnd = "<!-- table-4.2 end -->";

// The seed's numbers as docs/curvature-volume.md reads the damaged table:
// pairs (H, K) in reading order for q1, q2, the cubic and the cosine; "lost"
// where the text has none.
const char* const kSeed[5][2] = {
    {"0", "0"}, {".002950", ".002597"}, {".001115", ".002216"}, {".002545", "lost"}, {".001207", "lost"}};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", v);
  return text;
}

std::string fallbacks(const Errors& e) {
  std::ostringstream out;
  const char* names[isoform::kGraphFitCount] = {"centred", "shifted", "reduced", "platelet", "one-sided platelet", "none"};
  bool first = true;
  for (int f = 0; f < isoform::kGraphFitCount; ++f)
    if (e.fits[size_t(f)]) {
      out << (first ? "" : ", ") << e.fits[size_t(f)] << " " << names[f];
      first = false;
    }
  return out.str();
}

std::string table() {
  std::ostringstream out;
  out << kBegin << "\n\n"
      << "RMS errors over all 26^3 points (and, in brackets, over the 24^3 interior points).\n\n"
      << "| function | seed's H | seed's K | seed's method H (ours) | seed's method K (ours) "
         "| default H | default K |\n"
      << "|---|---|---|---|---|---|---|\n";
  std::ostringstream fits;
  fits << "\nFits used per point (of 17,576):\n\n| function | seed's method | default |\n|---|---|---|\n";
  for (size_t i = 0; i < functions().size(); ++i) {
    const Function& f = functions()[i];
    const Errors s = measure(f, Column::Seed), d = measure(f, Column::Default);
    out << "| `" << f.name << "` | " << kSeed[i][0] << " | " << kSeed[i][1] << " | " << number(s.rms_mean_all)
        << " (" << number(s.rms_mean_interior) << ") | " << number(s.rms_gauss_all) << " ("
        << number(s.rms_gauss_interior) << ") | " << number(d.rms_mean_all) << " (" << number(d.rms_mean_interior)
        << ") | " << number(d.rms_gauss_all) << " (" << number(d.rms_gauss_interior) << ") |\n";
    fits << "| `" << f.name << "` | " << fallbacks(s) << " | " << fallbacks(d) << " |\n";
  }
  out << fits.str() << "\nThe seed's method with the exact (analytic) gradient instead of the grid's, "
      << "interior RMS H / K, for comparison:\n\n";
  for (const Function& f : functions()) {
    const Errors x = measure(f, Column::SeedExactGradient);
    out << "- `" << f.name << "`: " << number(x.rms_mean_interior) << " / " << number(x.rms_gauss_interior)
        << " (all points: " << number(x.rms_mean_all) << " / " << number(x.rms_gauss_all) << ")\n";
  }
  out << "\n" << kEnd;
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: curvature_volume_table docs/curvature-volume.md\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  std::string doc = text.str();
  const size_t begin = doc.find(kBegin), end = doc.find(kEnd);
  if (!in || begin == std::string::npos || end == std::string::npos || end < begin) {
    std::cerr << argv[1] << ": no table markers found\n";
    return 1;
  }
  doc.replace(begin, end + std::string(kEnd).size() - begin, table());
  std::ofstream out(argv[1]);
  out << doc;
  if (!out) {
    std::cerr << argv[1] << ": cannot be written\n";
    return 1;
  }
  std::cout << "wrote Table 4.2 into " << argv[1] << "\n";
  return 0;
}
