// The consolidation pressure p0 of Cam-clay snow as a function of its plastic volume change
// (DESIGN.md section 4, snow_cam_clay; issue 16). With eps = -ln J_P (> 0 compacted) and the
// plastic density rho_P = rho0 / J_P = rho0 e^eps:
//   compaction, eps >= 0:         p0 = p_c0 exp((rho_P - rho0) / rho_h)
//   dilation, -eps_s < eps < 0:   p0 = p_c0 (1 + eps / eps_s)
//   eps <= -eps_s:                p0 = 0 (no strength left: the snow has broken apart)
// The compaction branch is an exponential in density, the form that laboratory and field
// compaction of snow follows: final density depends on the applied pressure and hardly on the
// initial density (Richmond 1995, CRREL Report 95-7: final density against peak contact pressure
// for snow of initial density 0.11-0.25 Mg/m^3; fitted in data/snow/). Writing it in rho_P rather than in eps makes one law serve every initial density:
// p0 = [p_c0 e^(-rho0 / rho_h)] e^(rho_P / rho_h). Its scale rho_h is a density, its own parameter
// and independent of the elastic bulk modulus (cf. the NACC hardening of Wolper et al. 2019, ACM
// TOG 38(4):119, p0 = K sinh(xi max(-ln J_P, 0)), which ties the two together and leaves no
// strength once J_P > 1). The dilation branch removes the cohesion beta p0 linearly over a
// plastic dilation eps_s, the softening the thesis' future work asks for (section 6.3).
#pragma once

#include <cmath>

#include "kernels/hd.hpp"

namespace firn {

template <class T>
struct CamClayHardening {
  T p_c0;   // consolidation pressure at the rest density (Pa)
  T rho0;   // rest density (kg/m^3)
  T rho_h;  // compaction hardening density scale (kg/m^3)
  T eps_s;  // plastic dilation -ln J_P that removes all strength

  // p0(eps).
  FIRN_HD T pressure(T eps) const {
    if (eps >= T(0)) return p_c0 * std::exp((rho0 * std::exp(eps) - rho0) / rho_h);
    if (eps > -eps_s) return p_c0 * (T(1) + eps / eps_s);
    return T(0);
  }
};

}  // namespace firn
