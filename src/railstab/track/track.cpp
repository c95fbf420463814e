// Track centreline and moving track frame (thesis chapter 3 with ERRATA 1-5).
//
// Along each segment, with local arc length u = s - s_i in [0, L]:
//   curvature  k(u)   = k_i + (k_end - k_i) u / L     (k_end = k_i on tangent/arc)
//   heading    psi(u) = psi_i + k_i u + (k_end - k_i) u^2 / (2 L)
//                     = psi_i + u (k_i + k(u)) / 2     (exact for linear k)
//   position   (x, y)(u) = (x_i, y_i) + integral_0^u (cos psi, sin psi) dt
//   cant       h(u)   = h_i + (h_end - h_i) u / L
//   roll       phi    = -asin(h / D)                  (ERRATA 2; h > 0 raises the right rail)
// The centreline stays horizontal (ERRATA 2: cant is a rotation, not a height)
// and the spec has no vertical profile, so grade = 0 and z = start_z.
#include <railstab/track/track.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace railstab {
namespace {

// ---- Quadrature for the clothoid position --------------------------------------

constexpr int kGaussNodes = 8;

struct GaussLegendreRule {
  std::array<double, kGaussNodes> node{}, weight{};
};

// Nodes are the roots of the Legendre polynomial P_n, found by Newton's method
// from the classical first guess x_i ~ cos(pi (i + 3/4) / (n + 1/2));
// weights w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2). Computed once, not tabulated,
// so the digits cannot be mistyped.
GaussLegendreRule make_gauss_legendre_rule() {
  constexpr int n = kGaussNodes;
  GaussLegendreRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double p_n = 0.0, p_n_minus_1 = 0.0;
    auto evaluate_legendre = [&](double at) {
      // Bonnet: (m + 1) P_{m+1} = (2m + 1) x P_m - m P_{m-1}.
      double p_prev = 1.0, p = at;
      for (int m = 1; m < n; ++m) {
        const double p_next = ((2 * m + 1) * at * p - m * p_prev) / (m + 1);
        p_prev = p;
        p = p_next;
      }
      p_n = p;
      p_n_minus_1 = p_prev;
    };
    // P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1).
    auto derivative = [&](double at) { return n * (at * p_n - p_n_minus_1) / (at * at - 1.0); };
    for (int iteration = 0; iteration < 100; ++iteration) {
      evaluate_legendre(x);
      const double step = p_n / derivative(x);
      x -= step;
      if (std::abs(step) <= 1e-16) break;
    }
    evaluate_legendre(x);
    const double dp = derivative(x);
    rule.node[i] = x;
    rule.weight[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

const GaussLegendreRule& gauss_legendre_rule() {
  static const GaussLegendreRule rule = make_gauss_legendre_rule();
  return rule;
}

// Largest clothoid quadrature piece. Over a piece the heading changes by at
// most max|k| * h <= 0.5 rad. The n-point Gauss-Legendre error on exp(i psi)
// is about h Phi^(2n) (n!)^4 / ((2n + 1) ((2n)!)^3) for a heading change Phi,
// ~1e-28 h for n = 8 and Phi = 0.5: exact to rounding with a wide margin
// (checked: the tests pass with 5 nodes, or 8 nodes and 3 rad pieces; 4 fail).
// 8 rather than 16 nodes halves the cost of a clothoid evaluation.
constexpr double kMaxPieceLength_m = 100.0;
constexpr double kMaxPieceHeadingChange_rad = 0.5;
constexpr int kMaxPiecesPerClothoid = 1000000;

// integral_a^b (cos psi(t), sin psi(t)) dt,  psi(t) = psi0 + k0 t + dk t^2 / 2,
// with t the local arc length from the clothoid start.
Eigen::Vector2d clothoid_chord(double psi0, double k0, double dk, double a, double b) {
  const GaussLegendreRule& rule = gauss_legendre_rule();
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum_cos = 0.0, sum_sin = 0.0;
  for (int i = 0; i < kGaussNodes; ++i) {
    const double t = mid + half * rule.node[i];
    const double psi = psi0 + t * (k0 + 0.5 * dk * t);
    sum_cos += rule.weight[i] * std::cos(psi);
    sum_sin += rule.weight[i] * std::sin(psi);
  }
  return {half * sum_cos, half * sum_sin};
}

// sin(x) / x, with its Taylor series where the quotient would be 0/0.
double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;  // next term x^4/120 < 1e-18
  return std::sin(x) / x;
}

// Constant curvature k (arc, or tangent with k = 0): ERRATA 3,
//   x = (sin(psi0 + k u) - sin psi0) / k,  y = -(cos(psi0 + k u) - cos psi0) / k,
// rewritten with sum-to-product identities as
//   (x, y) = u sinc(k u / 2) (cos, sin)(psi0 + k u / 2),
// which has no 1/k and no cancellation as k -> 0.
Eigen::Vector2d constant_curvature_chord(double psi0, double k, double u) {
  const double half_turn = 0.5 * k * u;
  const double chord = u * sinc(half_turn);
  return {chord * std::cos(psi0 + half_turn), chord * std::sin(psi0 + half_turn)};
}

// ---- Rotations and frame rates ---------------------------------------------------

// Sines and cosines of the three frame angles, computed once per evaluation.
struct FrameTrig {
  double s_phi, c_phi, s_theta, c_theta, s_psi, c_psi;  // roll, grade, heading
  FrameTrig(double roll, double grade, double heading)
      : s_phi(std::sin(roll)), c_phi(std::cos(roll)), s_theta(std::sin(grade)),
        c_theta(std::cos(grade)), s_psi(std::sin(heading)), c_psi(std::cos(heading)) {}
};

// A = Az(psi) Ay(theta) Ax(phi) multiplied out, with the right-handed
// Rz = [[c,-s,0],[s,c,0],[0,0,1]], Ry = [[c,0,s],[0,1,0],[-s,0,c]],
// Rx = [[1,0,0],[0,c,-s],[0,s,c]].
Eigen::Matrix3d rotation_zyx(const FrameTrig& t) {
  Eigen::Matrix3d a;
  a << t.c_psi * t.c_theta, t.c_psi * t.s_theta * t.s_phi - t.s_psi * t.c_phi,
      t.c_psi * t.s_theta * t.c_phi + t.s_psi * t.s_phi,  //
      t.s_psi * t.c_theta, t.s_psi * t.s_theta * t.s_phi + t.c_psi * t.c_phi,
      t.s_psi * t.s_theta * t.c_phi - t.c_psi * t.s_phi,  //
      -t.s_theta, t.c_theta * t.s_phi, t.c_theta * t.c_phi;
  return a;
}

// Time rates of the frame angles (roll phi, grade theta, heading psi).
struct AngleRates {
  double phi, theta, psi;
};

// Angular velocity of A = Az(psi) Ay(theta) Ax(phi) in its own (T) frame:
//   w = Ax^T Ay^T (0, 0, psi') + Ax^T (0, theta', 0) + (phi', 0, 0)
//   w_x = phi' - s_theta psi'
//   w_y = c_phi theta' + s_phi c_theta psi'
//   w_z = -s_phi theta' + c_phi c_theta psi'
Eigen::Vector3d angular_velocity_in_T(const FrameTrig& t, const AngleRates& rate) {
  return {rate.phi - t.s_theta * rate.psi,
          t.c_phi * rate.theta + t.s_phi * t.c_theta * rate.psi,
          -t.s_phi * rate.theta + t.c_phi * t.c_theta * rate.psi};
}

// Time derivative of the components above (product rule: the trigonometric
// factors change at the angle rates, the rates change at rate2).
Eigen::Vector3d angular_acceleration_in_T(const FrameTrig& t, const AngleRates& rate,
                                          const AngleRates& rate2) {
  return {rate2.phi - t.c_theta * rate.theta * rate.psi - t.s_theta * rate2.psi,
          -t.s_phi * rate.phi * rate.theta + t.c_phi * rate2.theta +
              t.c_phi * rate.phi * t.c_theta * rate.psi -
              t.s_phi * t.s_theta * rate.theta * rate.psi + t.s_phi * t.c_theta * rate2.psi,
          -t.c_phi * rate.phi * rate.theta - t.s_phi * rate2.theta -
              t.s_phi * rate.phi * t.c_theta * rate.psi -
              t.c_phi * t.s_theta * rate.theta * rate.psi + t.c_phi * t.c_theta * rate2.psi};
}

// ---- Validation -------------------------------------------------------------------

[[noreturn]] void reject(const std::string& what) { throw std::invalid_argument("track: " + what); }

std::string segment_label(int index, TrackSegmentKind kind) {
  return "segment " + std::to_string(index) + " (" + std::string(track_segment_kind_name(kind)) + ")";
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

void require_finite(double value, const std::string& name) {
  if (!std::isfinite(value)) reject(name + " must be finite, got " + number(value));
}

// Cant must stay below the rail contact distance: roll = -asin(cant / D).
void require_cant_below_contact_distance(double cant_m, double distance_m,
                                         const std::string& where) {
  if (!(std::abs(cant_m) < distance_m))
    reject(where + " cant must satisfy |cant| < rail_contact_distance_m = " + number(distance_m) +
           " m, got " + number(cant_m) + " m");
}

void validate_track_start(const TrackSpec& spec) {
  const double d = spec.rail_contact_distance_m;
  if (!(std::isfinite(d) && d > 0.0))
    reject("rail_contact_distance_m must be positive and finite, got " + number(d) + " m");
  if (spec.segments.empty()) reject("needs at least one segment");
  require_finite(spec.start_x_m, "start_x_m");
  require_finite(spec.start_y_m, "start_y_m");
  require_finite(spec.start_z_m, "start_z_m");
  require_finite(spec.start_heading_rad, "start_heading_rad");
  require_finite(spec.start_curvature_per_m, "start_curvature_per_m");
  require_cant_below_contact_distance(spec.start_cant_m, d, "start");
}

std::string out_of_track_message(double s_m, double length_m) {
  return "arc length " + number(s_m) + " m is outside the track [0, " + number(length_m) + "] m";
}

}  // namespace

// ---- Track --------------------------------------------------------------------------

Eigen::Matrix3d track_rotation(double heading_rad, double grade_rad, double roll_rad) {
  return rotation_zyx(FrameTrig(roll_rad, grade_rad, heading_rad));
}

Track::Track(const TrackSpec& spec) : spec_(spec) {
  validate_track_start(spec_);
  const int count = static_cast<int>(spec_.segments.size());
  starts_.reserve(count);
  laws_.reserve(count);
  SegmentStart start{0.0,
                     spec_.start_x_m,
                     spec_.start_y_m,
                     spec_.start_heading_rad,
                     spec_.start_curvature_per_m,
                     spec_.start_cant_m};
  for (int i = 0; i < count; ++i) {
    starts_.push_back(start);
    append_segment(i, spec_.segments[i]);
    // The next segment starts exactly where this one's own law ends.
    start = state_at(i, laws_[i].length_m);
  }
  total_length_m_ = start.s_m;
  if (spec_.irregularities) irregularities_ = std::make_shared<const TrackIrregularities>(*spec_.irregularities);
}

// Validates segment `index` against its (already chained) start and records
// its law; for a clothoid also the quadrature piece starts.
void Track::append_segment(int index, const TrackSegmentSpec& segment) {
  const SegmentStart& start = starts_[index];
  const std::string label = segment_label(index, segment.kind);
  if (!(std::isfinite(segment.length_m) && segment.length_m > 0.0))
    reject(label + ": length must be positive and finite, got " + number(segment.length_m) + " m");
  require_cant_below_contact_distance(segment.end_cant_m, spec_.rail_contact_distance_m,
                                      label + ": end");

  SegmentLaw law{segment.kind, segment.length_m, start.curvature_per_m, segment.end_cant_m,
                 0.0, 0, 0};
  switch (segment.kind) {
    case TrackSegmentKind::tangent:
      if (start.curvature_per_m != 0.0)
        reject(label + ": a tangent needs start curvature 0, got " +
               number(start.curvature_per_m) +
               " 1/m (the previous segment ends curved; insert a clothoid)");
      break;
    case TrackSegmentKind::arc:
      break;  // constant curvature = start curvature; end_curvature_per_m is not used
    case TrackSegmentKind::clothoid: {
      require_finite(segment.end_curvature_per_m, label + ": end_curvature_per_m");
      law.end_curvature_per_m = segment.end_curvature_per_m;
      const double max_curvature =
          std::max(std::abs(start.curvature_per_m), std::abs(segment.end_curvature_per_m));
      double piece_limit = kMaxPieceLength_m;
      if (max_curvature * piece_limit > kMaxPieceHeadingChange_rad)
        piece_limit = kMaxPieceHeadingChange_rad / max_curvature;
      const double pieces = std::ceil(segment.length_m / piece_limit);
      if (pieces > kMaxPiecesPerClothoid)
        reject(label + ": curvature " + number(max_curvature) + " 1/m over " +
               number(segment.length_m) + " m is too sharp to integrate");
      law.piece_count = std::max(1, static_cast<int>(pieces));
      law.piece_length_m = segment.length_m / law.piece_count;
      law.first_piece = static_cast<int>(piece_xy_.size());
      break;
    }
  }
  laws_.push_back(law);

  if (law.kind != TrackSegmentKind::clothoid) return;
  // Piece starts by summing whole pieces: x_{j+1} = x_j + integral over piece j.
  const double dk = (law.end_curvature_per_m - start.curvature_per_m) / law.length_m;
  Eigen::Vector2d xy(start.x_m, start.y_m);
  for (int j = 0; j < law.piece_count; ++j) {
    piece_xy_.push_back(xy);
    xy += clothoid_chord(start.heading_rad, start.curvature_per_m, dk, j * law.piece_length_m,
                         (j + 1) * law.piece_length_m);
  }
}

// Binary search over the segment starts; at a joint the later segment.
int Track::segment_containing(double s_m) const {
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), s_m,
                                      [](double s, const SegmentStart& a) { return s < a.s_m; });
  return std::max(0, static_cast<int>(after - starts_.begin()) - 1);
}

