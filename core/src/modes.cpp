#include "softtune/modes.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "softtune/support/run_limit.h"
#include <algorithm>
#include <cmath>
#include <numbers>

#include "softtune/discrete_analysis.h"

namespace softtune::modes {
namespace {

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// A row's anchor in the world with the coordinates moved by `delta`; a static anchor is a world point.
Eigen::Vector2d anchor(const LinearModel& m, int body, const Eigen::Vector2d& r, const Eigen::VectorXd& delta) {
  if (body < 0) return r;
  const int o = kBodyDofs * body;
  return m.bodies[body].position + Eigen::Vector2d(delta[o], delta[o + 1]) + rotated(r, delta[o + 2]);
}

// The row's exact position function C(q) (modes.h, Row).
double row_value(const LinearModel& m, const Row& row, const Eigen::VectorXd& delta) {
  const double theta_a = row.body_a >= 0 ? delta[kBodyDofs * row.body_a + 2] : 0.0;
  const double theta_b = row.body_b >= 0 ? delta[kBodyDofs * row.body_b + 2] : 0.0;
  if (row.angular) return theta_b - theta_a;
  const Eigen::Vector2d d = anchor(m, row.body_b, row.r_b, delta) - anchor(m, row.body_a, row.r_a, delta);
  switch (row.frame) {
    case AxisFrame::world: return row.axis.dot(d);
    case AxisFrame::body_a: return rotated(row.axis, theta_a).dot(d);
    case AxisFrame::along_anchors: return d.norm();
  }
  return 0.0;
}

std::vector<int> touched(const Row& row) {
  std::vector<int> out;
  for (int b : {row.body_a, row.body_b}) {
    if (b < 0) continue;
    for (int k = 0; k < kBodyDofs; ++k) out.push_back(kBodyDofs * b + k);
  }
  return out;
}

constexpr double kJacobianStep = 1e-6;  // m or rad
constexpr double kHessianStep = 1e-4;

// Poles of a continuous pair: a complex root s, or two real roots (over-damped): omega^2 = s1 s2.
std::optional<Pole> continuous_pole(const std::vector<std::complex<double>>& roots) {
  if (roots.empty()) return std::nullopt;
  double omega = 0.0, zeta = 0.0;
  if (roots.front().imag() != 0.0) {
    omega = std::abs(roots.front());
    zeta = -roots.front().real() / omega;
  } else {
    if (roots.size() < 2) return std::nullopt;
    const double s1 = roots[0].real(), s2 = roots[1].real();
    if (!(s1 * s2 > 0.0)) return std::nullopt;
    omega = std::sqrt(s1 * s2);
    zeta = -(s1 + s2) / (2.0 * omega);
  }
  if (!(omega > 0.0) || !std::isfinite(omega)) return std::nullopt;
  return Pole{omega / (2.0 * std::numbers::pi), zeta == 0.0 ? 0.0 : zeta};
}

std::optional<Pole> discrete_pole(const std::vector<std::complex<double>>& roots, double h) {
  if (roots.empty()) return std::nullopt;
  const std::complex<double> z1 = roots.front();
  const std::complex<double> z2 = z1.imag() != 0.0 ? std::conj(z1) : (roots.size() > 1 ? roots[1] : z1);
  if (z1.imag() == 0.0 && roots.size() < 2) return std::nullopt;
  Pole p;
  if (!achieved_from_poles(z1, z2, h, p.frequency_hz, p.damping_ratio)) return std::nullopt;
  return p;
}

// Each eigenvalue (with its position part y) goes to the undamped mode it overlaps most, |phi^T M y|^2 /
// (y^H M y): a complex root fills a mode, a real root half of one (an over-damped pair). Greedy, largest
// overlap first, so a mode never takes more than its two poles.
std::vector<std::vector<std::complex<double>>> assign_roots(const Eigen::VectorXcd& values, const Eigen::MatrixXcd& vectors,
                                                            const Eigen::MatrixXd& phi, const Eigen::MatrixXd& mass) {
  const int d = static_cast<int>(phi.cols());
  struct Candidate { double overlap; int mode, root; };
  std::vector<Candidate> candidates;
  const Eigen::MatrixXcd m_phi = (mass * phi).cast<std::complex<double>>();
  for (int j = 0; j < values.size(); ++j) {
    if (values[j].imag() < 0.0) continue;  // the conjugate of a root already listed
    const Eigen::VectorXcd y = vectors.col(j).head(d);
    const double norm = std::real(y.dot(mass.cast<std::complex<double>>() * y));
    if (!(norm > 0.0)) continue;
    for (int i = 0; i < d; ++i) candidates.push_back({std::norm(m_phi.col(i).dot(y)) / norm, i, j});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.overlap > b.overlap; });
  std::vector<std::vector<std::complex<double>>> out(d);
  std::vector<int> capacity(d, 2);
  std::vector<bool> used(values.size(), false);
  for (const Candidate& c : candidates) {
    if (used[c.root]) continue;
    const int weight = values[c.root].imag() != 0.0 ? 2 : 1;
    if (capacity[c.mode] < weight) continue;
    capacity[c.mode] -= weight;
    used[c.root] = true;
    out[c.mode].push_back(values[c.root]);
  }
  return out;
}

}  // namespace

