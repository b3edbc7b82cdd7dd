#!/usr/bin/env python3
"""Calibrates firn's snow_cam_clay presets on laboratory data only (issue 16, item 2).

Each parameter comes from one data set; nothing here looks at a wheel or a snowball:
  E (Young's modulus)   Scapozza 2004 (PhD thesis, ETH Zurich): E = 0.1873 exp(0.0149 rho)
                        MPa, rho in kg/m^3, fitted on 180-490 kg/m^3; evaluated at the preset's density.
  nu                    0.2, as the thesis' Table 4.1 (Stomakhin et al. 2013).
  hardening_density     the compaction law sigma(rho) = A exp(rho / rho_h) fitted by least squares in
                        ln sigma to the steps of the final-density rule of CRREL Report 95-7
                        (crrel_95_7_final_density.csv: at each step pressure, the mid density of the
                        step). The rule gives the density a wheel's contact pressure leaves in
                        shallow snow on firm ground, which is compaction under lateral confinement:
                        the pressure is the axial stress of a confined (oedometric) compression.
  M                     the critical-state stress ratio from the friction angle phi of snow,
                        M = 6 sin(phi) / (3 - sin(phi)), the stress ratio q / p of Mohr-Coulomb
                        failure in triaxial compression (Wood 1990, Soil Behaviour and Critical
                        State Soil Mechanics, Cambridge University Press), with phi the angle of
                        repose of loose granular snow (grains 1-2 mm, 42 degrees;
                        angle_of_repose.csv). The table's range, 39-50 degrees, gives M 1.59-2.06.
  p0, beta              jointly, at the preset's density, from two conditions:
                        (1) confined compression: the axial stress k(M, beta, nu) p0 at which the
                            snow compacts (below) is the compaction law at the rest density, so
                            the piston of scenes/snow_compression.toml follows the CRREL rule;
                        (2) uniaxial tension: the stress at which a uniaxial stress path
                            (p, q) = (-s/3, s) meets the yield ellipse is the tensile strength of
                            Sigrist 2006 (PhD thesis, ETH Zurich): sigma_t = 240 kPa (rho/917)^2.44.
                        k: snow_cam_clay returns radially toward the ellipse's centre
                        (kernels/constitutive/snow_cam_clay.hpp). In steady confined compression
                        the elastic trial moves along (dp, dq) = (K, 2G) d(eps_axial), and where
                        the hardening modulus H = d p0 / d(-ln J_P) is far below K the state sits
                        where the ray from the centre along that direction meets the ellipse;
                        sigma_axial = k p0 = p + 2 q / 3 there. H / K is below 1% at the presets'
                        rest densities (printed) and grows with compaction, so at the CRREL
                        densities k is off by a few percent (2% for fresh_snow compacted to 440
                        kg/m^3), a few kg/m^3 in density. Checked by firn verify
                        material_driver_snow_cam_clay (confined_compression_axial_ratio) and by the
                        confined-compression run (tests/snow_calibration_test.py compression).
  softening_strain      0.01: the critical tensile strain of snow is 1% or less (Jamieson and
                        Johnston 1990, Can. Geotech. J. 27:296).

Run: python3 data/snow/fit_cam_clay.py   (prints the fit, its error and one line per preset in the
form of engine/material_catalog.cpp; tests/snow_calibration_test.py checks the catalog agrees).
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ICE_DENSITY = 917.0
POISSON = 0.2
SOFTENING_STRAIN = 0.01
REPOSE_SNOW = "granular (grains 1-2 mm)"  # the angle_of_repose.csv row M is taken from
PRESETS = [("fresh_snow", 220.0), ("soft_cam_clay_snow", 330.0), ("packed_snow", 400.0)]


def rows(name):
    with open(os.path.join(HERE, name)) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def scapozza_modulus(rho):
    return 0.1873e6 * math.exp(0.0149 * rho)


def sigrist_tensile_strength(rho):
    return 240e3 * (rho / ICE_DENSITY) ** 2.44


def fit_compaction():
    """Least squares of ln p = ln A + rho / rho_h over the rule's steps; returns A, rho_h, points."""
    points = [(0.5 * (float(r["density_below"]) + float(r["density_above"])), 1e3 * float(r["pressure_kPa"]))
              for r in rows("crrel_95_7_final_density.csv")]
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(math.log(p) for _, p in points) / n
    slope = sum((x - mx) * (math.log(p) - my) for x, p in points) / sum((x - mx) ** 2 for x, _ in points)
    return math.exp(my - slope * mx), 1.0 / slope, points