Eigen::Vector2d Track::centreline_xy(int segment, double u_m) const {
  const SegmentStart& start = starts_[segment];
  const SegmentLaw& law = laws_[segment];
  if (law.kind != TrackSegmentKind::clothoid)
    return Eigen::Vector2d(start.x_m, start.y_m) +
           constant_curvature_chord(start.heading_rad, start.curvature_per_m, u_m);
  // Uniform pieces: the piece index is a division, clamped for u = L (and
  // rounding just past it).
  const int piece = std::clamp(static_cast<int>(u_m / law.piece_length_m), 0, law.piece_count - 1);
  const double dk = (law.end_curvature_per_m - start.curvature_per_m) / law.length_m;
  return piece_xy_[law.first_piece + piece] +
         clothoid_chord(start.heading_rad, start.curvature_per_m, dk, piece * law.piece_length_m,
                        u_m);
}

Track::SegmentStart Track::state_at(int segment, double u_m) const {
  const SegmentStart& start = starts_[segment];
  const SegmentLaw& law = laws_[segment];
  // std::lerp is exact at both ends (fraction 0 and 1), so the chained start
  // of the next segment carries exactly the specified end curvature and cant.
  const double fraction = u_m / law.length_m;
  const double curvature = std::lerp(start.curvature_per_m, law.end_curvature_per_m, fraction);
  const Eigen::Vector2d xy = centreline_xy(segment, u_m);
  return {start.s_m + u_m,
          xy.x(),
          xy.y(),
          start.heading_rad + u_m * 0.5 * (start.curvature_per_m + curvature),
          curvature,
          std::lerp(start.cant_m, law.end_cant_m, fraction)};
}

