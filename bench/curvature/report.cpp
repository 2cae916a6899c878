// The benchmark's table (one per mesh) and its JSON, as ratios against
// isoform's default method within the same run.
#include <cstdio>

#include "curvature_bench.h"

namespace isoform_curvature_bench {
namespace {

// Vertices per second per core: from CPU time (which sums the threads) or
// from wall time times the threads.
double cpu_rate(double vertices, const Timing& t) { return t.cpu > 0 ? vertices / t.cpu : 0.0; }
double wall_rate(double vertices, const Timing& t, int threads) {
  return t.wall > 0 ? vertices / t.wall / threads : 0.0;
}
bool has(const Timing& t) { return t.wall > 0; }
double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

Json rms_json(const isoform::truth::Rms& r) {
  return Json{{"H", r.mean}, {"K", r.gauss}, {"k1", r.k1}, {"k2", r.k2}};
}

Json ratio_json(const isoform::truth::Rms& r, const isoform::truth::Rms& base) {
  return Json{{"H", ratio(r.mean, base.mean)}, {"K", ratio(r.gauss, base.gauss)}, {"k1", ratio(r.k1, base.k1)},
              {"k2", ratio(r.k2, base.k2)}};
}

Json timing_json(double n, const Timing& t, int threads) {
  return Json{{"wall_seconds", t.wall},
              {"cpu_seconds", t.cpu},
              {"vertices_per_second_per_core_cpu", cpu_rate(n, t)},
              {"vertices_per_second_per_core_wall", wall_rate(n, t, threads)}};
}

}  // namespace

Json case_json(const Case& c, const std::vector<Result>& results) {
  const double n = double(c.vertex_count());
  const Result& base = results.front();
  Json rows = Json::array();
  for (const Result& r : results) {
    Json row{{"method", r.method},
             {"one_thread", timing_json(n, r.one, 1)},
             {"speed_vs_default_1_thread_cpu", ratio(cpu_rate(n, r.one), cpu_rate(n, base.one))},
             {"rms", rms_json(r.rms)},
             {"rms_vs_default", ratio_json(r.rms, base.rms)},
             {"extra", r.extra}};
    if (has(r.two)) {
      row["two_threads"] = timing_json(n, r.two, 2);
      row["same_bits_1_and_2_threads"] = r.same_bits;
    }
    if (!r.setup_what.empty()) row["setup"] = Json{{"what", r.setup_what}, {"wall_seconds", r.setup_seconds}};
    rows.push_back(row);
  }
  return Json{{"mesh", c.name},
              {"vertices", c.vertex_count()},
              {"triangles", c.triangles.size() / 3},
              {"jitter", c.jitter},
              {"results", rows}};
}

void print_case(const Case& c, const std::vector<Result>& results) {
  const double n = double(c.vertex_count());
  const Result& base = results.front();
  std::printf("\n%s: %zu vertices, %zu triangles\n", c.name.c_str(), c.vertex_count(), c.triangles.size() / 3);
  std::printf("%-31s %6s %6s %6s %6s %6s | %8s %8s %8s %8s | %6s %6s %6s %6s\n", "", "cpu", "cpu", "wall", "wall",
              "speed", "RMS H", "RMS K", "RMS k1", "RMS k2", "H", "K", "k1", "k2");
  std::printf("%-31s %6s %6s %6s %6s %6s | %35s | %27s\n", "method", "1 thr", "2 thr", "1 thr", "2 thr", "vs def",
              "against exact", "RMS / default's RMS");
  for (const Result& r : results) {
    char two_cpu[16] = "serial", two_wall[16] = "serial";
    if (has(r.two)) {
      std::snprintf(two_cpu, sizeof two_cpu, "%.3f%s", cpu_rate(n, r.two) / 1e6, r.same_bits ? "" : "*");
      std::snprintf(two_wall, sizeof two_wall, "%.3f", wall_rate(n, r.two, 2) / 1e6);
    }
    std::printf("%-31s %6.3f %6s %6.3f %6s %6.3f | %8.2e %8.2e %8.2e %8.2e | %6.2f %6.2f %6.2f %6.2f\n",
                r.method.c_str(), cpu_rate(n, r.one) / 1e6, two_cpu, wall_rate(n, r.one, 1) / 1e6, two_wall,
                ratio(cpu_rate(n, r.one), cpu_rate(n, base.one)), r.rms.mean, r.rms.gauss, r.rms.k1, r.rms.k2,
                ratio(r.rms.mean, base.rms.mean), ratio(r.rms.gauss, base.rms.gauss), ratio(r.rms.k1, base.rms.k1),
                ratio(r.rms.k2, base.rms.k2));
  }
  for (const Result& r : results)
    if (!r.setup_what.empty() && r.method.rfind("isoform quartic", 0) == 0)
      std::printf("  (not in the table: %s, %.3f s wall)\n", r.setup_what.c_str(), r.setup_seconds);
}

}  // namespace isoform_curvature_bench
