#pragma once
// The modes of planar rigid bodies on several soft constraints, about a rest state.
//
// Whenever several soft constraints share a body, the per-constraint effective mass of the talk (Catto GDC
// 2011, "3:2") is not the mass a motion sees. Near rest the scene is a small linear system
//   M q'' + C q' + K q = 0,   J_r q' = 0 (rigid rows, contacts)
// in q = (x, y, theta) per dynamic body, with
//   K = sum_soft k_i J_i^T J_i - sum_all f_i H_i,   C = sum_soft c_i J_i^T J_i,
// J_i = dC_i/dq and H_i = d^2 C_i/dq^2 of each row's position function C_i, and f_i the row's force at rest
// (the geometric stiffness of a preloaded spring, a hanging pin, a leaning wheel axis). The rigid rows are held
// by projection onto their null space, q = N y with N^T N = I, so the reduced system is (N^T M N, N^T C N,
// N^T K N). Its modes: the undamped shapes of the generalised eigenproblem K phi = omega0^2 M phi, and the
// damped poles s of the state matrix [[0, I], [-M^-1 K, -M^-1 C]] (omega = |s|, zeta = -Re(s)/|s|). At the
// scene's step h the soft constraints are implicit Euler (softness.h):
//   (M + h C + h^2 K) v1 = M v0 - h K y0,   y1 = y0 + h v1,
// whose step matrix has the discrete poles z; s = ln(z)/h is read as for one constraint (achieved_from_poles).

#include <Eigen/Core>
#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace softtune::modes {

/// A dynamic body in the plane; its coordinates are (x, y, theta) of its centre of mass.
struct PlanarBody {
  std::string id;
  double mass = 1.0;                  ///< kg
  double inertia = 1.0;               ///< kg m^2 about the centre of mass (a locked rotation: a rigid angular row)
  Eigen::Vector2d position{0, 0};     ///< m, world centre of mass at rest
};

/// How a linear row's axis moves with the bodies.
enum class AxisFrame {
  world,          ///< fixed in the world (contact normal, revolute pin x/y rows, mouse)
  body_a,         ///< turns with body A (a wheel joint's suspension axis and its rigid perpendicular row)
  along_anchors,  ///< the unit vector from anchor A to anchor B (a distance joint: C = |pB - pA|)
};

/// One scalar row between two bodies (index into LinearModel::bodies; -1 = the static world).
/// Linear: C = n . (pB - pA), p = centre + R(theta) r; angular: C = theta_b - theta_a.
struct Row {
  int body_a = -1, body_b = -1;
  bool angular = false;
  AxisFrame frame = AxisFrame::world;
  Eigen::Vector2d r_a{0, 0}, r_b{0, 0};  ///< m, anchors from each body's centre, world frame at rest
  Eigen::Vector2d axis{0, 1};            ///< unit, world, at rest
  bool rigid = false;                    ///< held by projection (no k, c)
  double stiffness = 0.0;                ///< k, N/m (N m/rad angular); soft rows
  double damping = 0.0;                  ///< c, N s/m (N m s/rad); soft rows
  /// N (N m), the row's force at rest along +C: a spring's -k (C - C0); rigid rows get theirs from
  /// rigid_row_forces(). It only enters through the geometric stiffness -f H.
  double force = 0.0;
  int joint = -1;                        ///< the scene joint this row belongs to (for tuning and reports)
};

struct LinearModel {
  std::vector<PlanarBody> bodies;
  std::vector<Row> rows;
  Eigen::Vector2d gravity{0, -10};       ///< m/s^2, for the rigid rows' forces at rest
};

/// Coordinates: 3 per body (x, y, theta).
inline constexpr int kBodyDofs = 3;

/// J (1 x 3n) of a row at rest, and H (3n x 3n) its second derivative: central differences of the row's exact
/// position function over the (at most six) coordinates it touches (steps 1e-6 and 1e-4 of the model's length
/// scale: 1e-10 and 1e-8 relative).
Eigen::RowVectorXd row_jacobian(const LinearModel& model, const Row& row);
Eigen::MatrixXd row_hessian(const LinearModel& model, const Row& row);