double Track::uniform_stretch_end_m(double s_m) const {
  auto uniform = [&](int i) {
    return laws_[size_t(i)].kind != TrackSegmentKind::clothoid &&
           laws_[size_t(i)].end_cant_m == starts_[size_t(i)].cant_m;
  };
  int i = segment_containing(s_m);
  if (!uniform(i)) return s_m;
  while (i + 1 < int(laws_.size()) && uniform(i + 1) &&
         starts_[size_t(i + 1)].curvature_per_m == starts_[size_t(i)].curvature_per_m &&
         starts_[size_t(i + 1)].cant_m == starts_[size_t(i)].cant_m)
    ++i;
  return starts_[size_t(i)].s_m + laws_[size_t(i)].length_m;
}

TrackGeometryPoint Track::geometry_at(double s_m) const {
  if (!(s_m >= 0.0 && s_m <= total_length_m_))
    throw std::out_of_range(out_of_track_message(s_m, total_length_m_));
  const int segment = segment_containing(s_m);
  const SegmentStart& start = starts_[segment];
  const SegmentLaw& law = laws_[segment];
  const SegmentStart here = state_at(segment, s_m - start.s_m);

  TrackGeometryPoint g;
  g.s_m = s_m;
  g.segment = segment;
  g.p_WT_W = Eigen::Vector3d(here.x_m, here.y_m, spec_.start_z_m);
  g.heading_rad = here.heading_rad;
  g.curvature_per_m = here.curvature_per_m;
  g.curvature_rate_per_m2 = (law.end_curvature_per_m - start.curvature_per_m) / law.length_m;
  g.cant_m = here.cant_m;
  // phi = -asin(h / D):  phi' = -h' / sqrt(D^2 - h^2),
  // phi'' = -h'^2 h / (D^2 - h^2)^(3/2)   (h'' = 0: cant is linear in s).
  const double d = spec_.rail_contact_distance_m;
  const double cant_rate = (law.end_cant_m - start.cant_m) / law.length_m;
  const double root = std::sqrt((d - here.cant_m) * (d + here.cant_m));  // sqrt(D^2 - h^2)
  g.roll_rad = -std::asin(here.cant_m / d);
  g.roll_rate_per_m = -cant_rate / root;
  g.roll_rate2_per_m2 = -cant_rate * cant_rate * here.cant_m / (root * root * root);
  // No vertical profile in the spec: grade and its derivatives stay 0.
  g.grade_rad = g.grade_rate_per_m = g.grade_rate2_per_m2 = 0.0;
  return g;
}

