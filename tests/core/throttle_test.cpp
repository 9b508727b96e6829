// Tests of core/include/ctid/throttle.hpp: the plate's integration against
// closed forms and an independent matrix-exponential solution of the
// piecewise-linear modes, the loop against its definitions, and the
// estimators of sec. 4.2.3 (exact on noise-free data, IV unbiased where
// least squares is not, tracking R(t)), no allocation per sample,
// validation.
#include "ctid/throttle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "allocation_counter.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

using Params = ThrottleParameters<double>;
constexpr double kDeg = 3.14159265358979323846 / 180;

// ---------------------------------------------------------------------------
// An independent solution of the plate with constant R: within a mode (sign
// of omega, spring segment) the plate is linear time-invariant and solved
// exactly by the matrix exponential; events are found on a fine grid and
// refined by bisection on the exact solution.
class ReferencePlate {
 public:
  ReferencePlate(const Params& p, double r) : p_(p), r_(r) {
    b_[0] = p.phi_LH - p.delta_phi / 2;
    b_[1] = p.phi_LH + p.delta_phi / 2;
    b_[2] = p.phi_12;
    // M_s = k phi + m on each segment, from (4.7)-(4.8) written out.
    k_[0] = p.Ks3;
    m_[0] = -p.Ks3 * b_[0] - p.M_close;
    k_[1] = 0;
    m_[1] = 0;
    k_[2] = p.Ks1;
    m_[2] = -p.Ks1 * b_[1] + p.M_open;
    k_[3] = p.Ks2;
    m_[3] = -p.Ks2 * p.phi_12 + p.Ks1 * (p.phi_12 - b_[1]) + p.M_open;
  }

  void set_state(double phi, double omega) {
    x_ << phi, omega;
    stuck_ = omega == 0;
    pinned_ = -1;
    dir_ = omega > 0 ? 1 : (omega < 0 ? -1 : 0);
  }
  double phi() const { return x_(0); }
  double omega() const { return x_(1); }
  bool stuck() const { return stuck_; }
  bool pinned() const { return pinned_ >= 0; }
  int current_segment() const { return segment(x_(0)); }

  // Returns false after 100000 events in one interval (a Zeno sequence
  // that the pinning rule failed to stop).
  bool advance(double u, double h) {
    double t = 0;
    for (int events = 0; t < h; ++events) {
      if (events > 100000) return false;
      if (stuck_) {
        // R constant: the plate stays stuck or leaves at once.
        const double motor = p_.Kt * p_.Gr * u / r_;
        double below = torque(segment(x_(0)), x_(0)), above = below;
        if (pinned_ >= 0) {
          below = torque(pinned_, x_(0));
          above = torque(pinned_ + 1, x_(0));
        }
        if (motor <= above + p_.Mc && motor >= below - p_.Mc) return true;
        dir_ = motor > above + p_.Mc ? 1 : -1;
        if (pinned_ >= 0) x_(0) = std::nextafter(x_(0), dir_ * 1e300);
        stuck_ = false;
        pinned_ = -1;
      }
      t += slip(u, h - t);
    }
    return true;
  }