std::string_view dof_word(Dof d) {
  switch (d) {
    case Dof::x: return "surge";
    case Dof::y: return "heave";
    case Dof::angle: return "pitch";
  }
  return "";
}

Eigen::RowVectorXd row_jacobian(const LinearModel& m, const Row& row) {
  const int n = kBodyDofs * static_cast<int>(m.bodies.size());
  Eigen::RowVectorXd j = Eigen::RowVectorXd::Zero(n);
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
  for (int k : touched(row)) {
    delta[k] = kJacobianStep;
    const double plus = row_value(m, row, delta);
    delta[k] = -kJacobianStep;
    const double minus = row_value(m, row, delta);
    delta[k] = 0.0;
    j[k] = (plus - minus) / (2.0 * kJacobianStep);
  }
  return j;
}

Eigen::MatrixXd row_hessian(const LinearModel& m, const Row& row) {
  const int n = kBodyDofs * static_cast<int>(m.bodies.size());
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
  const double e = kHessianStep;
  const std::vector<int> idx = touched(row);
  for (std::size_t p = 0; p < idx.size(); ++p) {
    for (std::size_t q = p; q < idx.size(); ++q) {
      auto at = [&](double sp, double sq) {
        delta.setZero();
        delta[idx[p]] += sp;
        delta[idx[q]] += sq;
        return row_value(m, row, delta);
      };
      const double v = (at(e, e) - at(e, -e) - at(-e, e) + at(-e, -e)) / (4.0 * e * e);
      h(idx[p], idx[q]) = h(idx[q], idx[p]) = v;
    }
  }
  return h;
}

double rigid_row_forces(LinearModel& m) {
  const int n = kBodyDofs * static_cast<int>(m.bodies.size());
  Eigen::VectorXd applied = Eigen::VectorXd::Zero(n);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) applied.segment<2>(kBodyDofs * b) = m.bodies[b].mass * m.gravity;
  std::vector<int> rigid;
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    if (m.rows[i].rigid) rigid.push_back(static_cast<int>(i));
    else applied += row_jacobian(m, m.rows[i]).transpose() * m.rows[i].force;
  }
  if (rigid.empty()) return applied.norm();
  Eigen::MatrixXd jt(n, rigid.size());
  for (std::size_t k = 0; k < rigid.size(); ++k) jt.col(k) = row_jacobian(m, m.rows[rigid[k]]).transpose();
  const Eigen::VectorXd lambda = jt.completeOrthogonalDecomposition().solve(-applied);
  for (std::size_t k = 0; k < rigid.size(); ++k) m.rows[rigid[k]].force = lambda[k];
  return (jt * lambda + applied).norm();
}

