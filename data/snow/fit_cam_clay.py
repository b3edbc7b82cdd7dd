#!/usr/bin/env python3
"""Calibrates firn's snow_cam_clay presets on laboratory data only (issue 16, item 2).

Each parameter comes from one data set; nothing here looks at a wheel or a snowball:
  E (Young's modulus)   Scapozza 2004 (PhD thesis, ETH Zurich): E = 0.1873 exp(0.0149 rho)
                        MPa, rho in kg/m^3, fitted on 180-490 kg/m^3; evaluated at the preset's density.
  nu                    0.2, as the thesis' Table 4.1 (Stomakhin et al. 2013).
  p0, hardening_density the compaction law p0(rho) = A exp(rho / rho_h) fitted by least squares in
                        ln p to the steps of the final-density rule of CRREL Report 95-7
                        (crrel_95_7_final_density.csv: at each step pressure, the mid density of the
                        step); p0 of a preset is the law at its rest density.
  beta                  tensile strength over p0, the tensile strength from Sigrist 2006 (PhD thesis,
                        ETH Zurich): sigma_t = 240 kPa (rho / 917)^2.44.
  M                     1.0 for now: NOT calibrated yet. Its data set is to be plate sinkage
                        (a snow_plate_sinkage scene against the Bekker curve of Wong, Theory of
                        Ground Vehicles, Table 2.3); until then M is a placeholder (issue 16).
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
M = 1.0  # placeholder until the plate-sinkage calibration (see the docstring)
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


def main():
    A, rho_h, points = fit_compaction()
    print(f"compaction law p0(rho) = {A:.4g} Pa exp(rho / {rho_h:.4g} kg/m^3)")
    worst = 0.0
    for rho, p in points:
        fit = A * math.exp(rho / rho_h)
        worst = max(worst, abs(fit / p - 1))
        # The density the law gives at the step's pressure, against the rule's mid density.
        print(f"  step {p / 1e3:.0f} kPa: rule {rho:.0f} kg/m^3, law {rho_h * math.log(p / A):.1f} kg/m^3,"
              f" pressure {fit / 1e3:.1f} kPa ({100 * (fit / p - 1):+.1f}%)")
    print(f"  largest pressure error {100 * worst:.1f}%")
    for name, rho in PRESETS:
        E = scapozza_modulus(rho)
        p0 = A * math.exp(rho / rho_h)
        beta = sigrist_tensile_strength(rho) / p0
        print(f'{name}: {{"density", {rho:g}}}, {{"E", {E:.4g}}}, {{"nu", {POISSON:g}}}, {{"M", {M:g}}}, '
              f'{{"beta", {beta:.4g}}}, {{"p0", {p0:.4g}}}, {{"hardening_density", {rho_h:.4g}}}, '
              f'{{"softening_strain", {SOFTENING_STRAIN:g}}}')
    return 0


if __name__ == "__main__":
    sys.exit(main())