 private:
  int segment(double phi) const {
    if (phi < b_[0]) return 0;
    if (phi <= b_[1]) return 1;
    if (phi < b_[2]) return 2;
    return 3;
  }
  double torque(int s, double phi) const { return k_[s] * phi + m_[s]; }
  double drive(double u, double phi) const {
    return p_.Kt * p_.Gr * u / r_ - torque(segment(phi), phi);
  }
  Eigen::Vector2d exact(const Eigen::Matrix3d& M, double tau) const {
    const Eigen::Matrix3d E = (M * tau).exp();
    return E.topLeftCorner<2, 2>() * x_ + E.topRightCorner<2, 1>();
  }
  bool crossed(const Eigen::Vector2d& y) const {
    return dir_ * y(1) <= 0 || segment(y(0)) != segment(x_(0));
  }
  // Slips for at most `span`; returns the time advanced.
  double slip(double u, double span) {
    const int s = segment(x_(0));
    const double kvgr = p_.Kv * p_.Gr;
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    M(0, 1) = 1;
    M(1, 0) = -k_[s] / p_.J;
    M(1, 1) = -(p_.Kb + p_.Kt * p_.Gr * kvgr / r_) / p_.J;
    M(1, 2) = (p_.Kt * p_.Gr * u / r_ - m_[s] - p_.Mc * dir_) / p_.J;
    const int grid = 64;
    double lo = 0;
    for (int g = 1; g <= grid; ++g) {
      const double tau = span * g / grid;
      const Eigen::Vector2d y = exact(M, tau);
      if (!crossed(y)) {
        lo = tau;
        if (g == grid) {
          x_ = y;
          return span;
        }
        continue;
      }
      double hi = tau;
      Eigen::Vector2d at_hi = y;
      for (int it = 0; it < 80 && hi - lo > 1e-16 * span; ++it) {
        const double mid = (lo + hi) / 2;
        const Eigen::Vector2d ym = exact(M, mid);
        if (crossed(ym)) {
          hi = mid;
          at_hi = ym;
        } else {
          lo = mid;
        }
      }
      x_ = at_hi;
      if (dir_ * x_(1) <= 0) {
        x_(1) = 0;
        const double net = drive(u, x_(0));
        if (std::abs(net) <= p_.Mc) {
          stuck_ = true;
          dir_ = 0;
        } else {
          dir_ = net > 0 ? 1 : -1;
        }
        return hi;
      }
      // Crossed breakpoint j into segment e: pinned there if trapped by the
      // pre-load jump and the next excursion is below 1e-12 rad.
      const int e = segment(x_(0)), j = std::min(s, e);
      const double below = torque(j, b_[j]), above = torque(j + 1, b_[j]);
      const double motor = p_.Kt * p_.Gr * u / r_;
      const double net = motor - torque(e, b_[j]) - p_.Mc * dir_;
      if (above > below && motor <= above + p_.Mc &&
          motor >= below - p_.Mc && net * dir_ < 0 &&
          x_(1) * x_(1) * p_.J / (2 * std::abs(net)) <= 1e-12) {
        x_ << b_[j], 0;
        stuck_ = true;
        pinned_ = j;
        dir_ = 0;
      }
      return hi;
    }
    return span;
  }

  Params p_;
  double r_;
  double b_[3], k_[4], m_[4];
  Eigen::Vector2d x_ = Eigen::Vector2d::Zero();
  bool stuck_ = true;
  int pinned_ = -1;
  int dir_ = 0;
};

// A voltage that drives the open plate through all spring segments, the
// dead zone (where it sticks) and many reversals.
std::vector<double> rich_voltage(int n, double ts, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, 0.05);
  std::vector<double> u(n);
  for (int k = 0; k < n; ++k) {
    u[k] = 0.45 + 0.75 * std::sin(2 * M_PI * 0.1 * k * ts) + noise(rng);
  }
  return u;
}