ReducedSystem reduce(const LinearModel& m) {
  const int n = kBodyDofs * static_cast<int>(m.bodies.size());
  ReducedSystem s;
  std::vector<Eigen::RowVectorXd> rigid;
  for (const Row& row : m.rows) {
    if (row.rigid) rigid.push_back(row_jacobian(m, row));
  }
  if (rigid.empty()) {
    s.null_space = Eigen::MatrixXd::Identity(n, n);
  } else {
    Eigen::MatrixXd j(rigid.size(), n);
    for (std::size_t k = 0; k < rigid.size(); ++k) j.row(k) = rigid[k];
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeFullV);
    const Eigen::VectorXd& sigma = svd.singularValues();
    int rank = 0;
    for (int k = 0; k < sigma.size(); ++k) rank += sigma[k] > 1e-9 * sigma[0] ? 1 : 0;
    s.null_space = svd.matrixV().rightCols(n - rank);
  }
  Eigen::VectorXd mass(n);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    mass.segment<3>(kBodyDofs * b) << m.bodies[b].mass, m.bodies[b].mass, m.bodies[b].inertia;
  }
  const Eigen::MatrixXd& nn = s.null_space;
  s.mass = nn.transpose() * mass.asDiagonal() * nn;
  Eigen::MatrixXd geometric = Eigen::MatrixXd::Zero(n, n);
  // The calling request's run-time limit (support/run_limit.h) between rows and between the solves below:
  // a crowded scene has thousands of contact rows, each Hessian O(n^2); each solve alone is bounded by the
  // body cap (kMaxModeBodies: 100 bodies, at most 600 x 600; bench/modes_bench.cpp BM_LargestSolves).
  support::check_run_limit();
  for (const Row& row : m.rows) {
    support::check_run_limit();
    if (row.force != 0.0) geometric -= row.force * row_hessian(m, row);
  }
  s.geometric_stiffness = nn.transpose() * geometric * nn;
  s.soft_rows.resize(m.rows.size());
  std::vector<double> k(m.rows.size()), c(m.rows.size());
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    support::check_run_limit();
    if (!m.rows[i].rigid) s.soft_rows[i] = row_jacobian(m, m.rows[i]) * nn;
    k[i] = m.rows[i].stiffness;
    c[i] = m.rows[i].damping;
  }
  set_springs(s, k, c);
  return s;
}

void set_springs(ReducedSystem& s, const std::vector<double>& k, const std::vector<double>& c) {
  const Eigen::Index d = s.null_space.cols();
  s.stiffness = s.geometric_stiffness;
  s.row_stiffness = k;
  s.damping = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < s.soft_rows.size(); ++i) {
    support::check_run_limit();
    if (s.soft_rows[i].size() == 0) continue;
    const Eigen::MatrixXd outer = s.soft_rows[i].transpose() * s.soft_rows[i];
    s.stiffness += k[i] * outer;
    s.damping += c[i] * outer;
  }
}

