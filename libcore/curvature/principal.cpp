// Principal curvatures of a height-field graph from its first and second
// fundamental forms (4.14, 4.15).
#include "principal.h"

#include "principal_lanes.h"
#include "vector_level.h"

namespace isoform {

PrincipalCurvatures principal_curvatures(const HeightFit& f, const Eigen::Vector3d& b1,
                                         const Eigen::Vector3d& b2, const Eigen::Vector3d& n) {
  return principal_curvatures_inline(f, b1, b2, n);
}

namespace {

ISOFORM_LANES_INLINE void principal4_body(const HeightFit (&f)[4], const Eigen::Vector3d (&b1)[4],
                                          const Eigen::Vector3d (&b2)[4], const Eigen::Vector3d (&n)[4],
                                          PrincipalCurvatures (&out)[4]) {
  const HeightFitLanes fit = {Lanes4{f[0].fu, f[1].fu, f[2].fu, f[3].fu}, Lanes4{f[0].fv, f[1].fv, f[2].fv, f[3].fv},
                              Lanes4{f[0].fuu, f[1].fuu, f[2].fuu, f[3].fuu},
                              Lanes4{f[0].fuv, f[1].fuv, f[2].fuv, f[3].fuv},
                              Lanes4{f[0].fvv, f[1].fvv, f[2].fvv, f[3].fvv}};
  const PrincipalLanes p = principal_curvatures_lanes(fit, vec3_lanes(b1), vec3_lanes(b2), vec3_lanes(n));
  for (int l = 0; l < 4; ++l) out[l] = principal_of_lane(p, l);
}

void principal4_plain(const HeightFit (&f)[4], const Eigen::Vector3d (&b1)[4], const Eigen::Vector3d (&b2)[4],
                      const Eigen::Vector3d (&n)[4], PrincipalCurvatures (&out)[4]) {
  principal4_body(f, b1, b2, n, out);
}

#ifdef ISOFORM_AVX_CLONE
ISOFORM_AVX_TARGET void principal4_avx(const HeightFit (&f)[4], const Eigen::Vector3d (&b1)[4],
                                       const Eigen::Vector3d (&b2)[4], const Eigen::Vector3d (&n)[4],
                                       PrincipalCurvatures (&out)[4]) {
  principal4_body(f, b1, b2, n, out);
}
#endif

}  // namespace

void principal_curvatures4(const HeightFit (&f)[4], const Eigen::Vector3d (&b1)[4], const Eigen::Vector3d (&b2)[4],
                           const Eigen::Vector3d (&n)[4], PrincipalCurvatures (&out)[4]) {
#ifdef ISOFORM_AVX_CLONE
  if (vector_level() > 0) return principal4_avx(f, b1, b2, n, out);
#endif
  principal4_plain(f, b1, b2, n, out);
}

}  // namespace isoform