TEST(ThrottleParameters, Table43AndSpringTorque) {
  const Params p = Params::table_4_3();
  EXPECT_NEAR(p.Ks1, 0.104851, 1e-6);  // 1.83e-3 N m/deg in N m/rad
  EXPECT_NEAR(p.linear_region_low() / kDeg, 13.14, 1e-12);  // (4.16)
  EXPECT_NEAR(p.linear_region_high() / kDeg, 85, 1e-12);
  EXPECT_TRUE(validate(p).ok());
  // (4.7)-(4.8): the pre-loads at the dead-zone edges, zero inside, h_s2
  // continuous with h_s1 at phi_12, and h_s1 = Ks1 phi + m_s1 (4.18).
  const double low = p.phi_LH - p.delta_phi / 2;
  const double high = p.phi_LH + p.delta_phi / 2;
  EXPECT_NEAR(spring_torque(p, low - 1e-12), -p.M_close, 1e-11);
  EXPECT_EQ(spring_torque(p, low), 0.0);
  EXPECT_EQ(spring_torque(p, p.phi_LH), 0.0);
  EXPECT_EQ(spring_torque(p, high), 0.0);
  EXPECT_NEAR(spring_torque(p, high + 1e-12), p.M_open, 1e-12);
  EXPECT_NEAR(spring_torque(p, p.phi_12),
              spring_torque(p, p.phi_12 - 1e-12), 1e-11);
  for (double deg : {20.0, 45.0, 80.0}) {
    EXPECT_NEAR(spring_torque(p, deg * kDeg), p.Ks1 * deg * kDeg + p.m_s1(),
                1e-15);
  }
  EXPECT_NEAR(spring_torque(p, 88 * kDeg) - spring_torque(p, 86 * kDeg),
              p.Ks2 * 2 * kDeg, 1e-14);
  EXPECT_NEAR(spring_torque(p, 9 * kDeg) - spring_torque(p, 10 * kDeg),
              -p.Ks3 * kDeg, 1e-14);
}

TEST(ThrottleController, PidAndSetPointFilterAsPrinted) {
  // (4.13) read literally: kp e + ki sum(e) + kd (e_k - e_(k-1)).
  const double kp = 2.85, ki = 6.06e-3, kd = -36.96;
  DiscreteFilter<double> c;
  c.configure(throttle_pid(kp, ki, kd));
  double sum = 0, e_prev = 0;
  for (int k = 0; k < 100; ++k) {
    const double e = std::sin(0.3 * k) + 0.1 * k;
    sum += e;
    ASSERT_NEAR(c.step(e), kp * e + ki * sum + kd * (e - e_prev), 1e-11);
    e_prev = e;
  }
  // (4.12) is the Tustin map of a/(p + a) with a Ts = 0.02 (the reading
  // Ts = 1 ms, a = 20 rad/s), to its printed digits.
  const DiscreteTransferFunction<double> f = throttle_setpoint_filter<double>();
  const double half = 0.01;
  EXPECT_NEAR(f.numerator(0), half / (1 + half), 5e-7);
  EXPECT_NEAR(f.numerator(1), half / (1 + half), 5e-7);
  EXPECT_NEAR(f.denominator(1), -(1 - half) / (1 + half), 5e-5);
}

// No spring, no Coulomb friction, constant R: omega relaxes exponentially
// to its final value, phi is its integral.
TEST(ThrottleBody, ViscousOnlyMatchesClosedForm) {
  Params p = Params::table_4_3();
  p.Ks1 = p.Ks2 = p.Ks3 = 0;
  p.M_open = p.M_close = 0;
  p.Mc = 0;
  const double u = 0.8, r = 1.1, kvgr = p.Kv * p.Gr, ts = 1e-3;
  const double c = (p.Kb + p.Kt * p.Gr * kvgr / r) / p.J;
  const double w_inf = p.Kt * p.Gr * u / r / p.J / c;
  ThrottleBody<double> body;
  body.configure(p, 2);
  const double phi0 = 40 * kDeg, w0 = -3;
  body.set_state(phi0, w0);
  double worst = 0;
  for (int k = 1; k <= 200; ++k) {
    ASSERT_TRUE(body.advance(u, r, r, kvgr, ts));
    const double t = k * ts;
    const double w = w_inf + (w0 - w_inf) * std::exp(-c * t);
    const double phi = phi0 + w_inf * t + (w0 - w_inf) * (1 - std::exp(-c * t)) / c;
    worst = std::max(worst, std::abs(body.phi() - phi) + std::abs(body.omega() - w));
  }
  // RK4 on w' = -c (w - w_inf) with step h: the error grows as
  // t c (c h)^4 / 120 |w0 - w_inf| e^(-c t), at most (c h)^4 / (120 e)
  // |w0 - w_inf| (2e-8 here); phi's error is smaller by about 1/c.
  const double h = ts / 2;
  const double bound = std::pow(c * h, 4) / (120 * std::exp(1.0)) *
                       std::abs(w0 - w_inf) * (1 + 1 / c);
  EXPECT_LT(worst, 1.1 * bound) << worst << " vs bound " << bound;
}