// The frame moves with ds/dt = V, so every time derivative is V times the
// arc-length derivative (ERRATA 4): psi' = V k, theta' = V grade',
// phi' = V roll', and the second rates carry V^2. With a speed rate
// dV/dt = a (a speed ramp), d2(angle)/dt2 = V^2 angle'' + a angle' and the
// origin acceleration gains the tangential a t (docs/speed_ramp.md).
TrackFrameKinematics Track::frame_at(double s_m, double speed_m_per_s,
                                     double speed_rate_m_per_s2) const {
  TrackFrameKinematics k;
  k.geometry = geometry_at(s_m);
  const TrackGeometryPoint& g = k.geometry;
  const double v = speed_m_per_s;
  const FrameTrig trig(g.roll_rad, g.grade_rad, g.heading_rad);
  k.R_WT = rotation_zyx(trig);

  const AngleRates rate{v * g.roll_rate_per_m, v * g.grade_rate_per_m, v * g.curvature_per_m};
  AngleRates rate2{v * v * g.roll_rate2_per_m2, v * v * g.grade_rate2_per_m2,
                   v * v * g.curvature_rate_per_m2};
  const double a = speed_rate_m_per_s2;
  if (a != 0.0)
    rate2 = AngleRates{rate2.phi + a * g.roll_rate_per_m, rate2.theta + a * g.grade_rate_per_m,
                       rate2.psi + a * g.curvature_per_m};
  k.w_WT_T = angular_velocity_in_T(trig, rate);
  k.alpha_WT_T = angular_acceleration_in_T(trig, rate, rate2);

  // Unit tangent of a centreline with heading psi and grade theta (the frame's
  // x axis, A e_x; with the right-handed Ay a positive grade points it
  // downwards), and its arc-length derivative:
  //   t = (c_theta c_psi, c_theta s_psi, -s_theta)
  //   dt/ds = (-s_theta theta' c_psi - c_theta s_psi k,
  //            -s_theta theta' s_psi + c_theta c_psi k,
  //            -c_theta theta')
  // Origin velocity V t and acceleration V^2 dt/ds, both expressed in T.
  const Eigen::Vector3d tangent(trig.c_theta * trig.c_psi, trig.c_theta * trig.s_psi,
                                -trig.s_theta);
  const double grade_rate = g.grade_rate_per_m, curvature = g.curvature_per_m;
  const Eigen::Vector3d tangent_rate(
      -trig.s_theta * grade_rate * trig.c_psi - trig.c_theta * trig.s_psi * curvature,
      -trig.s_theta * grade_rate * trig.s_psi + trig.c_theta * trig.c_psi * curvature,
      -trig.c_theta * grade_rate);
  k.v_WT_T = k.R_WT.transpose() * (v * tangent);
  k.a_WT_T = k.R_WT.transpose() * (v * v * tangent_rate);
  if (a != 0.0) k.a_WT_T += k.R_WT.transpose() * (a * tangent);
  if (irregularities_) {
    // y_left = alignment + gauge/2, y_right = alignment - gauge/2,
    // z_left = level + cross_level/2, z_right = level - cross_level/2.
    const TrackIrregularities& irr = *irregularities_;
    const double alignment = irr.at(IrregularityChannel::alignment, s_m).f;
    const double level = irr.at(IrregularityChannel::level, s_m).f;
    const double cross_level = irr.at(IrregularityChannel::cross_level, s_m).f;
    const double gauge = irr.at(IrregularityChannel::gauge, s_m).f;
    k.rails[0] = {alignment + 0.5 * gauge, level + 0.5 * cross_level};
    k.rails[1] = {alignment - 0.5 * gauge, level - 0.5 * cross_level};
  }
  return k;
}

}  // namespace railstab