/// The rigid rows' forces at rest: least squares (minimum norm) of J_r^T lambda = -(gravity + sum_soft J^T f).
/// Writes each rigid row's `force`; returns the residual |.| of the balance (N), 0 for a true rest.
double rigid_row_forces(LinearModel& model);

enum class Dof { x, y, angle };
/// "surge" (x), "heave" (y), "pitch" (angle): the words a side-view designer uses.
std::string_view dof_word(Dof d);

struct ShapeComponent {
  int body = 0;          ///< index into LinearModel::bodies
  Dof dof = Dof::y;
  double amplitude = 0;  ///< m or rad; the shape is scaled so that its largest-energy coordinate is 1
  double share = 0;      ///< fraction of the mode's kinetic energy in this coordinate (sums to 1)
};

struct Pole {
  double frequency_hz = 0.0;  ///< |s| / (2 pi)
  double damping_ratio = 0.0; ///< -Re(s) / |s|
};

struct Mode {
  std::string name;                      ///< from the largest component: "chassis heave", "load heave"
  double undamped_frequency_hz = 0.0;    ///< omega0 / (2 pi) of K phi = omega0^2 M phi
  bool free = false;                     ///< a motion nothing resists (rolling, falling): omega0 ~ 0
  bool unstable = false;                 ///< omega0^2 < 0: the rest state is not stable in this shape
  std::optional<Pole> continuous;        ///< damped poles of the continuous system
  std::optional<Pole> discrete;          ///< implicit Euler at h, s = ln(z) / h
  Eigen::VectorXd shape;                 ///< 3n generalised coordinates (x, y, theta per body)
  std::vector<ShapeComponent> components;  ///< sorted by share, those above kShapeShareFloor
  double tuned_energy_share = 0.0;       ///< fraction of the mode's potential energy k (J phi)^2 in `tuned rows`
};

/// Components below this share of a mode's kinetic energy are left out of Mode::components.
inline constexpr double kShapeShareFloor = 0.01;
/// omega0^2 below this fraction of the largest counts as free (a motion nothing resists).
inline constexpr double kFreeModeFraction = 1e-9;

/// The reduced linear system: N, and (M, C, K) projected onto the rigid rows' null space.
struct ReducedSystem {
  Eigen::MatrixXd null_space;  ///< 3n x d, orthonormal columns
  Eigen::MatrixXd mass, damping, stiffness;  ///< d x d
  Eigen::MatrixXd geometric_stiffness;       ///< d x d, N^T (-sum f H) N (part of `stiffness`)
  std::vector<Eigen::RowVectorXd> soft_rows; ///< J_i N of each soft row, indexed like LinearModel::rows (empty: rigid)
  std::vector<double> row_stiffness;         ///< k of each row as last set (N/m, N m/rad)
};
ReducedSystem reduce(const LinearModel& model);

/// Rebuilds `damping` and `stiffness` of a reduced system from new per-row k, c (indexed like model.rows).
void set_springs(ReducedSystem& system, const std::vector<double>& stiffness, const std::vector<double>& damping);

/// Modes of the reduced system, slowest first; h > 0 adds the discrete poles of implicit Euler at that step.
/// `tuned_rows` (row indices) only fills Mode::tuned_energy_share.
std::vector<Mode> modes_of(const LinearModel& model, const ReducedSystem& system, double h,
                           const std::vector<int>& tuned_rows = {});

/// The mode a designer means by (body, dof): the non-free mode whose kinetic energy has the largest share in
/// that coordinate; -1 when no mode moves it.
int find_mode(const std::vector<Mode>& modes, int body, Dof dof);

/// The mode that continues `shape` (3n generalised coordinates: a Mode::shape of a nearby system, e.g. before a
/// step of a solve changed the springs): the non-free, stable mode with the largest mass-weighted overlap
///   (q^T M s)^2 / ((q^T M q)(s^T M s))   (1: the same shape, 0: M-orthogonal),
/// so a mode keeps its identity while its frequency crosses another's or its largest component changes. -1 when
/// every mode is free or unstable.
int track_mode(const LinearModel& model, const std::vector<Mode>& modes, const Eigen::VectorXd& shape);

}  // namespace softtune::modes
