#include "softtune/modal_tune.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "softtune/exact_softness.h"

namespace softtune::modes {
namespace {

constexpr double kDifferenceStep = 1e-6;   // in ln k, ln c
constexpr double kMaxStep = 2.0;           // largest change of ln k or ln c per iteration (a factor e^2)
constexpr int kMaxIterations = 200;
constexpr double kUnreachedResidual = 10.0;  // stands for a target whose mode lost its poles (over-damped, free)

std::string target_path(std::size_t i) { return "targets." + std::to_string(i); }

// The unknowns of a group (modal_tune.h): p = (ln k, ln c) for the continuous poles; for the discrete ones
// p = (ln k, ln(c + h k)), so that c may go negative as an exact spring's c' does (exact_softness.h: implicit
// Euler's own damping exceeds a fast request's) while c + h k, and so Box2D's gamma = 1 / (h (c + h k)), stays
// positive.
SpringConstants spring_of(const ModalTuneRequest& q, double p_k, double p_c) {
  const double k = std::exp(p_k);
  return {k, q.discrete ? std::exp(p_c) - q.h * k : std::exp(p_c)};
}
double damping_unknown(const ModalTuneRequest& q, const SpringConstants& s) {
  return std::log(q.discrete ? s.damping + q.h * s.stiffness : s.damping);
}

struct Evaluation {
  std::vector<Mode> modes;
  std::vector<int> mode_of_target;
  Eigen::VectorXd residual;
};

class Solver {
 public:
  Solver(const LinearModel& model, ReducedSystem& system, const ModalTuneRequest& request)
      : model_(model), system_(system), request_(request) {
    for (const SpringGroup& g : request.groups) tuned_rows_.insert(tuned_rows_.end(), g.rows.begin(), g.rows.end());
  }

  Evaluation evaluate(const Eigen::VectorXd& p) {
    std::vector<double> k = system_.row_stiffness, c(model_.rows.size());
    for (std::size_t i = 0; i < model_.rows.size(); ++i) c[i] = model_.rows[i].damping;
    for (std::size_t g = 0; g < request_.groups.size(); ++g) {
      for (int r : request_.groups[g].rows) {
        const SpringConstants spring = spring_of(request_, p[2 * g], p[2 * g + 1]);
        k[r] = spring.stiffness;
        c[r] = spring.damping;
      }
    }
    set_springs(system_, k, c);
    Evaluation e;
    e.modes = modes_of(model_, system_, request_.h, tuned_rows_);
    e.residual.resize(2 * request_.targets.size());
    for (std::size_t t = 0; t < request_.targets.size(); ++t) {
      const ModeTarget& target = request_.targets[t];
      const int m = followed_[t].size() ? track_mode(model_, e.modes, followed_[t]) : find_mode(e.modes, target.body, target.dof);
      e.mode_of_target.push_back(m);
      const std::optional<Pole> pole = m < 0 ? std::nullopt : (request_.discrete ? e.modes[m].discrete : e.modes[m].continuous);
      if (!pole) {
        e.residual.segment<2>(2 * t).setConstant(kUnreachedResidual);
        continue;
      }
      e.residual[2 * t] = std::log(pole->frequency_hz / target.frequency_hz);
      e.residual[2 * t + 1] = pole->damping_ratio - target.damping_ratio;
    }
    return e;
  }

  // From now on each target is the mode that continues its shape in `e` (modal_tune.h).
  void follow(const Evaluation& e) {
    followed_.resize(request_.targets.size());
    for (std::size_t t = 0; t < request_.targets.size(); ++t) {
      if (e.mode_of_target[t] >= 0) followed_[t] = e.modes[e.mode_of_target[t]].shape;
    }
  }

