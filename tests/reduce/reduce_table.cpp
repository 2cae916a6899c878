// Writes Table 5.1 into docs/reduce.md, between the lines
// "<!-- table51 begin -->" and "<!-- table51 end -->": the seed's RMS errors
// (5.41) beside isoform's for the nine graphs reduced by 50, 80 and 90 %,
// with the seed's point (refine off) and with isoform's default.
// Usage: reduce_table DOC.md
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "table51.h"

using namespace isoform;

namespace {

std::string table(bool refine) {
  std::ostringstream out;
  out << "| function | seed 50% | isoform 50% | seed 80% | isoform 80% | seed 90% | isoform 90% |\n";
  out << "|---|---:|---:|---:|---:|---:|---:|\n";
  const auto& graphs = truth::table41_graphs();
  for (size_t i = 0; i < graphs.size(); ++i) {
    const auto seed = table51::seed_row(int(i));
    out << "| " << i + 1 << ". " << graphs[i].name << " `" << graphs[i].formula << "` ";
    for (int c = 0; c < 3; ++c) {
      ReduceOptions o;
      o.refine_point = refine;
      const table51::Result r = table51::measure(graphs[i], table51::kRemoved[c], o);
      char buf[128];
      std::snprintf(buf, sizeof buf, "| %.6f | %s%.6f%s ", seed[size_t(c)], r.rms <= seed[size_t(c)] + 1e-12 ? "" : "**",
                    r.rms, r.rms <= seed[size_t(c)] + 1e-12 ? "" : "**");
      out << buf;
      std::cerr << graphs[i].name << " " << table51::kRemoved[c] << (refine ? " refined" : " seed point") << ": "
                << r.rms << " (" << r.triangles_after << " triangles, " << r.stats.passes << " passes)\n";
    }
    out << "|\n";
  }
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {
    std::cerr << "usage: reduce_table DOC.md\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str(), begin = "<!-- table51 begin -->\n", end = "<!-- table51 end -->";
  const size_t b = text.find(begin), e = text.find(end);
  if (b == std::string::npos || e == std::string::npos || e < b) {
    std::cerr << argv[1] << ": no table51 begin/end markers\n";
    return 1;
  }
  std::string body = "With isoform's default (the point refined, `refine_point` on):\n\n" + table(true) +
                     "\nWith the seed's point (`refine_point` off), everything else the same:\n\n" + table(false);
  std::ofstream out(argv[1]);
  out << text.substr(0, b + begin.size()) << body << text.substr(e);
  return out ? 0 : 1;
}
