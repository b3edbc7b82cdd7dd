// Tests of firn::svd3 and firn::polar_rotation (kernels/svd3.hpp) for float and double.
//
// The reference is Eigen::JacobiSVD run in long double on the very matrix given to svd3 (its
// entries are exactly representable), so the reference's own error (eps of long double, about
// 1e-19) is negligible next to the tolerances below, even for double. All error measures are
// evaluated in long double as well.
//
// Tolerances are in units of eps = std::numeric_limits<T>::epsilon():
//  - kRecon, backward error ||U diag(sigma) V^T - A||_F / max(||A||_F, tiny): svd3 is backward
//    stable, so this is a small multiple of eps whatever the conditioning. Its worst value over
//    3.5e6 random, clustered and graded matrices is 7 eps (20 to 30 rotations, each rounding at
//    eps/2, the errors partly cancelling); 32 leaves room for that, and two Jacobi sweeps fewer
//    give 1e4 (float) to 1e7 (double) eps. One sweep fewer is SweepCountIsConverged's business.
//  - kOrth, ||U^T U - I||_F and |det U - 1| (same for V): U and V are products of a handful of
//    rotations (or a quaternion's matrix), each orthogonal to a few eps; measured worst 13 eps
//    over 1.5e6 matrices, so 32.
//  - kSigma, | |sigma_i| - sigma_i(reference) | / sigma_0: by Weyl's theorem a backward error E
//    moves each singular value by at most ||E||_2 <= ||E||_F <= kRecon eps ||A||_F
//    <= kRecon eps sqrt(3) sigma_0, hence kSigma = 56 > 32 sqrt(3).
//  - The sign of sigma[2] is tested where the data decide it: where sigma_2(reference) >
//    kSigma eps sigma_0. Any matrix whose det has the other sign is at least sigma_2 away from A
//    (sigma_2 is the distance to the singular matrices), more than the backward error
//    kRecon eps ||A||_F <= kSigma eps sigma_0 allows. Below that, det(A) is within rounding of
//    zero and either sign is a correct answer.
//  - The ordering sigma[0] >= sigma[1] >= |sigma[2]| is exact (no tolerance).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "kernels/svd3.hpp"

namespace {

using LD = long double;
using M3 = Eigen::Matrix<LD, 3, 3>;

constexpr LD kRecon = 32;
constexpr LD kOrth = 32;
constexpr LD kSigma = 56;
// Polar decomposition R^T A = V diag(sigma) V^T + V U^T E for the backward error E of svd3: the
// skew part and the shift of the eigenvalues are at most ||E|| each (kRecon eps ||A||), plus the
// rounding of the product R^T A (a few eps ||A||): hence 2 kRecon for both.
constexpr LD kPolar = 2 * kRecon;

template <class T>
LD eps() {
  return std::numeric_limits<T>::epsilon();
}

template <class T>
M3 to_ld(const firn::Mat3<T>& a) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(i, j);
  return r;
}

template <class T>
firn::Mat3<T> from_ld(const M3& a) {
  firn::Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = T(a(i, j));
  return r;
}

std::string show(LD x) {
  std::ostringstream os;
  os << double(x);
  return os.str();
}

std::string show(const M3& a) {
  std::ostringstream os;
  os.precision(21);
  os << a;
  return os.str();
}

// Uniformly distributed rotation: the matrix of a normalised Gaussian quaternion.
M3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaternion<LD> q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

M3 random_uniform(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  M3 a;
  for (int i = 0; i < 9; ++i) a.data()[i] = u(rng);
  return a;
}

M3 random_gaussian(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  M3 a;
  for (int i = 0; i < 9; ++i) a.data()[i] = n(rng);
  return a;
}

// Whether det A < 0, from the reference SVD A = U diag(sigma >= 0) V^T: det A = det U det V
// sigma_0 sigma_1 sigma_2. Unlike the cofactor formula (whose 2x2 minors lose eps sigma_0^2 to
// cancellation, more than all of det A when sigma_1 and sigma_2 are small), this is reliable
// whenever sigma_2 is above rounding.
bool reference_det_negative(const Eigen::JacobiSVD<M3>& svd) {
  return svd.matrixU().determinant() * svd.matrixV().determinant() < 0;
}

// The largest value of an error measure seen over a set, and the matrix it came from.
struct Worst {
  LD value = 0;
  M3 A = M3::Zero();
  void update(LD v, const M3& a) {
    if (!(v <= value)) {  // NaN counts as worst
      value = v;
      A = a;
    }
  }
};

