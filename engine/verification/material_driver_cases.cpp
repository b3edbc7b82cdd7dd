// Material-point driver problems (DESIGN.md section 6, problem 5): each constitutive model with the
// thesis' parameters (material_catalog.cpp presets) along homogeneous paths (material_driver.hpp).
// Every row is one check; its error and bound are stated beside it. Rows carry level 0, dx 0,
// one particle and the number of increments as steps.
#include "engine/verification/material_driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "engine/materials.hpp"
#include "engine/verification/verification.hpp"
#include "kernels/svd3.hpp"

namespace firn {
namespace {

double max_abs(const Mat3<double>& a) {
  double m = 0;
  for (double x : a.m) m = std::max(m, std::abs(x));
  return m;
}

double dev_norm(const Mat3<double>& a) {
  Mat3<double> d = a;
  for (int i = 0; i < 3; ++i) d(i, i) -= trace(a) / 3;
  return std::sqrt(ddot(d, d));
}

// Times one check and appends its row.
struct Rows {
  std::string problem;
  std::vector<VerificationRow> rows;
  void add(const std::string& check, long increments, double bound, const std::function<double()>& error) {
    const auto t0 = std::chrono::steady_clock::now();
    const double e = error();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rows.push_back({problem + ":" + check, 0, 0, 1, increments, e, bound, seconds});
  }
};

// tau(F = I) relative to the P-wave modulus: zero up to rounding (of the polar rotation for Stomakhin).
double zero_stress_error(const MaterialModel<double>& model) {
  return std::visit(
      [](const auto& m) {
        PlasticState<double> s;
        return max_abs(m.kirchhoff(Mat3<double>::identity(), s)) / m.p_wave_modulus(s);
      },
      model);
}

// Objectivity: a superposed rotation Q(t) (a full turn about a skew axis) must give Q tau Q^T and
// the same plastic state. Error: largest deviation relative to the largest stress, and of the state.
double objectivity_error(const MaterialModel<double>& model, const DeformationPath& path, int increments) {
  const Vec3<double> axis = {{1, -2, 0.5}};
  const double angle = 2 * M_PI;
  const DriverHistory a = drive_material(model, path, increments);
  const DriverHistory b = drive_material(model, paths::rotated(path, axis, angle), increments);
  double scale = 0;
  for (const auto& t : a.tau) scale = std::max(scale, max_abs(t));
  double e = 0;
  for (int k = 0; k <= increments; ++k) {
    const Mat3<double> Q = axis_angle_rotation(axis, angle * k / increments);
    e = std::max(e, max_abs(b.tau[k] - mul_transposed(Q * a.tau[k], Q)) / scale);
    e = std::max(e, std::abs(b.state[k].alpha - a.state[k].alpha) / std::max(a.state.back().alpha, 1e-300));
    e = std::max(e, std::abs(b.state[k].Jp - a.state[k].Jp));
  }
  return e;
}

// Deviation of the final stress and state of an N-increment run from a 100 N reference, relative.
double substep_error(const MaterialModel<double>& model, const DeformationPath& path, int increments) {
  const DriverHistory coarse = drive_material(model, path, increments);
  const DriverHistory fine = drive_material(model, path, 100 * increments);
  const double e_tau = max_abs(coarse.tau.back() - fine.tau.back()) / max_abs(fine.tau.back());
  const double e_alpha = fine.state.back().alpha > 0
                             ? std::abs(coarse.state.back().alpha - fine.state.back().alpha) / fine.state.back().alpha
                             : 0;
  return std::max({e_tau, e_alpha, std::abs(coarse.state.back().Jp - fine.state.back().Jp)});
}

std::vector<VerificationRow> verify_hyperelastic_plastic() {
  Rows r{"material_driver_hyperelastic_plastic", {}};
  const MaterialInfo shell = preset_material_info("thesis_shell");
  const MaterialModel<double> model = make_material_model<double>(shell);
  const HyperelasticPlastic<double>& hp = std::get<HyperelasticPlastic<double>>(model);
  const double K = shell.moduli.K, G = shell.moduli.G;

  r.add("zero_stress", 0, 1e-14, [&] { return zero_stress_error(model); });

  // Pure volume change has no deviatoric stress, so it stays elastic down to J = 0.3 and back:
  // tau = K/2 (J^2 - 1) I (thesis Eq. 4.2) in closed form; any alpha is an error too. Bound: rounding.
  r.add("hydrostatic_closed_form", 200, 1e-12, [&] {
    const DriverHistory h = drive_material(model, paths::hydrostatic_cycle(0.3), 200);
    double e = 0;
    for (std::size_t k = 0; k < h.tau.size(); ++k) {
      const double J = determinant(h.F[k]);
      e = std::max({e, max_abs(h.tau[k] - (K / 2 * (J * J - 1)) * Mat3<double>::identity()) / K, h.state[k].alpha});
    }
    return e;
  });

  // Linear hardening in uniaxial strain eps, small strain: trial ||s|| = 2G sqrt(2/3) eps along the fixed
  // direction n = sqrt(2/3)(1, -1/2, -1/2), and the return 2G sqrt(2/3) eps - 2G dgamma = sqrt(2/3)(sigma_y0
  // + E_p alpha), alpha = sqrt(2/3) dgamma, give alpha = (2G eps - sigma_y0) / (3G + E_p) (also the axial
  // plastic strain). The model is finite-strain (dev of bbar_e, mu_bar = G tr(bbar_e)/3), which departs
  // from this at relative order eps / (eps - eps_y): bound 4 eps_end / (eps_end - eps_y) = 6 eps_end at
  // eps_end = 3 eps_y, eps_y = sigma_y0 / (2G).
  const double E_p = 0.1 * G, sigma_y0 = 100, eps_y = sigma_y0 / (2 * G), eps_end = 3 * eps_y;
  const MaterialModel<double> linear =
      make_material_model<double>(preset_material_info("thesis_shell", {{"hardening", 0}, {"E_p", E_p}}));
  r.add("linear_hardening_uniaxial_strain", 60, 6 * eps_end, [&] {
    const DriverHistory h = drive_material(linear, paths::uniaxial_strain(eps_end), 60);
    const double alpha_end = (2 * G * eps_end - sigma_y0) / (3 * G + E_p);
    double e = 0;
    for (std::size_t k = 0; k < h.F.size(); ++k) {
      const double eps = h.F[k](0, 0) - 1;
      const double exact = std::max(0.0, (2 * G * eps - sigma_y0) / (3 * G + E_p));
      e = std::max(e, std::abs(h.state[k].alpha - exact) / alpha_end);
    }
    return e;
  });

  // Yield surface after every return, on compaction to J = 0.3 with shear, simple shear and cyclic
  // loading: f = ||dev tau|| - sqrt(2/3) sigma_y(alpha) recomputed from the returned F_E, relative to
  // sqrt(2/3) sigma_y0; and det F_E = det F (isochoric flow). Bound: rounding (1e-10).
  r.add("yield_surface_and_volume", 3 * 400, 1e-10, [&] {
    double e = 0;
    for (const DeformationPath& path :
         {paths::compress_and_shear(0.3, 2.0), paths::simple_shear(1.0), paths::cyclic_uniaxial_strain(0.05, 3)}) {
      const DriverHistory h = drive_material(model, path, 400);
      for (std::size_t k = 0; k < h.F.size(); ++k) {
        const double f = dev_norm(h.tau[k]) - std::sqrt(2.0 / 3) * hp.hardening.yield_stress(h.state[k].alpha);
        e = std::max(e, f / (std::sqrt(2.0 / 3) * hp.hardening.sigma_y0));
        e = std::max(e, std::abs(determinant(h.F_E[k]) / determinant(h.F[k]) - 1));
      }
    }
    return e;
  });

  // Backward-Euler return: first order in the increment. Compaction to J = 0.3 with shear 2 in 40
  // increments against 4000; measured 4.3e-4, bound 1e-2.
  r.add("substep_compress_and_shear", 40, 1e-2,
        [&] { return substep_error(model, paths::compress_and_shear(0.3, 2.0), 40); });

  r.add("objectivity", 400, 1e-10, [&] { return objectivity_error(model, paths::compress_and_shear(0.3, 2.0), 400); });
  return r.rows;
}

std::vector<VerificationRow> verify_snow_stomakhin() {
  Rows r{"material_driver_snow_stomakhin", {}};
  const MaterialInfo snow = preset_material_info("thesis_stomakhin_snow");
  const MaterialModel<double> model = make_material_model<double>(snow);
  const SnowStomakhin<double>& sm = std::get<SnowStomakhin<double>>(model);

  r.add("zero_stress", 0, 1e-14, [&] { return zero_stress_error(model); });

  // Uniaxial compression F = diag(a, 1, 1) to a = 0.8 in closed form (Stomakhin et al. 2013): below
  // a = 1 - theta_c, F_E = diag(1 - theta_c, 1, 1) and J_P = a / (1 - theta_c); the fixed-corotated
  // stress of a diagonal F_E is tau_ii = 2 mu h (s_i - 1) s_i + lambda h (J_E - 1) J_E, h = e^(xi (1 - J_P)).
  // Error relative to the largest stress; bound: rounding.
  r.add("uniaxial_compression_closed_form", 40, 1e-12, [&] {
    const DriverHistory h = drive_material(model, paths::uniaxial_strain(-0.2), 40);
    double scale = 0;
    for (const auto& t : h.tau) scale = std::max(scale, max_abs(t));
    double e = 0;
    for (std::size_t k = 0; k < h.F.size(); ++k) {
      const double a = h.F[k](0, 0), s0 = std::max(a, 1 - sm.theta_c), Jp = a / s0;
      const double f = std::exp(sm.xi * (1 - Jp));
      const double s[3] = {s0, 1, 1};
      for (int i = 0; i < 3; ++i) {
        const double exact = 2 * sm.mu * f * (s[i] - 1) * s[i] + sm.lambda * f * (s0 - 1) * s0;
        e = std::max(e, std::abs(h.tau[k](i, i) - exact) / scale);
      }
      e = std::max(e, std::abs(h.state[k].Jp - Jp));
    }
    return e;
  });

  // Bookkeeping and clamp after every return, on compaction to J = 0.3 and back, compaction with shear,
  // cyclic loading: det(F_E) J_P = det F, and the singular values of F_E within [1 - theta_c, 1 + theta_s].
  // Relative error; bound: rounding.
  r.add("clamp_and_Jp_bookkeeping", 3 * 400, 1e-12, [&] {
    double e = 0;
    for (const DeformationPath& path :
         {paths::hydrostatic_cycle(0.3), paths::compress_and_shear(0.3, 2.0), paths::cyclic_uniaxial_strain(0.05, 3)}) {
      const DriverHistory h = drive_material(model, path, 400);
      for (std::size_t k = 0; k < h.F.size(); ++k) {
        e = std::max(e, std::abs(determinant(h.F_E[k]) * h.state[k].Jp / determinant(h.F[k]) - 1));
        Mat3<double> U, V;
        Vec3<double> s;
        svd3(h.F_E[k], U, s, V);
        for (int d = 0; d < 3; ++d) e = std::max({e, (1 - sm.theta_c) - s[d], s[d] - (1 + sm.theta_s)});
      }
    }
    return e;
  });

  // The clamp is applied once per increment, so a coarse path differs from a fine one; compaction with
  // shear in 40 increments against 4000: measured 5.2e-3, bound 2e-2.
  r.add("substep_compress_and_shear", 40, 2e-2,
        [&] { return substep_error(model, paths::compress_and_shear(0.5, 1.0), 40); });

  r.add("objectivity", 400, 1e-10, [&] { return objectivity_error(model, paths::compress_and_shear(0.3, 2.0), 400); });
  return r.rows;
}

// p = -tr(tau)/3 (positive in compression) and q = sqrt(3/2) ||dev tau|| of a Kirchhoff stress.
double mean_pressure(const Mat3<double>& tau) { return -trace(tau) / 3; }
double von_mises(const Mat3<double>& tau) { return std::sqrt(1.5) * dev_norm(tau); }

std::vector<VerificationRow> verify_snow_cam_clay() {
  Rows r{"material_driver_snow_cam_clay", {}};
  const MaterialInfo snow = preset_material_info("fresh_snow");
  const MaterialModel<double> model = make_material_model<double>(snow);
  const SnowCamClay<double>& cc = std::get<SnowCamClay<double>>(model);
  const double K = cc.elastic.K, p_c0 = cc.hardening.p_c0, rho0 = cc.hardening.rho0, rho_h = cc.hardening.rho_h;

  r.add("zero_stress", 0, 1e-14, [&] { return zero_stress_error(model); });

  // Hydrostatic compaction to J = 0.4 (220 to 550 kg/m^3, the CRREL range): q = 0 throughout and,
  // past the compressive tip, the Cauchy pressure p = p_tau / J = p0(rho_P). Closed form by
  // inverting the hardening law: from the returned p_tau, J_E = sqrt(1 - 2 p_tau / K) and
  // rho_P = rho0 + rho_h ln(p / p0(rest)), so J = J_E rho0 / rho_P; error |J(p) - det F| relative
  // to J (and q / p), where the model yielded. Bound: rounding of the return's root solve (1e-10).
  r.add("hydrostatic_compaction_closed_form", 400, 1e-10, [&] {
    const DriverHistory h = drive_material(model, paths::compress_and_shear(0.4, 0), 400);
    double e = 0;
    for (std::size_t k = 0; k < h.F.size(); ++k) {
      const double p_tau = mean_pressure(h.tau[k]), J = determinant(h.F[k]);
      e = std::max(e, von_mises(h.tau[k]) / std::max(p_tau, p_c0));
      if (h.state[k].Jp == 1) continue;  // still elastic
      const double rho_P = rho0 + rho_h * std::log(p_tau / J / p_c0);
      e = std::max(e, std::abs(std::sqrt(1 - 2 * p_tau / K) * rho0 / rho_P - J) / J);
    }
    return e;
  });

  // Dilation to J = 1.05: the tensile tip p_tau / J = -beta p0 with p0 = p0(rest) (1 + eps / eps_s),
  // eps = -ln J_P, softening to no strength at all; inverted like the row above. Error: the
  // closed form's deviation relative to J, and at the end the stress relative to p0(rest).
  // Bound: rounding (1e-10).
  r.add("dilation_softens_to_zero_cohesion", 400, 1e-10, [&] {
    const DriverHistory h = drive_material(model, paths::compress_and_shear(1.05, 0), 400);
    double e = max_abs(h.tau.back()) / p_c0 + cc.consolidation_pressure(h.state.back()) / p_c0;
    for (std::size_t k = 0; k < h.F.size(); ++k) {
      const double p_tau = mean_pressure(h.tau[k]), J = determinant(h.F[k]);
      if (h.state[k].Jp == 1 || cc.consolidation_pressure(h.state[k]) == 0) continue;  // elastic, or no strength left
      const double eps = cc.hardening.eps_s * (-p_tau / J / (cc.beta * p_c0) - 1);
      e = std::max(e, std::abs(std::sqrt(1 - 2 * p_tau / K) * std::exp(-eps) - J) / J);
    }
    return e;
  });

  // Yield surface after every return, on compaction with shear, simple shear and cyclic loading:
  // y(p, q) <= 0 recomputed from the returned Cauchy stress tau / J, relative to M^2 p0^2 at the
  // state's p0 (and p0(rest)), and det(F_E) J_P = det F. Bound: rounding (1e-9).
  r.add("yield_surface_and_volume", 3 * 400, 1e-9, [&] {
    double e = 0;
    for (const DeformationPath& path :
         {paths::compress_and_shear(0.5, 2.0), paths::simple_shear(1.0), paths::cyclic_uniaxial_strain(0.05, 3)}) {
      const DriverHistory h = drive_material(model, path, 400);
      for (std::size_t k = 0; k < h.F.size(); ++k) {
        const double J = determinant(h.F[k]);
        const double p = mean_pressure(h.tau[k]) / J, q = von_mises(h.tau[k]) / J;
        const double p0 = cc.consolidation_pressure(h.state[k]);
        const double y = (1 + 2 * cc.beta) * q * q + cc.M * cc.M * (p + cc.beta * p0) * (p - p0);
        e = std::max(e, y / (cc.M * cc.M * std::max(p0, p_c0) * std::max(p0, p_c0)));
        e = std::max(e, std::abs(determinant(h.F_E[k]) * h.state[k].Jp / determinant(h.F[k]) - 1));
      }
    }
    return e;
  });

  // Confined (oedometric) compression to J = 0.8, the test the presets' p0 is calibrated on
  // (data/snow/fit_cam_clay.py): with the radial return and a hardening modulus H far below K, the
  // state settles where the ray from the ellipse's centre along the elastic trial direction
  // (dp, dq) = (K, 2G) d(eps_axial) meets the ellipse, so the axial Cauchy stress is k p0 with
  // k = p/p0 + 2 q / (3 p0) there. Error: |sigma_axial / (k p0) - 1| at the end, over the three
  // snow_cam_clay presets. The closed form neglects H J / K, which grows with compaction (1.2% for
  // fresh_snow at J = 0.8): measured 1.9e-3 at J = 0.9, 2.9e-3 at 0.8, 2.1e-2 at 0.5 (where H J / K
  // is 8%); the same with 10 times as many increments. Bound 1e-2.
  r.add("confined_compression_axial_ratio", 3 * 2000, 1e-2, [&] {
    double e = 0;
    for (const char* name : {"fresh_snow", "soft_cam_clay_snow", "packed_snow"}) {
      const MaterialModel<double> preset = make_material_model<double>(preset_material_info(name));
      const SnowCamClay<double>& m = std::get<SnowCamClay<double>>(preset);
      const double slope = 2 * m.elastic.G1 / m.elastic.K;
      const double a = (1 + m.beta) / 2, c = (1 - m.beta) / 2, b = m.M * a / std::sqrt(1 + 2 * m.beta);
      const double t = 1 / std::hypot(1 / a, slope / b);
      const double k = c + t + 2 * slope * t / 3;
      const DriverHistory h = drive_material(preset, paths::uniaxial_strain(-0.2), 2000);
      const double sigma_axial = -h.tau.back()(0, 0) / determinant(h.F.back());
      e = std::max(e, std::abs(sigma_axial / (k * m.consolidation_pressure(h.state.back())) - 1));
    }
    return e;
  });

  // The return once per increment: simple shear 1 in 40 increments against 4000; measured 1.7e-2,
  // bound 5e-2. (On compaction paths the state ends at the compressive tip, where hardening is
  // implicit and depends only on J: there 40 and 4000 increments agree to 1e-12.)
  r.add("substep_simple_shear", 40, 5e-2, [&] { return substep_error(model, paths::simple_shear(1.0), 40); });

  r.add("objectivity", 400, 1e-10, [&] { return objectivity_error(model, paths::compress_and_shear(0.5, 2.0), 400); });
  return r.rows;
}

std::vector<VerificationRow> verify_mooney_rivlin() {
  Rows r{"material_driver_mooney_rivlin", {}};
  // Thesis tire rubber with a third of the shear modulus in the G2 term, so that both terms are tested.
  const MaterialInfo rubber_info = preset_material_info("thesis_tire_rubber");
  const MaterialInfo rubber = preset_material_info("thesis_tire_rubber", {{"G2", rubber_info.moduli.G / 3}});
  const MaterialModel<double> model = make_material_model<double>(rubber);
  const MooneyRivlin<double>& mr = std::get<MooneyRivlin<double>>(model);

  r.add("zero_stress", 0, 1e-14, [&] { return zero_stress_error(model); });

  // Uniaxial stress at strain 1e-5: tau_xx / eps must be Young's modulus E and the lateral strain
  // -nu eps (linearised Mooney-Rivlin, shear modulus G1 + G2 = G). Relative error O(eps) / (1 - 2 nu):
  // bound 1e-3.
  r.add("uniaxial_stress_small_strain", 10, 1e-3, [&] {
    const double eps = 1e-5;
    const DriverHistory h = drive_uniaxial_stress(model, eps, 10);
    const double E = rubber.moduli.E, nu = rubber.moduli.nu;
    const double e_E = std::abs(h.tau.back()(0, 0) / eps / E - 1);
    const double e_nu = std::abs(-(h.F.back()(1, 1) - 1) / eps / nu - 1);
    const double e_lateral = std::abs(h.tau.back()(1, 1) / h.tau.back()(0, 0));
    return std::max({e_E, e_nu, e_lateral});
  });

  // Work = stored energy along compaction to J = 0.8 with shear 1: the midpoint-rule sum of
  // tau : sym(dF F_mid^{-1}) over 2000 increments against W(F_end), second order: relative error
  // about 1 / N^2 = 2.5e-7, bound 1e-5.
  r.add("work_equals_energy", 2000, 1e-5, [&] {
    const DriverHistory h = drive_material(model, paths::compress_and_shear(0.8, 1.0), 2000);
    double work = 0;
    for (std::size_t k = 1; k < h.F.size(); ++k) {
      const Mat3<double> L = (h.F[k] - h.F[k - 1]) * inverse(0.5 * (h.F[k] + h.F[k - 1]));
      work += ddot(0.5 * (h.tau[k] + h.tau[k - 1]), L);  // tau symmetric: tau : L = tau : sym(L)
    }
    const double W = mr.energy_density(h.F.back());
    return std::abs(work - W) / W;
  });

  r.add("objectivity", 400, 1e-10, [&] { return objectivity_error(model, paths::compress_and_shear(0.8, 1.0), 400); });
  return r.rows;
}

}  // namespace

std::vector<VerificationRow> verify_material_driver(const std::string& model) {
  if (model == "hyperelastic_plastic") return verify_hyperelastic_plastic();
  if (model == "snow_stomakhin") return verify_snow_stomakhin();
  if (model == "mooney_rivlin") return verify_mooney_rivlin();
  if (model == "snow_cam_clay") return verify_snow_cam_clay();
  throw std::invalid_argument("no material driver problem for model '" + model + "'");
}

}  // namespace firn
