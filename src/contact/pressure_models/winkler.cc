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
#include "base/numbers.h"
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
    using numbers::pi;
    constexpr unsigned int sub         = 8;    ///< sub-samples per discrete area
    constexpr double       floor_force = 1e-5; ///< [N], see evaluate()


    class Winkler : public PressureModel
    {
    public:
      explicit Winkler(ParameterReader &r)
        : thickness(r.get_positive("Layer thickness"))
        , nonlinear(r.get_bool("Nonlinear"))
      {
      }

      void
      update_geometry(const JointGeometry &g) override
      {
        geometry = g;
        // Layer moduli in series: d = p h/E_f,bore + p h/E_f,pin.
        modulus   = series_foundation_modulus(g.bushing, g.pin_material);
        stiffness = modulus / thickness;
      }

      /**
       * The pressure that carries @p load: the eccentricity at which the foundation's
       * resultant equals the load (force control), found in three steps — a sub-grid
       * of the bore, a start in contact along the load direction, Newton on the convex
       * foundation energy — then averaged over the discrete areas of both surfaces.
       */
      void
      evaluate(const ContactLoad &load, SurfacePressure &out) override
      {
        out.bore.assign(geometry.bore.n_points(), 0.0);
        out.pin.assign(geometry.pin.n_points(), 0.0);
        // Loads below 10 µN meet the floating-point floor of the force balance (see
        // equilibrium()) and are left without pressure: in a joint carrying newtons
        // their wear is below 1e-6 of the total (documented approximation, not a
        // fallback model).
        if (!(load.normal_force > floor_force))
          return;
        set_up_subgrid(load);
        Eigen::Vector2d e = start_in_contact(load);
        e                 = equilibrium(load, e);
        area_averages(e, load, out);
      }

    private:
      /** Sub-grid in global angle, aligned with the bore's areas, and the load vector. */
      void
      set_up_subgrid(const ContactLoad &load)
      {
        const auto &bore = geometry.bore;
        n                = bore.n_points() * sub;
        dp               = 2 * pi / n;
        const double tb = load.bushing_angle, tp = load.pin_angle;
        target = load.normal_force * Eigen::Vector2d(std::cos(load.contact_angle), std::sin(load.contact_angle));
        phi.resize(n);
        r1.resize(n);
        r2.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          {
            phi[j] = tb + (j + 0.5) * dp - 0.5 * 2 * pi / bore.n_points();
            r1[j]  = bore.radius(phi[j] - tb);
            r2[j]  = geometry.pin.radius(phi[j] - tp);
          }
      }

      /** R(e) = Σ p_j u_j L R1_j Δφ − F, and its Jacobian if @p jac is set. */
      Eigen::Vector2d
      residual(const Eigen::Vector2d &x, Eigen::Matrix2d *jac) const
      {
        const double    length = geometry.axial_length;
        Eigen::Vector2d f      = -target;
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
      }

      /**
       * Start in contact: along the load direction the carried force grows
       * monotonically with the pin's travel s; find s where it equals F_n (Illinois
       * regula falsi on a bracket), so that Newton only corrects the lateral part. (A
       * start at the rigid-body eccentricity fails for light loads, whose overlap arc is
       * narrower than the sub-grid.)
       */
      Eigen::Vector2d
      start_in_contact(const ContactLoad &load) const
      {
        const Eigen::Vector2d e(load.eccentricity[0], load.eccentricity[1]);
        const Eigen::Vector2d dir   = target.normalized();
        auto                  along = [&](double travel) {
          return residual(travel * dir, nullptr).dot(dir) + load.normal_force;
        };
        double s_lo = 0, f_lo = along(s_lo) - load.normal_force;
        double s_hi = std::max(e.norm(), geometry.bore.max_radius() - geometry.pin.min_radius());
        double f_hi = along(s_hi) - load.normal_force;
        for (unsigned int k = 0; k < 60 && f_hi <= 0; ++k)
          {
            s_lo = s_hi;
            f_lo = f_hi;
            s_hi *= 1.5;
            f_hi = along(s_hi) - load.normal_force;
          }
        int side = 0;
        for (unsigned int k = 0; k < 200 && std::abs(f_hi - f_lo) > 0 && s_hi - s_lo > 1e-15 * s_hi; ++k)
          {
            const double s_new = (s_lo * f_hi - s_hi * f_lo) / (f_hi - f_lo);
            const double f_new = along(s_new) - load.normal_force;
            if (std::abs(f_new) <= 1e-9 * load.normal_force)
              {
                s_lo = s_hi = s_new;
                break;
              }
            if ((f_new > 0) == (f_hi > 0))
              {
                s_hi = s_new;
                f_hi = f_new;
                if (side == 1)
                  f_lo *= 0.5;
                side = 1;
              }
            else
              {
                s_lo = s_new;
                f_lo = f_new;
                if (side == -1)
                  f_hi *= 0.5;
                side = -1;
              }
          }
        return 0.5 * (s_lo + s_hi) * dir;
      }

      /**
       * Φ(x + λ s) − Φ(x) of the foundation energy Φ(e) = Σ_j w_j P(d_j(e)) − F·e,
       * summed term by term (no cancellation against F·e).
       */
      double
      energy_change(const Eigen::Vector2d &x, const Eigen::Vector2d &step, const double lambda) const
      {
        const double length = geometry.axial_length;
        double       change = -lambda * target.dot(step);
        for (unsigned int j = 0; j < n; ++j)
          {
            const Eigen::Vector2d u(std::cos(phi[j]), std::sin(phi[j]));
            const double          d_old = r2[j] + x.dot(u) - r1[j];
            const double          d_new = d_old + lambda * step.dot(u);
            if (d_old > 0 || d_new > 0)
              change +=
                length * r1[j] * dp * (stored_energy(std::max(d_new, 0.0)) - stored_energy(std::max(d_old, 0.0)));
          }
        return change;
      }

      /**
       * The force balance from @p e_start. It is the stationarity of the convex
       * foundation energy Φ (∇Φ = R(e), ∇²Φ = J ⪰ 0), so Newton steps are descent
       * directions of Φ, and an Armijo line search on Φ (not on |R|, whose decrease a
       * kink of the piecewise-smooth R can block) converges also on worn, jagged
       * profiles.
       *
       * A light load overlaps only a sample or two of the sub-grid, whose directions are
       * quantized to dφ: the resultant can then miss the load direction by up to F dφ/2,
       * which no eccentricity fixes. Such a start is kept if Newton cannot do better
       * (error in direction ≤ dφ, in magnitude ≤ 1e-9 F). Loads so light that the force
       * balance meets the floating-point floor of the overlap (k_foundation × area × ε ×
       * |e| ~ 1e-11 N, more on worn, jagged profiles) are accepted within 10 µN.
       * Anything worse than 1e-6 of the load is a NumericalError, never a silent result
       * (measured on the nine-bar's profiles after 50,000 revolutions, where a line
       * search on |R| stalled at up to 9 % of F).
       */
      Eigen::Vector2d
      equilibrium(const ContactLoad &load, const Eigen::Vector2d &e_start) const
      {
        Eigen::Vector2d e = e_start;
        Eigen::Matrix2d jac;
        Eigen::Vector2d f       = residual(e, &jac);
        const double    f_start = f.norm();
        unsigned int    it      = 0;
        for (; it < 200 && f.norm() > 1e-10 * load.normal_force; ++it)
          {
            if (!damped_newton_step(e, f, jac))
              break;
          }
        if (!(f.norm() <= 1e-6 * load.normal_force) && f_start <= dp * load.normal_force + floor_force &&
            f_start < f.norm())
          {
            e = e_start;
            f = residual(e, nullptr);
          }
        if (!(f.norm() <= 1e-6 * load.normal_force + floor_force))
          {
            std::ostringstream os;
            os << "winkler pressure model: the foundation could not carry the load " << load.normal_force
               << " N (residual " << f.norm() << " N after " << it
               << " Newton iterations). Increase 'Layer thickness' or check the profiles.";
            throw NumericalError(os.str());
          }
        return e;
      }

      /**
       * One Newton step with a small Levenberg shift (where only one or two sub-grid
       * samples overlap, J is nearly singular along the bore, and the shifted step slides
       * the pin towards the next contact), trimmed by an Armijo line search on Φ.
       * Updates @p e, @p f and @p jac; false if no step decreases Φ.
       */
      bool
      damped_newton_step(Eigen::Vector2d &e, Eigen::Vector2d &f, Eigen::Matrix2d &jac) const
      {
        const double    shift       = 1e-8 * std::max(jac.trace(), 1e-300);
        Eigen::Vector2d step        = -(jac + shift * Eigen::Matrix2d::Identity()).ldlt().solve(f);
        double          slope_along = f.dot(step);
        if (!(slope_along < 0))
          {
            step        = -f * (1e-7 / std::max(f.norm(), 1e-300));
            slope_along = f.dot(step);
          }
        double lambda = 1;
        double change = energy_change(e, step, lambda);
        for (unsigned int k = 0; k < 80 && change > 1e-4 * lambda * slope_along; ++k)
          {
            lambda *= 0.5;
            change = energy_change(e, step, lambda);
          }
        if (!(change < 0))
          return false;
        e = e + lambda * step;
        f = residual(e, &jac);
        return true;
      }

      /** The sub-grid pressures at eccentricity @p e, averaged over both surfaces' areas. */
      void
      area_averages(const Eigen::Vector2d &e, const ContactLoad &load, SurfacePressure &out) const
      {
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
            const unsigned int k = pin_area(phi[j] - load.pin_angle);
            out.pin[k] += p * r1[j] / r2[j] * dp / (2 * pi / geometry.pin.n_points());
          }
      }

      double
      pressure(double d) const
      {
        if (!nonlinear)
          return stiffness * d;
        return -modulus * std::log(1 - std::min(d / thickness, 1 - 1e-12));
      }

      /** P(d) = ∫0^d p(s) ds [N/m], the energy stored per unit area. */
      double
      stored_energy(double d) const
      {
        if (!nonlinear)
          return 0.5 * stiffness * d * d;
        const double x = std::min(d / thickness, 1 - 1e-12);
        return modulus * thickness * ((1 - x) * std::log(1 - x) + x);
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
      std::vector<double> phi, r1, r2; ///< sub-grid angle, bore and pin radius
      unsigned int        n  = 0;      ///< sub-grid size
      double              dp = 0;      ///< sub-grid spacing [rad]
      Eigen::Vector2d     target;      ///< the load vector [N]
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