struct Report {
  int count = 0;
  Worst recon, orth, det, sigma;
  int nonfinite = 0, misordered = 0, sign_checked = 0, negative_det = 0, wrong_sign = 0;
  M3 first_bad = M3::Zero();
};

// Runs svd3 on A and records every error measure (in units of eps of T) in rep. abs_floor is an
// absolute error allowance for reconstruction (nonzero only for inputs whose singular values
// are subnormal numbers, which cannot be stored to relative precision).
template <class T>
void check_svd(const firn::Mat3<T>& A, Report& rep, LD abs_floor = 0) {
  firn::Mat3<T> U, V;
  firn::Vec3<T> s;
  firn::svd3(A, U, s, V);
  const M3 a = to_ld(A), u = to_ld(U), v = to_ld(V);
  ++rep.count;
  bool finite = true;
  for (int i = 0; i < 9; ++i) finite = finite && std::isfinite(U.m[i]) && std::isfinite(V.m[i]);
  for (int i = 0; i < 3; ++i) finite = finite && std::isfinite(s[i]);
  if (!finite) {
    if (rep.nonfinite++ == 0) rep.first_bad = a;
    return;
  }
  const LD e = eps<T>();
  const LD norm_a = std::max<LD>(a.norm(), std::numeric_limits<T>::min());
  M3 usv = u * Eigen::Matrix<LD, 3, 1>(s[0], s[1], s[2]).asDiagonal() * v.transpose();
  rep.recon.update(std::max<LD>((usv - a).norm() - abs_floor, 0) / (norm_a * e), a);
  rep.orth.update(
      std::max((u.transpose() * u - M3::Identity()).norm(), (v.transpose() * v - M3::Identity()).norm()) / e, a);
  rep.det.update(std::max(std::fabs(u.determinant() - 1), std::fabs(v.determinant() - 1)) / e, a);

  const Eigen::JacobiSVD<M3> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix<LD, 3, 1> ref = svd.singularValues();  // sorted, >= 0
  const LD sigma0 = std::max<LD>(ref(0), std::numeric_limits<T>::min());
  LD sigma_err = 0;
  for (int i = 0; i < 3; ++i) sigma_err = std::max(sigma_err, std::fabs(std::fabs(LD(s[i])) - ref(i)));
  rep.sigma.update(std::max<LD>(sigma_err - abs_floor, 0) / (sigma0 * e), a);

  if (!(s[0] >= s[1] && s[1] >= std::fabs(s[2]))) {
    if (rep.misordered++ == 0) rep.first_bad = a;
  }
  if (ref(2) > kSigma * e * sigma0) {
    ++rep.sign_checked;
    const bool negative = reference_det_negative(svd);
    rep.negative_det += negative;
    if ((s[2] < 0) != negative && rep.wrong_sign++ == 0) rep.first_bad = a;
  }
}

void expect_report(const Report& rep, const std::string& what) {
  ASSERT_GT(rep.count, 0) << what;
  EXPECT_EQ(rep.nonfinite, 0) << what << ": non-finite output for A =\n" << show(rep.first_bad);
  EXPECT_LE(rep.recon.value, kRecon) << what << ": reconstruction error (eps) for A =\n" << show(rep.recon.A);
  EXPECT_LE(rep.orth.value, kOrth) << what << ": ||U^T U - I|| or ||V^T V - I|| (eps) for A =\n" << show(rep.orth.A);
  EXPECT_LE(rep.det.value, kOrth) << what << ": |det U - 1| or |det V - 1| (eps) for A =\n" << show(rep.det.A);
  EXPECT_LE(rep.sigma.value, kSigma) << what << ": singular value error (eps sigma_0) for A =\n" << show(rep.sigma.A);
  EXPECT_EQ(rep.misordered, 0) << what << ": sigma not ordered, first A =\n" << show(rep.first_bad);
  EXPECT_EQ(rep.wrong_sign, 0) << what << ": sign(sigma[2]) != sign(det A) (of " << rep.sign_checked
                               << " checked), first A =\n"
                               << show(rep.first_bad);
}

// diag(d) itself, and R diag(d) Q for `count` random rotations R, Q.
template <class T>
Report check_family(LD d0, LD d1, LD d2, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const M3 D = Eigen::Matrix<LD, 3, 1>(d0, d1, d2).asDiagonal();
  Report rep;
  check_svd(from_ld<T>(D), rep);
  for (int n = 0; n < count; ++n) check_svd(from_ld<T>(random_rotation(rng) * D * random_rotation(rng)), rep);
  return rep;
}

template <class T>
class Svd3Test : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Svd3Test, Scalars);

