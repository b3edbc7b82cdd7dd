// Solid cylinder on an incline with Coulomb friction (DESIGN.md section 6, problem 4). A uniform
// cylinder (I = m R^2 / 2) released from rest rolls without slipping when the friction it needs,
// f = m g sin(theta) / 3, is available, i.e. mu >= tan(theta) / 3, with
//   a = g sin(theta) / (1 + I / (m R^2)) = 2/3 g sin(theta),  alpha R = a;
// below that it slides with a = g (sin theta - mu cos theta) and alpha R = 2 mu g cos theta
// (e.g. Meriam and Kraige, Engineering Mechanics: Dynamics, rolling on an incline). The slip ratio
// s = 1 - alpha R / a is 0 when rolling and (sin - 3 mu cos) / (sin - mu cos) when sliding: 1/3 at
// mu = 0.75 tan(theta) / 3, whatever theta.
// Set-up (incline.hpp): theta = 45 degrees, R = 0.1 m, the cylinder's axis along z (plane strain),
// neo-Hookean with E = 1e7 Pa, nu = 0.3, rho = 1000 kg/m^3. Two runs per level:
// mu = 1.25 tan(theta) / 3 (rolls) and mu = 0.75 tan(theta) / 3 (slides). a and alpha are
// least-squares slopes of the centre of mass's velocity and of the rigid angular velocity (angular
// momentum about the centre of mass over the moment of inertia) over t in [0.07, 0.13] s.
// Gravity is eased in over 0.06 s, about 1.5 periods of the cylinder bouncing on its contact
// (0.04 s at R / dx = 10), which a half-cosine ramp of that length barely excites.
// Rows per level:
//   incline_rolling.acceleration        |a / (2/3 g sin theta) - 1| of the rolling run;
//   incline_rolling.roll_slip           |s| of the rolling run, bound 1/6;
//   incline_rolling.slide_slip          1/3 - s of the sliding run, bound 1/6 (i.e. s >= 1/6);
//   incline_rolling.slide_acceleration  |a / (g (sin theta - mu cos theta)) - 1| of the sliding run.
// The two slip rows split at s = 1/6, halfway between rolling (0) and sliding (1/3): a cylinder
// that rolls at both coefficients fails the third row, one that slides at both fails the second.
// Accuracy: the ground is a set of grid nodes, so it touches the cylinder across the stencil of
// every particle within 1.5 dx of it, a patch of half-width about sqrt(3 R dx), much wider than
// the elastic contact. Only approaching nodes carry load (boundary `separate`), and in a turning
// cylinder those are the ones ahead of the lowest point: the normal force acts a lever arm e ahead
// of the centre (from the collider's force and torque, in trial runs with a shorter ramp:
// e = 0.044 R, 0.034 R, 0.018 R at R / dx = 10, 20, 40), a rolling resistance that slows the
// rolling cylinder by about (e / R) cot(theta) and spins the sliding one less than
// 2 mu g cos(theta) / R. Against it, the rolling cylinder slips 5-7% and the sliding one feels less
// friction than mu N (some contact nodes stick, |v_t| < mu |v_n|), which speed them up. Measured errors (README.md, "firn verify"): rolling -1.3%,
// +0.8%, +1.9% and sliding 2.2%, 3.5%, 4.4% at R / dx = 10, 20, 40: not converging. The bounds are
// therefore not proven: 2% at R / dx = 40 is issue 5's requirement, 5% and 3% at the coarser
// levels and 5% on the sliding acceleration are the measured errors with a margin.
#include <cmath>

#include "engine/verification/incline.hpp"
#include "engine/verification/least_squares.hpp"
#include "engine/verification/verification.hpp"

namespace firn {

namespace {

struct RollingLevel {
  int level;
  int cells_per_radius;      // R / dx
  double acceleration_bound;  // on |a / (2/3 g sin theta) - 1|
};

std::vector<VerificationRow> run_rolling_levels(const std::vector<RollingLevel>& levels,
                                                const VerificationOptions& options) {
  const double theta = M_PI / 4, radius = 0.1, fit_start = 0.07, slip_split = 1.0 / 6, slide_bound = 0.05;
  const double threshold = std::tan(theta) / 3;  // the smallest mu that lets it roll
  std::vector<VerificationRow> rows;
  for (const RollingLevel& l : levels) {
    InclineRun run;
    run.angle = theta;
    run.dx = radius / l.cells_per_radius;
    run.per_cell = 2;
    run.material = {"cylinder", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e7, 0.3)};
    run.body_max = {2 * radius, 2 * radius, 0};
    run.inside = [radius](const Point& p) {
      return (p[0] - radius) * (p[0] - radius) + (p[1] - radius) * (p[1] - radius) < radius * radius;
    };
    run.travel = 0.08;
    run.ramp = 0.06;
    run.end_time = 0.13;
    double slip[2], accel[2], exact[2];
    long steps = 0;
    double seconds = 0;
    const double factors[2] = {1.25, 0.75};
    for (int k = 0; k < 2; ++k) {
      run.mu = factors[k] * threshold;
      exact[k] = k == 0 ? 2.0 / 3 * kInclineGravity * std::sin(theta)
                        : kInclineGravity * (std::sin(theta) - run.mu * std::cos(theta));
      const InclineHistory h = run_incline(run, options);
      accel[k] = least_squares_slope(h.time, h.velocity, fit_start, run.end_time);
      slip[k] = 1 - least_squares_slope(h.time, h.spin, fit_start, run.end_time) * radius / accel[k];
      steps += h.steps;
      seconds += h.seconds;
      if (options.log)
        *options.log << "incline_rolling R/dx " << l.cells_per_radius << " mu " << run.mu << ": a " << accel[k]
                     << " m/s^2 (exact " << exact[k] << "), slip ratio " << slip[k] << " (exact "
                     << (k == 0 ? 0.0 : 1.0 / 3) << ")\n";
    }
    rows.push_back({"incline_rolling.acceleration", l.level, run.dx, run.per_cell, steps,
                    std::abs(accel[0] / exact[0] - 1), l.acceleration_bound, seconds});
    rows.push_back({"incline_rolling.roll_slip", l.level, run.dx, run.per_cell, steps, std::abs(slip[0]), slip_split, 0});
    rows.push_back({"incline_rolling.slide_slip", l.level, run.dx, run.per_cell, steps, 1.0 / 3 - slip[1],
                    slip_split, 0});
    rows.push_back({"incline_rolling.slide_acceleration", l.level, run.dx, run.per_cell, steps,
                    std::abs(accel[1] / exact[1] - 1), slide_bound, 0});
  }
  return rows;
}

}  // namespace

std::vector<VerificationRow> verify_incline_rolling(const VerificationOptions& options) {
  return run_rolling_levels({{0, 10, 0.05}}, options);
}

std::vector<VerificationRow> verify_incline_rolling_fine(const VerificationOptions& options) {
  return run_rolling_levels({{1, 20, 0.03}, {2, 40, 0.02}}, options);
}

}  // namespace firn
