// The elastic deformation gradient after a return mapping that scales the deviator of the
// isochoric elastic left Cauchy-Green tensor and sets the elastic volume (DESIGN.md section 4):
// given the trial F_tr = U diag(sigma_tr) V^T (svd3), bbar_tr = J_tr^(-2/3) b_tr with mean
// Ibar = tr(bbar_tr) / 3 and principal deviations d_i = J_tr^(-2/3) sigma_tr_i^2 - Ibar, it returns
// F = U diag(sigma) V^T with
//   dev(bbar) = keep dev(bbar_tr)   and   det F = J_new.
// Only J and dev(bbar) enter the stress of an isochoric-volumetric split energy, so the trace part
// of bbar is free: it is the x with det(x I + keep dev(bbar_tr)) = 1 (the volume-preserving variant
// of Simo and Hughes, Computational Inelasticity, Box 9.1 step 4; cf. Simo 1992, CMAME 99:61-112),
// and sigma_i = J_new^(1/3) sqrt(x + keep d_i). Used by the J2 radial return (keep = 1 - beta,
// J_new = J_tr) and the Cam-clay return (keep = q / q_tr, J_new from the returned pressure).
#pragma once

#include <cmath>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/svd3.hpp"

namespace firn {

template <class T>
FIRN_HD Mat3<T> rescale_isochoric_deviator(const Mat3<T>& U, const Vec3<T>& sigma_tr, const Mat3<T>& V, T Jm23,
                                           T Ibar, T keep, T J_new) {
  // h(x) = prod(x + c_i) - 1 is increasing and convex where all factors are positive, and
  // h(Ibar) >= 0 for keep <= 1 (for fixed trace the product grows as the deviation shrinks), so
  // Newton from x = Ibar decreases monotonically to the root without leaving that region.
  Vec3<T> c;
  for (int d = 0; d < 3; ++d) c[d] = keep * (Jm23 * sigma_tr[d] * sigma_tr[d] - Ibar);
  T x = Ibar;
  for (int it = 0; it < 32; ++it) {
    const T a0 = x + c[0], a1 = x + c[1], a2 = x + c[2];
    const T h = a0 * a1 * a2 - T(1);
    const T step = h / (a0 * a1 + a1 * a2 + a0 * a2);
    x -= step;
    if (!(step > T(4) * FloatLimits<T>::kEpsilon * x)) break;
  }
  Vec3<T> s_new;
  for (int d = 0; d < 3; ++d) s_new[d] = std::sqrt(x + c[d]);
  // Rescale by (J_new / prod)^(1/3): J_new^(1/3) from bbar -> b_e, and the rounding left in prod(x + c_i).
  const T scale = std::cbrt(J_new / (s_new[0] * s_new[1] * s_new[2]));
  for (int d = 0; d < 3; ++d) s_new[d] *= scale;
  return svd_compose(U, s_new, V);
}

}  // namespace firn