// No spring, u = 0: Coulomb and viscous friction stop the plate at
// t* = ln(1 + w0 / a) / c, a = Mc / (J c), and it stays stuck.
TEST(ThrottleBody, CoulombStopMatchesClosedForm) {
  Params p = Params::table_4_3();
  p.Ks1 = p.Ks2 = p.Ks3 = 0;
  p.M_open = p.M_close = 0;
  const double r = 1.4, kvgr = p.Kv * p.Gr, ts = 1e-3;
  const double c = (p.Kb + p.Kt * p.Gr * kvgr / r) / p.J;
  const double a = p.Mc / (p.J * c);
  const double w0 = 2.0, phi0 = 30 * kDeg;
  const double t_stop = std::log(1 + w0 / a) / c;
  const double phi_stop = phi0 - a * t_stop + (w0 + a) * (1 - std::exp(-c * t_stop)) / c;
  ThrottleBody<double> body;
  body.configure(p, 1);
  body.set_state(phi0, w0);
  int k_stop = -1;
  for (int k = 1; k <= 300; ++k) {
    ASSERT_TRUE(body.advance(0.0, r, r, kvgr, ts));
    if (k_stop < 0 && body.stuck()) k_stop = k;
  }
  EXPECT_EQ(k_stop, static_cast<int>(std::ceil(t_stop / ts))) << t_stop;
  EXPECT_TRUE(body.stuck());
  EXPECT_EQ(body.omega(), 0.0);
  // The RK4 error of w, at most (c h)^4 / 120 (w0 + a) (see above),
  // integrated over the decay time 1/c; the stop itself is located to
  // machine precision.
  const double bound = std::pow(c * ts, 4) / 120 * (w0 + a) / c;
  EXPECT_NEAR(body.phi(), phi_stop, bound) << t_stop;
  EXPECT_EQ(body.events(), 1);
}

// Stuck in the linear spring region with R rising linearly: the motor
// torque Kt Gr u / R(t) falls, and the plate breaks away (closing) in the
// interval where Kt Gr u / R(t) = M_s - Mc, not before.
TEST(ThrottleBody, BreakawayWithRisingResistance) {
  const Params p = Params::table_4_3();
  const double phi0 = 40 * kDeg, kvgr = p.Kv * p.Gr, ts = 1e-3;
  const double ms = spring_torque(p, phi0);
  const double u = 1.0 * ms / (p.Kt * p.Gr);  // balances at R = 1
  // R(t) = 1 + 0.5 t: breakaway at R_b = Kt Gr u / (ms - Mc).
  const double r_b = p.Kt * p.Gr * u / (ms - p.Mc);
  const double t_b = (r_b - 1) / 0.5;
  ThrottleBody<double> body;
  body.configure(p, 2);
  body.set_state(phi0, 0);
  for (int k = 0; k < 2000; ++k) {
    const double t = k * ts;
    ASSERT_TRUE(body.advance(u, 1 + 0.5 * t, 1 + 0.5 * (t + ts), kvgr, ts));
    if (t + ts < t_b) {
      ASSERT_EQ(body.phi(), phi0) << t;
      ASSERT_TRUE(body.stuck());
    } else {
      EXPECT_LT(body.phi(), phi0) << "moved in the breakaway interval";
      EXPECT_LT(body.omega(), 0.0);
      break;
    }
  }
}

// Samples spent in each spring segment (h_s3, dead zone, h_s1, h_s2) and
// stuck, by the reference.
struct Coverage {
  int segment[4] = {0, 0, 0, 0};
  int stuck = 0;
  int pinned = 0;
};