 private:
  const LinearModel& model_;
  ReducedSystem& system_;
  const ModalTuneRequest& request_;
  std::vector<int> tuned_rows_;
  std::vector<Eigen::VectorXd> followed_ = std::vector<Eigen::VectorXd>(request_.targets.size());
};

}  // namespace

ModalTuneResult solve_modal_tune(const LinearModel& model, ReducedSystem& system, const ModalTuneRequest& request) {
  ModalTuneResult out;
  const std::size_t unknowns = 2 * request.groups.size();
  const std::size_t equations = 2 * request.targets.size();
  out.least_squares = equations > unknowns;

  // Refusals before any work: poles the step cannot represent (exact mode).
  for (std::size_t t = 0; t < request.targets.size(); ++t) {
    const ModeTarget& target = request.targets[t];
    if (request.discrete) {
      const double omega_max = exact_max_omega(target.damping_ratio, request.h);
      if (2.0 * std::numbers::pi * target.frequency_hz >= omega_max) {
        out.refusal = Refusal::step_limit;
      out.refused_target = static_cast<int>(t);
        out.error = FieldError{target_path(t) + ".frequency_hz",
                               "is beyond what the step represents in exact mode: at most " +
                                   std::to_string(omega_max / (2.0 * std::numbers::pi)) + " Hz at this damping ratio and h = " +
                                   std::to_string(request.h) + " s (omega_d h < pi)"};
        return out;
      }
    }
  }

  Solver solver(model, system, request);
  Eigen::VectorXd p(unknowns);
  for (std::size_t g = 0; g < request.groups.size(); ++g) {
    p[2 * g] = std::log(request.groups[g].start.stiffness);
    p[2 * g + 1] = damping_unknown(request, request.groups[g].start);
  }
  Evaluation current = solver.evaluate(p);
  for (std::size_t t = 0; t < request.targets.size(); ++t) {
    const ModeTarget& target = request.targets[t];
    const int m = current.mode_of_target[t];
    if (m < 0) {
      out.refusal = Refusal::no_mode;
      out.refused_target = static_cast<int>(t);
      out.error = FieldError{target_path(t), "no mode of the scene moves " + model.bodies[target.body].id + " in " +
                                                 std::string(dof_word(target.dof))};
      return out;
    }
    if (current.modes[m].tuned_energy_share < kMinTunedEnergyShare) {
      out.refusal = Refusal::not_moved;
      out.refused_target = static_cast<int>(t);
      out.error = FieldError{target_path(t), "the tuned joints do not move mode '" + current.modes[m].name +
                                                 "' (they store none of its energy): tune joints that it stretches"};
      return out;
    }
  }
  solver.follow(current);

  double mu = 1e-3;
  for (out.iterations = 0; out.iterations < kMaxIterations; ++out.iterations) {
    const double cost = current.residual.squaredNorm();
    if (std::sqrt(cost) < kModalTolerance) break;
    Eigen::MatrixXd jac(equations, unknowns);
    for (std::size_t u = 0; u < unknowns; ++u) {
      Eigen::VectorXd q = p;
      q[u] += kDifferenceStep;
      jac.col(u) = (solver.evaluate(q).residual - current.residual) / kDifferenceStep;
    }
    const Eigen::MatrixXd normal = jac.transpose() * jac;
    const Eigen::VectorXd gradient = jac.transpose() * current.residual;
    bool improved = false;
    for (int attempt = 0; attempt < 30 && !improved; ++attempt) {
      Eigen::MatrixXd damped = normal;
      for (std::size_t u = 0; u < unknowns; ++u) damped(u, u) += mu * std::max(normal(u, u), 1e-12);
      Eigen::VectorXd step = damped.ldlt().solve(-gradient);
      const double largest = step.cwiseAbs().maxCoeff();
      if (!std::isfinite(largest)) break;
      if (largest > kMaxStep) step *= kMaxStep / largest;
      Evaluation trial = solver.evaluate(p + step);
      if (trial.residual.squaredNorm() < cost) {
        p += step;
        current = std::move(trial);
        solver.follow(current);
        mu = std::max(mu / 3.0, 1e-12);
        improved = true;
      } else {
        mu *= 4.0;
      }
    }
    if (!improved) break;  // a minimum: the least-squares answer, or a target out of reach
  }
  current = solver.evaluate(p);  // leaves `system` at the solution

  out.residual = current.residual.norm();
  out.modes = current.modes;
  for (std::size_t g = 0; g < request.groups.size(); ++g) out.groups.push_back(spring_of(request, p[2 * g], p[2 * g + 1]));
  std::size_t worst = 0;
  for (std::size_t t = 0; t < request.targets.size(); ++t) {
    TargetOutcome o;
    o.mode = current.mode_of_target[t];
    if (o.mode >= 0) o.predicted = request.discrete ? current.modes[o.mode].discrete : current.modes[o.mode].continuous;
    if (o.predicted) {
      o.frequency_error = o.predicted->frequency_hz / request.targets[t].frequency_hz - 1.0;
      o.damping_ratio_error = o.predicted->damping_ratio - request.targets[t].damping_ratio;
    }
    if (current.residual.segment<2>(2 * t).norm() > current.residual.segment<2>(2 * worst).norm()) worst = t;
    out.targets.push_back(o);
  }
  if (!out.least_squares && out.residual > 1e3 * kModalTolerance) {
    const TargetOutcome& o = out.targets[worst];
    std::string best = o.predicted ? "the closest the joints get is " + std::to_string(o.predicted->frequency_hz) + " Hz, zeta " +
                                         std::to_string(o.predicted->damping_ratio)
                                   : "the mode has no oscillating poles there";
    out.refusal = Refusal::unreached;
    out.refused_target = static_cast<int>(worst);
    out.error = FieldError{target_path(worst), "cannot be reached by tuning the given joints: " + best};
  }
  return out;
}

}  // namespace softtune::modes