constexpr int kRandomCount = 4000;  // per random set
constexpr int kFamilyCount = 300;   // random rotations per special case

TYPED_TEST(Svd3Test, RandomUniform) {
  using T = TypeParam;
  std::mt19937_64 rng(1);
  Report rep;
  for (int n = 0; n < kRandomCount; ++n) check_svd(from_ld<T>(random_uniform(rng)), rep);
  expect_report(rep, "uniform entries in [-1, 1]");
  // The sign convention is really exercised: nearly all have a clear sign of det, half negative.
  EXPECT_GT(rep.sign_checked, kRandomCount * 9 / 10);
  EXPECT_GT(rep.negative_det, kRandomCount * 4 / 10);
}

TYPED_TEST(Svd3Test, RandomGaussian) {
  using T = TypeParam;
  std::mt19937_64 rng(2);
  Report rep;
  for (int n = 0; n < kRandomCount; ++n) check_svd(from_ld<T>(random_gaussian(rng)), rep);
  expect_report(rep, "Gaussian entries");
}

// Random singular values with a log-uniform spread of up to 1e8 and random signs of det.
TYPED_TEST(Svd3Test, RandomGraded) {
  using T = TypeParam;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(0, 8);
  Report rep;
  for (int n = 0; n < kRandomCount; ++n) {
    const LD s1 = std::pow(LD(10), -LD(exponent(rng)));
    const LD s2 = (n % 2 ? -1 : 1) * s1 * std::pow(LD(10), -LD(exponent(rng)));
    const M3 D = Eigen::Matrix<LD, 3, 1>(1, s1, s2).asDiagonal();
    check_svd(from_ld<T>(random_rotation(rng) * D * random_rotation(rng)), rep);
  }
  expect_report(rep, "graded singular values");
}

TYPED_TEST(Svd3Test, IdentityAndRotations) {
  using T = TypeParam;
  expect_report(check_family<T>(1, 1, 1, kFamilyCount, 4), "rotations");
  // The identity itself (also in the family above): sigma = (1, 1, 1) to rounding.
  firn::Mat3<T> U, V;
  firn::Vec3<T> s;
  firn::svd3(firn::Mat3<T>::identity(), U, s, V);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], T(1), kRecon * eps<T>());
}

TYPED_TEST(Svd3Test, Diagonal) {
  using T = TypeParam;
  // Every order and sign pattern of (3, 2, 1), including det < 0.
  const LD v[3] = {3, 2, 1};
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  Report rep;
  for (const auto& p : perms)
    for (int signs = 0; signs < 8; ++signs) {
      const LD d0 = (signs & 1 ? -1 : 1) * v[p[0]], d1 = (signs & 2 ? -1 : 1) * v[p[1]];
      const LD d2 = (signs & 4 ? -1 : 1) * v[p[2]];
      check_svd(from_ld<T>(Eigen::Matrix<LD, 3, 1>(d0, d1, d2).asDiagonal()), rep);
    }
  expect_report(rep, "diagonal, permutations and signs of (3, 2, 1)");
  EXPECT_EQ(rep.sign_checked, 48);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n;
  Report random;
  for (int k = 0; k < kFamilyCount; ++k)
    check_svd(from_ld<T>(Eigen::Matrix<LD, 3, 1>(n(rng), n(rng), n(rng)).asDiagonal()), random);
  expect_report(random, "diagonal, Gaussian entries");
}

TYPED_TEST(Svd3Test, RepeatedSingularValues) {
  using T = TypeParam;
  expect_report(check_family<T>(2, 2, 2, kFamilyCount, 6), "diag(2, 2, 2)");
  expect_report(check_family<T>(1, 1, 0.5, kFamilyCount, 7), "diag(1, 1, 0.5)");
  expect_report(check_family<T>(1, 0.5, 0.5, kFamilyCount, 8), "diag(1, 0.5, 0.5)");
  expect_report(check_family<T>(3, 3, -3, kFamilyCount, 9), "diag(3, 3, -3)");
  // Clustered within 1e-2 .. 1e-12 relative (below eps in float: exactly repeated there).
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> u(-1, 1);
  Report rep;
  for (int n = 0; n < kRandomCount; ++n) {
    const LD delta = std::pow(LD(10), -LD(2 + n % 11));
    const LD third = (n % 3 == 0) ? LD(u(rng)) : 1 - delta * LD(u(rng));
    const M3 D = Eigen::Matrix<LD, 3, 1>(1, 1 - delta * LD(u(rng)), third).asDiagonal();
    check_svd(from_ld<T>(random_rotation(rng) * D * random_rotation(rng)), rep);
  }
  expect_report(rep, "clustered singular values");
}