double reference_error(int substeps, Coverage* coverage = nullptr) {
  const Params p = Params::table_4_3();
  const double r = 1.4, kvgr = p.Kv * p.Gr, ts = 1e-3;
  const int n = 10000;
  const std::vector<double> u = rich_voltage(n, ts, 3);
  ThrottleBody<double> body;
  body.configure(p, substeps);
  body.set_state(30 * kDeg, 0);
  ReferencePlate reference(p, r);
  reference.set_state(30 * kDeg, 0);
  double worst = 0;
  Coverage seen;
  for (int k = 0; k < n; ++k) {
    EXPECT_TRUE(body.advance(u[k], r, r, kvgr, ts));
    EXPECT_TRUE(reference.advance(u[k], ts));
    worst = std::max(worst, std::abs(body.phi() - reference.phi()));
    ++seen.segment[reference.current_segment()];
    if (reference.stuck()) ++seen.stuck;
    if (reference.pinned()) ++seen.pinned;
  }
  if (coverage) *coverage = seen;
  return worst;
}

// Spring segments, dead zone, stick-slip and reversals: RK4 with located
// events against the exact piecewise solution, converging at fourth order.
TEST(ThrottleBody, MatchesMatrixExponentialReference) {
  Coverage seen;
  const double e1 = reference_error(1, &seen);
  const double e2 = reference_error(2);
  const double e4 = reference_error(4);
  std::printf("max |phi - phi_ref| (rad), substeps 1/2/4: %.3e %.3e %.3e; "
              "samples in h_s3/dead zone/h_s1/h_s2 %d/%d/%d/%d, stuck %d, "
              "pinned %d\n",
              e1, e2, e4, seen.segment[0], seen.segment[1], seen.segment[2],
              seen.segment[3], seen.stuck, seen.pinned);
  for (int s = 0; s < 4; ++s) {
    EXPECT_GT(seen.segment[s], 10) << "the voltage must sweep segment " << s;
  }
  EXPECT_GT(seen.stuck, 10) << "and make the plate stick";
  EXPECT_LT(e2, 1e-7);
  EXPECT_LT(e4, 1e-8);
  EXPECT_GT(e1 / e2, 8.0) << "fourth order: halving the step divides by 16";
}

// Pushed from the dead zone against the closing pre-load M_close with
// Mc < |T_m| < M_close + Mc, the plate bounces on the edge phi_LH -
// delta_phi/2 with ever smaller excursions (a Zeno sequence) and ends
// pinned there; a stronger push frees it into h_s3.
TEST(ThrottleBody, ZenoBouncesEndPinnedAtTheDeadZoneEdge) {
  const Params p = Params::table_4_3();
  const double r = 1.4, kvgr = p.Kv * p.Gr, ts = 1e-3;
  const double edge = p.phi_LH - p.delta_phi / 2;
  const double u_trap = -0.02 * r / (p.Kt * p.Gr);  // T_m = -0.02 N m
  const double u_free = -0.045 * r / (p.Kt * p.Gr);
  ThrottleBody<double> body;
  body.configure(p, 2);
  body.set_state(p.phi_LH, 0);
  ReferencePlate reference(p, r);
  reference.set_state(p.phi_LH, 0);
  double worst = 0;
  for (int k = 0; k < 600; ++k) {
    const double u = k < 300 ? u_trap : u_free;
    ASSERT_TRUE(body.advance(u, r, r, kvgr, ts)) << k;
    ASSERT_TRUE(reference.advance(u, ts)) << k;
    worst = std::max(worst, std::abs(body.phi() - reference.phi()));
    if (k == 299) {
      EXPECT_TRUE(body.pinned());
      EXPECT_EQ(body.phi(), edge);
      EXPECT_EQ(body.omega(), 0.0);
      EXPECT_GT(body.events(), 4) << "it bounces before it is pinned";
      EXPECT_LT(body.events(), 200);
    }
  }
  EXPECT_FALSE(body.pinned());
  EXPECT_LT(body.phi(), edge - 0.1 * kDeg) << "freed into h_s3";
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace ctid
