// SPDX-License-Identifier: LGPL-2.1-or-later
// `winkler`: elastic-foundation pressure from the local overlap of the (worn) profiles
// (REFERENCE.md §5; Bei & Fregly 2004). Each surface carries an elastic layer of
// thickness h; a layer of modulus E_f = E(1 − ν)/((1 + ν)(1 − 2ν)) compressed by d
// carries p = E_f d/h (linear) or p = −E_f ln(1 − d/h) (nonlinear). Two layers in
// series share the overlap, d = d_bore + d_pin, so
//     p = E_c d/h  or  p = −E_c ln(1 − d/h),   E_c = 1/(1/E_f,bore + 1/E_f,pin).
// The overlap of the rigid profiles at global direction φ for a pin centre at e is
//     d(φ) = R2*(φ − θ_pin) + e·u(φ) − R1*(φ − θ_bushing)   (= −g(φ), contact/gap.h).
// Force control, like the FE model: the pin centre e is solved for (Newton on the 2D
// resultant) so that the foundation carries exactly the normal force of the multibody
// model, ∫ p u(φ) L R1 dφ = F_n u(φ*); the rigid-body eccentricity is only the start.
// The overlap is integrated on a sub-grid (8 points per discrete area) and averaged per
// area on both surfaces. Mukras et al. (J. Tribol. 132, 2010): foundation and FE give
// similar wear volumes but different profiles — `wearlink compare-pressure` shows it.
#include "base/exceptions.h"
#include "base/parameters.h"
#include "contact/pressure_model.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wearlink::contact
{
  namespace
  {
    constexpr double pi         = 3.14159265358979323846;
    constexpr unsigned int sub  = 8; ///< sub-samples per discrete area

    double
    foundation_modulus(const Material &m)
    {
      const double nu = m.poisson_ratio;
      return m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    }

    class Winkler : public PressureModel
    {
    public:
      explicit Winkler(ParameterReader &r)
        : thickness(r.get_positive("Layer thickness"))
        , nonlinear(r.get_bool("Nonlinear"))
      {}

      void
      update_geometry(const JointGeometry &g) override
      {
        geometry = g;
        // Layer moduli in series: d = p h/E_f,bore + p h/E_f,pin.
        modulus   = 1.0 / (1.0 / foundation_modulus(g.bushing) + 1.0 / foundation_modulus(g.pin_material));
        stiffness = modulus / thickness;
      }

      void
      evaluate(const ContactLoad &load, SurfacePressure &out) override
      {
        const auto &bore = geometry.bore;
        const auto &pin  = geometry.pin;
        out.bore.assign(bore.n_points(), 0.0);
        out.pin.assign(pin.n_points(), 0.0);
        if (!(load.normal_force > 0))
          return;

        const unsigned int n  = bore.n_points() * sub;
        const double       dp = 2 * pi / n;
        const double       tb = load.bushing_angle, tp = load.pin_angle;
        const Eigen::Vector2d target = load.normal_force *
                                       Eigen::Vector2d(std::cos(load.contact_angle), std::sin(load.contact_angle));
        // Sub-grid in global angle, aligned with the bore's areas.
        phi.resize(n);
        r1.resize(n);
        r2.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          {
            phi[j] = tb + (j + 0.5) * dp - 0.5 * 2 * pi / bore.n_points();
            r1[j]  = bore.radius(phi[j] - tb);
            r2[j]  = pin.radius(phi[j] - tp);
          }
        const double length = geometry.axial_length;

        // Newton on the resultant: R(e) = Σ p_j u_j L R1_j Δφ − F = 0.
        Eigen::Vector2d e(load.eccentricity[0], load.eccentricity[1]);
        auto            residual = [&](const Eigen::Vector2d &x, Eigen::Matrix2d *jac) {
          Eigen::Vector2d f = -target;
          if (jac)
            jac->setZero();
          for (unsigned int j = 0; j < n; ++j)
            {
              const Eigen::Vector2d u(std::cos(phi[j]), std::sin(phi[j]));
              const double          d = r2[j] + x.dot(u) - r1[j];
              if (d <= 0)
                continue;
              const double w = length * r1[j] * dp;
              f += pressure(d) * w * u;
              if (jac)
                *jac += slope(d) * w * u * u.transpose();
            }
          return f;
        };
        Eigen::Matrix2d jac;
        Eigen::Vector2d f = residual(e, &jac);
        // Start in contact: if nothing overlaps, move along the load until it does.
        for (unsigned int it = 0; it < 60 && jac.determinant() <= 0; ++it)
          {
            e += 0.2 * (geometry.bore.mean_radius() - geometry.pin.mean_radius() + 1e-9) *
                 target.normalized();
            f = residual(e, &jac);
          }
        unsigned int it = 0;
        for (; it < 100 && f.norm() > 1e-10 * load.normal_force; ++it)
          {
            Eigen::Vector2d step;
            if (std::abs(jac.determinant()) > 0)
              step = -jac.fullPivLu().solve(f);
            else
              step = 1e-7 * target.normalized();
            // Backtracking keeps the residual decreasing (the response is monotone but
            // the active arc changes between iterations).
            double          lambda = 1;
            Eigen::Vector2d trial;
            Eigen::Matrix2d jt;
            Eigen::Vector2d ft;
            for (unsigned int k = 0; k < 30; ++k, lambda *= 0.5)
              {
                trial = e + lambda * step;
                ft    = residual(trial, &jt);
                if (ft.norm() < f.norm())
                  break;
              }
            e   = trial;
            f   = ft;
            jac = jt;
          }
        if (!(f.norm() <= 1e-6 * load.normal_force))
          {
            std::ostringstream os;
            os << "winkler pressure model: the foundation could not carry the load " << load.normal_force
               << " N (residual " << f.norm() << " N after " << it
               << " Newton iterations). Increase 'Layer thickness' or check the profiles.";
            throw NumericalError(os.str());
          }

        // Area averages on both surfaces.
        for (unsigned int j = 0; j < n; ++j)
          {
            const Eigen::Vector2d u(std::cos(phi[j]), std::sin(phi[j]));
            const double          d = r2[j] + e.dot(u) - r1[j];
            if (d <= 0)
              continue;
            const double p = pressure(d);
            out.bore[j / sub] += p / sub;
            // The same load on the pin: the sub-arc's length on the pin is r2/r1 of the
            // bore's; distribute the force (p r1 dφ) over the pin area it falls in.
            const unsigned int k = pin_area(phi[j] - tp);
            out.pin[k] += p * r1[j] / r2[j] * dp / (2 * pi / pin.n_points());
          }
      }

    private:
      double
      pressure(double d) const
      {
        if (!nonlinear)
          return stiffness * d;
        return -modulus * std::log(1 - std::min(d / thickness, 1 - 1e-12));
      }

      double
      slope(double d) const
      {
        if (!nonlinear)
          return stiffness;
        return modulus / thickness / std::max(1 - d / thickness, 1e-12);
      }

      unsigned int
      pin_area(double psi) const
      {
        const unsigned int m = geometry.pin.n_points();
        double             s = psi / (2 * pi);
        s -= std::floor(s);
        return std::min(m - 1, static_cast<unsigned int>(std::floor(s * m + 0.5)) % m);
      }

      const double        thickness;
      const bool          nonlinear;
      JointGeometry       geometry;
      double              stiffness = 0, modulus = 0;
      std::vector<double> phi, r1, r2;
    };
  } // namespace

  void
  register_winkler()
  {
    pressure_models().add(
      "winkler",
      "elastic foundation (Winkler) pressure from the local overlap of the worn profiles, "
      "force-controlled to carry the multibody normal force (Bei & Fregly 2004).",
      [](dealii::ParameterHandler &prm) {
        declare_required(prm,
                         "Layer thickness",
                         dealii::Patterns::Double(0),
                         "Thickness h of the elastic layer on each surface; the foundation "
                         "stiffness per unit overlap is 1/(h/E_f,bore + h/E_f,pin). No source "
                         "fixes it for metals: scenes state their choice.",
                         "m");
        declare(prm,
                "Nonlinear",
                "false",
                dealii::Patterns::Bool(),
                "Use the nonlinear layer p = −E_c ln(1 − d/h) instead of p = E_c d/h, with "
                "E_c = 1/(1/E_f,bore + 1/E_f,pin) (same small-overlap stiffness).",
                "none");
      },
      [](ParameterReader &r) { return std::make_unique<Winkler>(r); });
  }
} // namespace wearlink::contact