TYPED_TEST(Svd3Test, RankDeficient) {
  using T = TypeParam;
  expect_report(check_family<T>(3, 1, 0, kFamilyCount, 11), "rank 2");
  expect_report(check_family<T>(1, 1, 0, kFamilyCount, 12), "rank 2, repeated");
  expect_report(check_family<T>(2, 0, 0, kFamilyCount, 13), "rank 1");
  // Rank 1 as an outer product u v^T, which is exactly singular in T as well.
  std::mt19937_64 rng(14);
  Report rep;
  for (int n = 0; n < kFamilyCount; ++n) {
    const M3 g = random_gaussian(rng);
    check_svd(from_ld<T>(g.col(0) * g.col(1).transpose()), rep);
  }
  expect_report(rep, "outer product");
  // The zero matrix: all singular values exactly zero.
  Report zero;
  check_svd(firn::Mat3<T>::zero(), zero);
  expect_report(zero, "zero");
  firn::Mat3<T> U, V;
  firn::Vec3<T> s;
  firn::svd3(firn::Mat3<T>::zero(), U, s, V);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(s[i], T(0));
}

TYPED_TEST(Svd3Test, Reflected) {
  using T = TypeParam;
  expect_report(check_family<T>(2, 1, -0.5, kFamilyCount, 15), "diag(2, 1, -0.5)");
  expect_report(check_family<T>(-1, -1, -1, kFamilyCount, 16), "-I and improper rotations");
  expect_report(check_family<T>(1, 1, -1, kFamilyCount, 17), "reflections");
  // Every one of these has det < 0 far from zero: sigma[2] must be negative.
  const Report rep = check_family<T>(5, 3, -1, kFamilyCount, 18);
  EXPECT_EQ(rep.negative_det, kFamilyCount + 1);
  expect_report(rep, "diag(5, 3, -1)");
}

TYPED_TEST(Svd3Test, Scaled) {
  using T = TypeParam;
  for (const LD scale : {LD(1e-4), LD(1e4)}) {
    std::mt19937_64 rng(19);
    Report rep;
    for (int n = 0; n < kRandomCount; ++n) check_svd(from_ld<T>(scale * random_uniform(rng)), rep);
    expect_report(rep, "uniform entries times " + show(scale));
  }
}

TYPED_TEST(Svd3Test, NearlySingular) {
  using T = TypeParam;
  expect_report(check_family<T>(1, 0.5, 1e-6, kFamilyCount, 20), "diag(1, 0.5, 1e-6)");
  expect_report(check_family<T>(1, 0.5, -1e-6, kFamilyCount, 21), "diag(1, 0.5, -1e-6)");
  expect_report(check_family<T>(1, 1e-6, 1e-6, kFamilyCount, 22), "diag(1, 1e-6, 1e-6)");
  expect_report(check_family<T>(1, 1e-6, -1e-7, kFamilyCount, 23), "diag(1, 1e-6, -1e-7)");
  expect_report(check_family<T>(1, 1e-6, 0, kFamilyCount, 24), "diag(1, 1e-6, 0)");
}

// Deformation gradients of elastic MPM: a rotation times I + small strain.
TYPED_TEST(Svd3Test, NearIdentity) {
  using T = TypeParam;
  std::mt19937_64 rng(25);
  Report rep;
  for (int n = 0; n < kRandomCount; ++n) {
    const LD strain = std::pow(LD(10), -LD(1 + n % 6));
    check_svd(from_ld<T>(random_rotation(rng) * (M3::Identity() + strain * random_gaussian(rng))), rep);
  }
  expect_report(rep, "rotation times (I + small strain)");
}

// Finite output for any finite input, down to subnormal and up to near-overflow magnitudes.
TYPED_TEST(Svd3Test, ExtremeMagnitudes) {
  using T = TypeParam;
  using lim = std::numeric_limits<T>;
  // Largest magnitude such that sigma_0 <= 3 max|a_ij| cannot overflow.
  for (const LD scale : {LD(lim::max()) / 4, LD(lim::min()), LD(lim::denorm_min()) * 4096}) {
    std::mt19937_64 rng(26);
    Report rep;
    // Singular values below lim::min() are stored with absolute precision denorm_min / 2 only.
    const LD floor = 4 * LD(lim::denorm_min());
    for (int n = 0; n < kFamilyCount; ++n) check_svd(from_ld<T>(scale * random_uniform(rng)), rep, floor);
    expect_report(rep, "uniform entries times " + show(scale));
  }
}