std::vector<Mode> modes_of(const LinearModel& m, const ReducedSystem& s, double h, const std::vector<int>& tuned_rows) {
  const Eigen::Index d = s.null_space.cols();
  std::vector<Mode> out;
  if (d == 0) return out;
  // K is symmetric up to the Hessians' differencing error; the solver wants it exactly so.
  const Eigen::MatrixXd k = 0.5 * (s.stiffness + s.stiffness.transpose());
  const Eigen::MatrixXd& mass = s.mass;
  const Eigen::MatrixXd& c = s.damping;
  support::check_run_limit();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> undamped(k, mass);
  const Eigen::VectorXd omega2 = undamped.eigenvalues();
  const Eigen::MatrixXd phi = undamped.eigenvectors();  // M-orthonormal columns, ascending omega0^2

  const Eigen::LLT<Eigen::MatrixXd> mass_llt(mass);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * d, 2 * d);
  a.topRightCorner(d, d).setIdentity();
  a.bottomLeftCorner(d, d) = -mass_llt.solve(k);
  a.bottomRightCorner(d, d) = -mass_llt.solve(c);
  support::check_run_limit();
  Eigen::EigenSolver<Eigen::MatrixXd> continuous(a);
  const auto cont_roots = assign_roots(continuous.eigenvalues(), continuous.eigenvectors(), phi, mass);

  std::vector<std::vector<std::complex<double>>> disc_roots(d);
  if (h > 0.0) {
    // Implicit Euler (modes.h): v1 = S^-1 (M v0 - h K y0), y1 = y0 + h v1, S = M + h C + h^2 K.
    const Eigen::PartialPivLU<Eigen::MatrixXd> step(mass + h * c + h * h * k);
    const Eigen::MatrixXd sk = step.solve(k), sm = step.solve(mass);
    Eigen::MatrixXd ad(2 * d, 2 * d);
    ad.topLeftCorner(d, d) = Eigen::MatrixXd::Identity(d, d) - h * h * sk;
    ad.topRightCorner(d, d) = h * sm;
    ad.bottomLeftCorner(d, d) = -h * sk;
    ad.bottomRightCorner(d, d) = sm;
    support::check_run_limit();
    Eigen::EigenSolver<Eigen::MatrixXd> discrete(ad);
    disc_roots = assign_roots(discrete.eigenvalues(), discrete.eigenvectors(), phi, mass);
  }

  const double scale = std::max(omega2.cwiseAbs().maxCoeff(), 0.0);
  Eigen::VectorXd body_mass(kBodyDofs * m.bodies.size());
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    body_mass.segment<3>(kBodyDofs * b) << m.bodies[b].mass, m.bodies[b].mass, m.bodies[b].inertia;
  }
  std::vector<std::string> names;
  for (Eigen::Index i = 0; i < d; ++i) {
    Mode mode;
    mode.free = std::abs(omega2[i]) <= kFreeModeFraction * scale || scale == 0.0;
    mode.unstable = !mode.free && omega2[i] < 0.0;
    mode.undamped_frequency_hz = mode.free ? 0.0 : std::sqrt(std::abs(omega2[i])) / (2.0 * std::numbers::pi);
    if (!mode.free && !mode.unstable) {
      mode.continuous = continuous_pole(cont_roots[i]);
      if (h > 0.0) mode.discrete = discrete_pole(disc_roots[i], h);
    }
    Eigen::VectorXd q = s.null_space * phi.col(i);
    const Eigen::VectorXd energy = body_mass.cwiseProduct(q.cwiseAbs2());
    Eigen::Index top = 0;
    const double total = energy.maxCoeff(&top) > 0.0 ? energy.sum() : 1.0;
    if (q[top] != 0.0) q /= q[top];
    mode.shape = q;
    for (Eigen::Index k2 = 0; k2 < q.size(); ++k2) {
      const double share = energy[k2] / total;
      if (share >= kShapeShareFloor) {
        mode.components.push_back({static_cast<int>(k2 / kBodyDofs), static_cast<Dof>(k2 % kBodyDofs), q[k2], share});
      }
    }
    std::sort(mode.components.begin(), mode.components.end(), [](const auto& x, const auto& y) { return x.share > y.share; });
    std::string name = m.bodies[top / kBodyDofs].id + " " + std::string(dof_word(static_cast<Dof>(top % kBodyDofs)));
    const auto repeats = std::count(names.begin(), names.end(), name);
    names.push_back(name);
    mode.name = repeats ? name + " " + std::to_string(repeats + 1) : name;
    const double potential = phi.col(i).dot(k * phi.col(i));
    if (potential > 0.0) {
      double tuned = 0.0;
      for (int r : tuned_rows) {
        if (s.soft_rows[r].size() == 0) continue;
        const double stretch = s.soft_rows[r].dot(phi.col(i));
        tuned += s.row_stiffness[r] * stretch * stretch;
      }
      mode.tuned_energy_share = tuned / potential;
    }
    out.push_back(std::move(mode));
  }
  return out;
}

int find_mode(const std::vector<Mode>& modes, int body, Dof dof) {
  int best = -1;
  double best_share = kShapeShareFloor;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (modes[i].free || modes[i].unstable) continue;
    for (const ShapeComponent& c : modes[i].components) {
      if (c.body == body && c.dof == dof && c.share > best_share) {
        best_share = c.share;
        best = static_cast<int>(i);
      }
    }
  }
  return best;
}

int track_mode(const LinearModel& m, const std::vector<Mode>& modes, const Eigen::VectorXd& shape) {
  Eigen::VectorXd mass(kBodyDofs * m.bodies.size());
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    mass.segment<3>(kBodyDofs * b) << m.bodies[b].mass, m.bodies[b].mass, m.bodies[b].inertia;
  }
  const double own = shape.dot(mass.cwiseProduct(shape));
  if (!(own > 0.0)) return -1;
  int best = -1;
  double best_overlap = -1.0;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (modes[i].free || modes[i].unstable || modes[i].shape.size() != shape.size()) continue;
    const Eigen::VectorXd& q = modes[i].shape;
    const double cross = q.dot(mass.cwiseProduct(shape));
    const double overlap = cross * cross / (q.dot(mass.cwiseProduct(q)) * own);
    if (overlap > best_overlap) {
      best_overlap = overlap;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace softtune::modes
