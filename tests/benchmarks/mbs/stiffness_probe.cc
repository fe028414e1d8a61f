// SPDX-License-Identifier: LGPL-2.1-or-later
// What sets the step in each contact regime of params/nine_bar_clearance.prm: on every
// 25th accepted step the full Jacobian of the right-hand side, A = [[0, I], [∂q̈/∂q,
// ∂q̈/∂q̇]] (central differences of Mechanism::accelerations, 2n of them), and its
// eigenvalues. Per regime of the two clearance joints (free, light contact δ < 1 µm,
// deep) the table prints the median step h, the median fastest rate ρ = max |λ|, the
// 10 %, 50 % and 90 % quantiles of h·ρ and the median damping ratio −Re λ/|λ| of the
// fastest eigenvalue. dopri5 is stable up to h·ρ ≈ 3.3 on the negative real axis and
// ≈ 3 along the imaginary axis: a regime whose h·ρ sits well below that, with a lightly
// damped fastest eigenvalue, is limited by accuracy on an oscillation the solution
// carries (doc/performance.md, "What sets the step"). Asserts nothing.
//   usage: stiffness_probe [seconds of motion, default 5] [Section/Entry=value ...]
#include "base/parameters.h"
#include "contact/clearance_joint.h"
#include "io/scene.h"
#include "mbs/mechanism.h"
#include "mbs/simulation.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace wearlink;

namespace
{
  std::string
  regime(const contact::JointDiagnostics &d)
  {
    if (!(d.penetration > 0))
      return "free";
    return d.penetration < 1e-6 ? "light" : "deep";
  }

  /** The p-quantile of @p v (nearest rank). */
  double
  quantile(std::vector<double> v, const double p)
  {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
  }

  class Probe : public mbs::StepObserver
  {
  public:
    explicit Probe(io::Scene &scene)
      : scene(scene)
    {
    }

    void
    on_step(const mbs::StepContext &c) override
    {
      if (count++ % 25 != 0)
        return;
      mbs::Mechanism      &mech = c.simulation.get_mechanism();
      const unsigned int   n    = mech.n_coordinates();
      const mbs::StateView s(c.y.data(), c.y.data() + n);
      std::string          key;
      for (const auto &j : scene.clearance_joints)
        key += j->name() + ":" + regime(j->diagnostics(s)) + " ";
      const std::complex<double> fastest = fastest_eigenvalue(mech, c);
      Row                       &r       = rows[key];
      const double               h       = c.t - c.t_previous;
      r.h.push_back(h);
      r.rate.push_back(std::abs(fastest));
      r.h_rate.push_back(h * std::abs(fastest));
      r.damping.push_back(-fastest.real() / std::abs(fastest));
    }

    void
    print() const
    {
      std::printf("%7s %11s %11s %8s %8s %8s %8s  regime (joint: free | light δ < 1 µm | deep)\n",
                  "samples",
                  "h [s]",
                  "rho [1/s]",
                  "h*rho10%",
                  "h*rho50%",
                  "h*rho90%",
                  "damping");
      for (const auto &[key, r] : rows)
        if (r.h.size() >= 20)
          std::printf("%7zu %11.3e %11.3e %8.2f %8.2f %8.2f %8.3f  %s\n",
                      r.h.size(),
                      quantile(r.h, 0.5),
                      quantile(r.rate, 0.5),
                      quantile(r.h_rate, 0.1),
                      quantile(r.h_rate, 0.5),
                      quantile(r.h_rate, 0.9),
                      quantile(r.damping, 0.5),
                      key.c_str());
    }

  private:
    struct Row
    {
      std::vector<double> h, rate, h_rate, damping;
    };

    /** The eigenvalue of largest modulus of A at the step's end (clobbers the workspace). */
    static std::complex<double>
    fastest_eigenvalue(mbs::Mechanism &mech, const mbs::StepContext &c)
    {
      const unsigned int  n = mech.n_coordinates();
      std::vector<double> q(c.y.data(), c.y.data() + n), v(c.y.data() + n, c.y.data() + 2 * n), plus(n), minus(n);
      mbs::PowerTerms     power;
      Eigen::MatrixXd     a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
      for (unsigned int i = 0; i < n; ++i)
        a(i, n + i) = 1;
      for (unsigned int i = 0; i < 2 * n; ++i)
        {
          double      &x    = i < n ? q[i] : v[i - n];
          const double step = i < n ? 1e-11 : 1e-8, x0 = x; // [m or rad], [m/s or rad/s]
          x = x0 + step;
          mech.accelerations(c.t, q.data(), v.data(), plus.data(), power);
          x = x0 - step;
          mech.accelerations(c.t, q.data(), v.data(), minus.data(), power);
          x = x0;
          for (unsigned int r = 0; r < n; ++r)
            a(n + r, i) = (plus[r] - minus[r]) / (2 * step);
        }
      const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, false);
      std::complex<double>                      fastest = 0;
      for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k)
        if (std::abs(solver.eigenvalues()[k]) > std::abs(fastest))
          fastest = solver.eigenvalues()[k];
      return fastest;
    }

    io::Scene                 &scene;
    std::map<std::string, Row> rows;
    long                       count = 0;
  };
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const double             end = argc > 1 ? std::stod(argv[1]) : 5;
  std::vector<std::string> overrides{"Simulation/End time=" + format_number(end), "Output/Time series=false"};
  for (int i = 2; i < argc; ++i)
    overrides.emplace_back(argv[i]);
  io::Scene             scene = io::read_scene(testing::source_path("params/nine_bar_clearance.prm"), overrides);
  Probe                 probe(scene);
  workflows::RunOptions options;
  options.observers.push_back(&probe);
  const Json s = workflows::run_scene(scene, options);
  std::printf("%s, %.1f s of motion: %.0f steps, %.0f rejected\n\n",
              std::string(s.at("integrator")).c_str(),
              end,
              json_number(s.at("steps")),
              json_number(s.at("rejected_steps")));
  probe.print();
  return 0;
}