// Three sweeps more change nothing: kSweeps is at the rounding floor on the hardest structure
// known for the approximate Jacobi rotations (two singular values clustered within 1e-16 .. 0.3
// relative, the third apart). With this many matrices, one sweep fewer fails here for both
// types (float: 114 eps; double: 16 eps against twice the floor, 12).
TYPED_TEST(Svd3Test, SweepCountIsConverged) {
  using T = TypeParam;
  const int sweeps = firn::svd3_detail::Traits<T>::kSweeps;
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> exponent(-16, -0.5), u(-1, 1);
  LD worst[2] = {0, 0};
  for (int n = 0; n < 100000; ++n) {
    const LD delta = std::pow(LD(10), LD(exponent(rng)));
    const M3 D = Eigen::Matrix<LD, 3, 1>(1, 1 - delta * LD(u(rng)), LD(u(rng))).asDiagonal();
    const firn::Mat3<T> A = from_ld<T>(random_rotation(rng) * D * random_rotation(rng));
    const M3 a = to_ld(A);
    for (int k = 0; k < 2; ++k) {
      firn::Mat3<T> U, V;
      firn::Vec3<T> s;
      firn::svd3_detail::svd3_sweeps(A, U, s, V, sweeps + 3 * k);
      const M3 usv = to_ld(U) * Eigen::Matrix<LD, 3, 1>(s[0], s[1], s[2]).asDiagonal() * to_ld(V).transpose();
      worst[k] = std::max(worst[k], (usv - a).norm() / (a.norm() * eps<T>()));
    }
  }
  // Both are rounding noise of about the same size (measured 6 to 9 eps).
  EXPECT_LE(worst[0], kRecon);
  EXPECT_LE(worst[0], 2 * worst[1]) << "kSweeps = " << sweeps << " has not converged";
}

TYPED_TEST(Svd3Test, PolarRotation) {
  using T = TypeParam;
  std::mt19937_64 rng(28);
  const LD e = eps<T>();
  LD worst_orth = 0, worst_sym = 0, worst_psd = 0, worst_ref = 0;
  int positive = 0;
  for (int n = 0; n < kRandomCount; ++n) {
    M3 g = random_uniform(rng);
    if (n % 4 == 0) g = random_rotation(rng) * (M3::Identity() + 1e-3L * random_gaussian(rng));
    if (n % 4 == 1) {  // nearly singular, det of either sign: the semidefinite case
      const LD s1 = LD(0.5) + g(0, 0) / 2, s2 = LD(1e-9) * g(1, 1);
      g = random_rotation(rng) * Eigen::Matrix<LD, 3, 1>(1, s1, s2).asDiagonal() * random_rotation(rng);
    }
    const firn::Mat3<T> A = from_ld<T>(g);
    const M3 a = to_ld(A), r = to_ld(firn::polar_rotation(A));
    const LD norm_a = a.norm();
    worst_orth = std::max(worst_orth, (r.transpose() * r - M3::Identity()).norm() / e);
    worst_orth = std::max(worst_orth, std::fabs(r.determinant() - 1) / e);
    const M3 p = r.transpose() * a;  // V diag(sigma) V^T: symmetric for any sign of det A
    worst_sym = std::max(worst_sym, (p - p.transpose()).norm() / (norm_a * e));
    const Eigen::JacobiSVD<M3> ref(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    if (reference_det_negative(ref)) continue;
    ++positive;
    // Positive semidefinite: no eigenvalue below -(rounding).
    const M3 sym = (p + p.transpose()) / 2;
    const LD lambda_min = Eigen::SelfAdjointEigenSolver<M3>(sym, Eigen::EigenvaluesOnly).eigenvalues()(0);
    worst_psd = std::max(worst_psd, -lambda_min / (norm_a * e));
    // Against the reference polar factor U V^T: a backward error E moves it by at most
    // 2 ||E||_F / (sigma_1 + sigma_2) (Li 1995); plus its own rounding (kOrth).
    const LD bound = 2 * kRecon * e * norm_a / (ref.singularValues()(1) + ref.singularValues()(2)) + kOrth * e;
    worst_ref = std::max(worst_ref, (r - ref.matrixU() * ref.matrixV().transpose()).norm() / bound);
  }
  EXPECT_GT(positive, kRandomCount / 3);
  EXPECT_LE(worst_orth, kOrth) << "R is not a rotation";
  EXPECT_LE(worst_sym, kPolar) << "R^T A is not symmetric";
  EXPECT_LE(worst_psd, kPolar) << "R^T A is not positive semidefinite";
  EXPECT_LE(worst_ref, LD(1)) << "R differs from the reference polar factor";
}

}  // namespace