def critical_state_ratio(phi_deg):
    """M of Mohr-Coulomb failure in triaxial compression at friction angle phi."""
    sin = math.sin(math.radians(phi_deg))
    return 6 * sin / (3 - sin)


def ellipse(M, beta):
    """The yield ellipse of size p0 = 1: centre, semi-axes along p and q (snow_cam_clay.hpp)."""
    a = (1 + beta) / 2
    return (1 - beta) / 2, a, M * a / math.sqrt(1 + 2 * beta)


def confined_axial_ratio(M, beta, nu):
    """k = sigma_axial / p0 in steady confined compression with the radial return (docstring)."""
    slope = 3 * (1 - 2 * nu) / (1 + nu)  # 2G / K
    c, a, b = ellipse(M, beta)
    t = 1 / math.hypot(1 / a, slope / b)
    p, q = c + t, slope * t
    return p + 2 * q / 3


def uniaxial_tensile_ratio(M, beta):
    """s / p0 where (p, q) = (-s/3, s) meets (1 + 2 beta) q^2 + M^2 (p + beta)(p - 1) = 0."""
    A, B, C = 1 + 2 * beta + M * M / 9, M * M * (1 - beta) / 3, -M * M * beta
    return (-B + math.sqrt(B * B - 4 * A * C)) / (2 * A)


def fit_strength(M, axial, tensile):
    """beta and p0 with k(beta) p0 = axial and s_t(beta) p0 = tensile. The ratio s_t / k rises
    monotonically with beta from 0 over the range where k > 0, so bisection on it finds the root."""
    ratio = lambda beta: uniaxial_tensile_ratio(M, beta) / confined_axial_ratio(M, beta, POISSON)
    lo, hi = 0.0, 1.0
    while confined_axial_ratio(M, 2 * hi, POISSON) > 0 and ratio(hi) < tensile / axial:
        hi *= 2
    if not ratio(hi) >= tensile / axial:
        raise SystemExit(f"no beta reaches a tensile strength of {tensile:.4g} Pa at M = {M:.4g}")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < tensile / axial else (lo, mid)
    beta = 0.5 * (lo + hi)
    return beta, axial / confined_axial_ratio(M, beta, POISSON)


def main():
    A, rho_h, points = fit_compaction()
    print(f"compaction law sigma(rho) = {A:.4g} Pa exp(rho / {rho_h:.4g} kg/m^3)")
    worst = 0.0
    for rho, p in points:
        fit = A * math.exp(rho / rho_h)
        worst = max(worst, abs(fit / p - 1))
        # The density the law gives at the step's pressure, against the rule's mid density.
        print(f"  step {p / 1e3:.0f} kPa: rule {rho:.0f} kg/m^3, law {rho_h * math.log(p / A):.1f} kg/m^3,"
              f" pressure {fit / 1e3:.1f} kPa ({100 * (fit / p - 1):+.1f}%)")
    print(f"  largest pressure error {100 * worst:.1f}%")
    repose = {r["snow"]: float(r["angle_mean_deg"]) for r in rows("angle_of_repose.csv")}
    M = critical_state_ratio(repose[REPOSE_SNOW])
    print(f"M = {M:.4g} from the angle of repose {repose[REPOSE_SNOW]:g} deg ({REPOSE_SNOW}); the table's range"
          f" {min(repose.values()):g}-{max(repose.values()):g} deg gives M"
          f" {critical_state_ratio(min(repose.values())):.3g}-{critical_state_ratio(max(repose.values())):.3g}")
    for name, rho in PRESETS:
        E = scapozza_modulus(rho)
        axial, tensile = A * math.exp(rho / rho_h), sigrist_tensile_strength(rho)
        beta, p0 = fit_strength(M, axial, tensile)
        H_over_K = p0 * rho / rho_h / (E / (3 * (1 - 2 * POISSON)))
        print(f"  {name}: confined yield {axial / 1e3:.2f} kPa, tensile strength {tensile / 1e3:.2f} kPa,"
              f" k = {confined_axial_ratio(M, beta, POISSON):.4f}, H / K = {H_over_K:.2e}")
        print(f'{name}: {{"density", {rho:g}}}, {{"E", {E:.4g}}}, {{"nu", {POISSON:g}}}, {{"M", {M:.4g}}}, '
              f'{{"beta", {beta:.4g}}}, {{"p0", {p0:.4g}}}, {{"hardening_density", {rho_h:.4g}}}, '
              f'{{"softening_strain", {SOFTENING_STRAIN:g}}}')
    return 0


if __name__ == "__main__":
    sys.exit(main())
