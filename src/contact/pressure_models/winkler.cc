// SPDX-License-Identifier: LGPL-2.1-or-later
// `winkler`: elastic-foundation pressure from the local overlap of the (worn) profiles
// (doc/models.md §5.3; Bei & Fregly 2004). Each surface carries an elastic layer of
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
// Wear of the load state (the sequential wear update, wear/archard.h): a surface that
// wears by c p while it carries p acts as a second layer of compliance c in series with
// the foundation, so evaluate_wearing() solves the same force balance with the linear
// layer's stiffness k replaced by 1/(1/k + c) and returns the pressure at the state's end
// (backward Euler: stable for any c; the worn depth c p carries the state's Archard
// volume exactly). The nonlinear layer is stepped explicitly, stable while c is below
// the reciprocal of its stiffness at the deepest overlap.
// Cost: the sub-grid's directions and bore radii are computed once per geometry in the
// bushing's frame, and the sums of the solve run over a window of the samples that can
// overlap (checked against the whole grid at the end, so the result is the whole grid's
// balance); an evaluation takes ~10 µs instead of ~2.5 ms, which made a winkler wear run
// 40× slower than hertz-strip (its accuracy-study row ran for > 17 minutes).
#include "base/effect_ledger.h"
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

    /**
     * Where the layers can touch. The sub-grid lives in the bushing's frame (fixed per
     * geometry: angles, directions, bore radii); a load brings the pin's radii on it and
     * the load vector, both turned into that frame. The sums of the force balance run
     * over a window of sub-grid indices (ascending, so that they add the same terms in
     * the same order as a sum over the whole grid). The window around a centre e_w with
     * a slack s holds every sample with d_j(e_w) > −s; since |u_j| = 1, no sample outside
     * it overlaps at any e with |e − e_w| < s, so there the window's sums are the whole
     * grid's, exactly. The solver keeps its trial points inside that ball.
     */
    struct SubGrid
    {
      std::vector<double>       ux, uy;     ///< direction of each sample, bushing frame
      std::vector<double>       r1;         ///< bore radius [m]
      std::vector<double>       gap;        ///< r2 − r1 at e = 0 for the current load [m] (< 0)
      std::vector<unsigned int> candidates; ///< the samples near the load direction (ascending)
      std::vector<unsigned int> window;     ///< the samples the sums run over
      Eigen::Vector2d           centre;     ///< e_w [m]; see above
      double                    slack  = 0; ///< s [m]; 0: the window is not a ball (all, or narrowed)
      unsigned int              n      = 0; ///< sub-grid size
      double                    dp     = 0; ///< spacing [rad]
      double                    offset = 0; ///< angle of sample 0 in the bushing frame [rad]

      /** Overlap d_j = r2_j + e·u_j − r1_j at eccentricity @p e (bushing frame) [m]. */
      double
      overlap(const unsigned int j, const Eigen::Vector2d &e) const
      {
        return gap[j] + e[0] * ux[j] + e[1] * uy[j];
      }
      void
      use_all()
      {
        window = candidates;
        slack  = 0;
      }
      /** The window of the candidates within @p s of overlapping at @p e. */
      void
      window_around(const Eigen::Vector2d &e, const double s)
      {
        window.clear();
        for (const unsigned int j : candidates)
          if (overlap(j, e) > -s)
            window.push_back(j);
        centre = e;
        slack  = s;
      }
      /** True if the segment from @p e to @p e + @p step stays where the window is exact. */
      bool
      covers(const Eigen::Vector2d &e, const Eigen::Vector2d &step) const
      {
        return (e - centre).norm() + step.norm() < slack;
      }
    };

    class Winkler : public PressureModel
    {
    public:
      explicit Winkler(ParameterReader &r)
        : thickness(r.get_positive("Layer thickness"))
        , nonlinear(r.get_bool("Nonlinear"))
      {
      }

      void
      evaluate_wearing(const ContactLoad &load, const WearCompliance &c, SurfacePressure &out) override
      {
        wear_compliance = nonlinear ? 0.0 : c.total();
        try
          {
            evaluate(load, out);
          }
        catch (...)
          {
            wear_compliance = 0;
            throw;
          }
        wear_compliance = 0;
      }

      double
      stable_compliance(const ContactLoad &) const override
      {
        return nonlinear ? 1 / slope(deepest_overlap) : std::numeric_limits<double>::infinity();
      }

      /**
       * The pressure that carries @p load: the eccentricity at which the foundation's
       * resultant equals the load (force control), found in three steps — the load on
       * the sub-grid, a start in contact along the load direction, Newton on the convex
       * foundation energy — then averaged over the discrete areas of both surfaces.
       */
      void
      evaluate(const ContactLoad &load, SurfacePressure &out) override
      {
        out.bore.assign(geometry().bore.n_points(), 0.0);
        out.pin.assign(geometry().pin.n_points(), 0.0);
        // Loads below 10 µN meet the floating-point floor of the force balance (see
        // equilibrium()) and are left without pressure: in a joint carrying newtons
        // their wear is below 1e-6 of the total (documented approximation, not a
        // fallback model).
        if (!(load.normal_force > floor_force))
          return;
        // The samples within ±w of the load direction are the candidates, w doubled
        // until none outside them can overlap at the solution (candidates_hold()).
        Eigen::Vector2d e;
        for (double w = initial_half_window;; w *= 2)
          {
            set_up_load(load, w);
            single_sample = -1;
            e             = equilibrium(load, start_in_contact(load));
            if (w >= pi || candidates_hold(e, w))
              break;
          }
        area_averages(e, load, out);
      }

    protected:
      /** The layers' stiffness and the sub-grid in the bushing frame, once per geometry. */
      void
      geometry_changed() override
      {
        const auto &g = geometry();
        // Layer moduli in series: d = p h/E_f,bore + p h/E_f,pin.
        modulus       = series_foundation_modulus(g.bushing, g.pin_material);
        largest_pin   = g.pin.max_radius();
        smallest_bore = g.bore.min_radius();
        stiffness     = modulus / thickness;
        const auto m  = g.bore.n_points();
        grid.n        = m * sub;
        grid.dp       = 2 * pi / grid.n;
        grid.offset   = 0.5 * grid.dp - 0.5 * 2 * pi / m;
        grid.ux.resize(grid.n);
        grid.uy.resize(grid.n);
        grid.r1.resize(grid.n);
        grid.gap.resize(grid.n);
        for (unsigned int j = 0; j < grid.n; ++j)
          {
            const double alpha = grid.offset + j * grid.dp;
            grid.ux[j]         = std::cos(alpha);
            grid.uy[j]         = std::sin(alpha);
            grid.r1[j]         = g.bore.radius(alpha);
          }
      }

      /** The sub-grid's bore radii around the worn bore areas. */
      void
      material_removed(const SurfaceWear &w) override
      {
        // Sub-sample j of area k sits at ψ_k + (j mod sub + 1/2 − sub/2) dφ, so the
        // radius of sample k reaches the sub-samples of areas k − 1 … k + 1.
        const long n = static_cast<long>(grid.n);
        for (const unsigned int k : w.bore_areas)
          for (long j = (static_cast<long>(k) - 1) * sub; j < (static_cast<long>(k) + 2) * sub; ++j)
            {
              const long jj = ((j % n) + n) % n;
              grid.r1[jj]   = geometry().bore.radius(grid.offset + jj * grid.dp);
            }
      }

    private:
      /**
       * The load in the bushing's frame: the load vector, the rigid-body eccentricity and
       * the pin's radii on the sub-grid (pin frame angle = bushing frame angle + θ_b − θ_p).
       */
      void
      set_up_load(const ContactLoad &load, const double half_window)
      {
        const double c = std::cos(load.bushing_angle), s = std::sin(load.bushing_angle);
        const double fx   = load.normal_force * std::cos(load.contact_angle);
        const double fy   = load.normal_force * std::sin(load.contact_angle);
        target            = Eigen::Vector2d(c * fx + s * fy, -s * fx + c * fy);
        eccentricity      = Eigen::Vector2d(c * load.eccentricity[0] + s * load.eccentricity[1],
                                       -s * load.eccentricity[0] + c * load.eccentricity[1]);
        const double turn = load.bushing_angle - load.pin_angle;
        select_candidates(std::atan2(target[1], target[0]), half_window);
        for (const unsigned int j : grid.candidates)
          grid.gap[j] = geometry().pin.radius(grid.offset + j * grid.dp + turn) - grid.r1[j];
        grid.use_all();
      }

      /** The sub-grid samples within ±@p w of the direction @p alpha (bushing frame), ascending. */
      void
      select_candidates(const double alpha, const double w)
      {
        auto &c = grid.candidates;
        c.clear();
        if (w >= pi)
          {
            for (unsigned int j = 0; j < grid.n; ++j)
              c.push_back(j);
            return;
          }
        const long n  = static_cast<long>(grid.n);
        const long lo = static_cast<long>(std::floor((alpha - w - grid.offset) / grid.dp));
        const long hi = static_cast<long>(std::ceil((alpha + w - grid.offset) / grid.dp));
        for (long j = lo; j <= hi; ++j)
          c.push_back(static_cast<unsigned int>(((j % n) + n) % n));
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
      }

      /**
       * True if no sample farther than @p w from the load direction can overlap at @p e:
       * there e·u ≤ |e| cos(w − θ), θ the angle between e and the load, so the overlap
       * is at most max R2 − min R1 + |e| cos(w − θ) (the radii of the geometry given to
       * update_geometry(): wear only lowers max R2 and raises min R1).
       */
      bool
      candidates_hold(const Eigen::Vector2d &e, const double w) const
      {
        const double theta = std::acos(std::clamp(e.dot(target) / (e.norm() * target.norm() + 1e-300), -1.0, 1.0));
        return largest_pin - smallest_bore + e.norm() * std::cos(std::max(0.0, w - theta)) < 0;
      }

      /** R(e) = Σ p_j u_j L R1_j Δφ − F over the window, and its Jacobian if @p jac is set. */
      Eigen::Vector2d
      residual(const Eigen::Vector2d &x, Eigen::Matrix2d *jac) const
      {
        const double    length = geometry().axial_length;
        Eigen::Vector2d f      = -target;
        if (jac)
          jac->setZero();
        for (const unsigned int j : grid.window)
          {
            const double d = grid.overlap(j, x);
            if (d <= 0)
              continue;
            const Eigen::Vector2d u(grid.ux[j], grid.uy[j]);
            const double          w = length * grid.r1[j] * grid.dp;
            f += pressure(d) * w * u;
            if (jac)
              *jac += slope(d) * w * u * u.transpose();
          }
        return f;
      }

      /** Keep in the window only the samples that overlap at the pin travel @p s along @p dir. */
      void
      narrow_window(const double s, const Eigen::Vector2d &dir)
      {
        auto &w = grid.window;
        w.erase(std::remove_if(w.begin(),
                               w.end(),
                               [&](const unsigned int j) { return !(grid.overlap(j, s * dir) > 0); }),
                w.end());
      }

      /**
       * Start in contact: along the load direction the carried force grows
       * monotonically with the pin's travel s; find s where it equals F_n (Illinois
       * regula falsi on a bracket), so that Newton only corrects the lateral part. (A
       * start at the rigid-body eccentricity fails for light loads, whose overlap arc is
       * narrower than the sub-grid.) No sample with u·dir ≤ 0 overlaps for s ≥ 0 (the pin
       * lies inside the bore), and none that is clear at the bracket's upper end overlaps
       * below it, so the window shrinks with the bracket.
       */
      Eigen::Vector2d
      start_in_contact(const ContactLoad &load)
      {
        const Eigen::Vector2d dir   = target.normalized();
        auto                  along = [&](double travel) {
          return residual(travel * dir, nullptr).dot(dir) + load.normal_force;
        };
        double s_lo = 0, f_lo = along(s_lo) - load.normal_force;
        double s_hi = std::max(eccentricity.norm(), geometry().bore.max_radius() - geometry().pin.min_radius());
        double f_hi = along(s_hi) - load.normal_force;
        for (unsigned int k = 0; k < 60 && f_hi <= 0; ++k)
          {
            s_lo = s_hi;
            f_lo = f_hi;
            s_hi *= 1.5;
            f_hi = along(s_hi) - load.normal_force;
          }
        narrow_window(s_hi, dir);
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
                narrow_window(s_hi, dir);
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
       * Φ(x + λ s) − Φ(x) of the foundation energy Φ(e) = Σ_j w_j P(d_j(e)) − F·e over
       * the window, summed term by term (no cancellation against F·e).
       */
      double
      energy_change(const Eigen::Vector2d &x, const Eigen::Vector2d &step, const double lambda) const
      {
        const double length = geometry().axial_length;
        double       change = -lambda * target.dot(step);
        for (const unsigned int j : grid.window)
          {
            const double d_old = grid.overlap(j, x);
            const double d_new = d_old + lambda * (step[0] * grid.ux[j] + step[1] * grid.uy[j]);
            if (d_old > 0 || d_new > 0)
              change += length * grid.r1[j] * grid.dp *
                        (stored_energy(std::max(d_new, 0.0)) - stored_energy(std::max(d_old, 0.0)));
          }
        return change;
      }

      /**
       * The force balance from @p e_start. It is the stationarity of the convex
       * foundation energy Φ (∇Φ = R(e), ∇²Φ = J ⪰ 0), so Newton steps are descent
       * directions of Φ, and an Armijo line search on Φ (not on |R|, whose decrease a
       * kink of the piecewise-smooth R can block) converges also on worn, jagged
       * profiles. The sums run over the window around the current point (SubGrid) with
       * a slack of 8 × the deepest overlap at the start, at least 2 µm, and twice any
       * step about to leave it: every trial point lies where the window is exact.
       *
       * A light load overlaps only a sample or two of the sub-grid, whose directions are
       * quantized to dφ: the resultant can then miss the load direction by up to F dφ/2,
       * which no eccentricity fixes. Such a start is kept if Newton cannot do better
       * (error in direction ≤ dφ, in magnitude ≤ 1e-9 F). Loads so light that the force
       * balance meets the floating-point floor of the overlap (k_foundation × area × ε ×
       * |e| ~ 1e-11 N, more on worn, jagged profiles) are accepted within 10 µN.
       * A load below resolution_force() compresses no sample by a nanometre: the
       * foundation's energy changes of the line search then sink into its rounding, and
       * such a load too, if Newton cannot balance it, is carried by the sample nearest
       * its direction (carry_on_one_sample()).
       * Anything worse than 1e-6 of the load is a NumericalError, never a silent result
       * (measured on the nine-bar's profiles after 50,000 revolutions, where a line
       * search on |R| stalled at up to 9 % of F).
       */
      Eigen::Vector2d
      equilibrium(const ContactLoad &load, const Eigen::Vector2d &e_start)
      {
        double deepest = 0;
        for (const unsigned int j : grid.window) // the samples overlapping at the start
          deepest = std::max(deepest, grid.overlap(j, e_start));
        base_slack = std::max(8 * deepest, 2e-6);
        grid.window_around(e_start, base_slack);
        Eigen::Vector2d e = e_start;
        Eigen::Matrix2d jac;
        Eigen::Vector2d f       = residual(e, &jac);
        const double    f_start = f.norm();
        unsigned int    it      = 0;
        for (; it < 200 && f.norm() > 1e-10 * load.normal_force; ++it)
          if (!damped_newton_step(e, f, jac))
            break;
        if (!(f.norm() <= 1e-6 * load.normal_force) && f_start <= grid.dp * load.normal_force + floor_force &&
            f_start < f.norm())
          {
            e = e_start;
            grid.window_around(e, base_slack);
            f = residual(e, nullptr);
          }
        if (!(f.norm() <= 1e-6 * load.normal_force + floor_force) &&
            (overlapping_samples(e) <= 2 || load.normal_force < resolution_force()))
          {
            carry_on_one_sample(load);
            return e;
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

      /** The force of the layer over one sub-grid sample compressed by 1 nm [N]. */
      double
      resolution_force() const
      {
        return stiffness * geometry().axial_length * smallest_bore * grid.dp * 1e-9;
      }

      /** How many samples of the window overlap at @p e. */
      unsigned int
      overlapping_samples(const Eigen::Vector2d &e) const
      {
        unsigned int n = 0;
        for (const unsigned int j : grid.window)
          n += grid.overlap(j, e) > 0 ? 1 : 0;
        return n;
      }

      /**
       * The limit of the sub-grid's resolution: a load so light that at most two samples
       * overlap, and whose direction those samples cannot match (their directions are
       * dφ apart), or so light that it compresses no sample by a nanometre
       * (resolution_force()), is carried by the one sample nearest its direction, with
       * its magnitude exact and its direction within dφ/2. The effect ledger counts them.
       */
      void
      carry_on_one_sample(const ContactLoad &load)
      {
        const double psi = std::atan2(target[1], target[0]) - grid.offset;
        const double x   = psi / grid.dp - std::floor(psi / (2 * pi)) * grid.n;
        single_sample    = static_cast<int>(std::lround(x)) % static_cast<int>(grid.n);
        single_pressure  = load.normal_force / (geometry().axial_length * grid.r1[single_sample] * grid.dp);
        EffectLedger::instance().add_calls("winkler light loads on one sample", 1);
      }

      /**
       * One Newton step with a small Levenberg shift (where only one or two sub-grid
       * samples overlap, J is nearly singular along the bore, and the shifted step slides
       * the pin towards the next contact), trimmed by an Armijo line search on Φ.
       * Updates @p e, @p f and @p jac; false if no step decreases Φ.
       */
      bool
      damped_newton_step(Eigen::Vector2d &e, Eigen::Vector2d &f, Eigen::Matrix2d &jac)
      {
        const double    shift       = 1e-8 * std::max(jac.trace(), 1e-300);
        Eigen::Vector2d step        = -(jac + shift * Eigen::Matrix2d::Identity()).ldlt().solve(f);
        double          slope_along = f.dot(step);
        if (!(slope_along < 0))
          {
            step        = -f * (1e-7 / std::max(f.norm(), 1e-300));
            slope_along = f.dot(step);
          }
        if (!grid.covers(e, step)) // f and jac at e stay: the new window holds the old one's overlaps
          grid.window_around(e, std::max(base_slack, 2 * step.norm()));
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
      area_averages(const Eigen::Vector2d &e, const ContactLoad &load, SurfacePressure &out)
      {
        const double turn = load.bushing_angle - load.pin_angle;
        deepest_overlap   = 0;
        if (single_sample >= 0)
          {
            const auto j = static_cast<unsigned int>(single_sample);
            out.bore[j / sub] += single_pressure / sub;
            const double r1 = grid.r1[j], r2 = grid.gap[j] + r1;
            out.pin[pin_area(grid.offset + j * grid.dp + load.bushing_angle - load.pin_angle)] +=
              single_pressure * r1 / r2 * grid.dp / (2 * pi / geometry().pin.n_points());
            return;
          }
        for (const unsigned int j : grid.window)
          {
            const double d = grid.overlap(j, e);
            if (d <= 0)
              continue;
            deepest_overlap = std::max(deepest_overlap, d);
            const double p  = pressure(d);
            out.bore[j / sub] += p / sub;
            // The same load on the pin: the sub-arc's length on the pin is r2/r1 of the
            // bore's; distribute the force (p r1 dφ) over the pin area it falls in.
            const double       r1 = grid.r1[j], r2 = grid.gap[j] + r1;
            const unsigned int k = pin_area(grid.offset + j * grid.dp + turn);
            out.pin[k] += p * r1 / r2 * grid.dp / (2 * pi / geometry().pin.n_points());
          }
      }

      /** The linear layer's stiffness in series with the state's wear compliance [Pa/m]. */
      double
      series_stiffness() const
      {
        return wear_compliance > 0 ? 1 / (1 / stiffness + wear_compliance) : stiffness;
      }

      double
      pressure(double d) const
      {
        if (!nonlinear)
          return series_stiffness() * d;
        return -modulus * std::log(1 - std::min(d / thickness, 1 - 1e-12));
      }

      /** P(d) = ∫0^d p(s) ds [N/m], the energy stored per unit area. */
      double
      stored_energy(double d) const
      {
        if (!nonlinear)
          return 0.5 * series_stiffness() * d * d;
        const double x = std::min(d / thickness, 1 - 1e-12);
        return modulus * thickness * ((1 - x) * std::log(1 - x) + x);
      }

      double
      slope(double d) const
      {
        if (!nonlinear)
          return series_stiffness();
        return modulus / thickness / std::max(1 - d / thickness, 1e-12);
      }

      unsigned int
      pin_area(double psi) const
      {
        const unsigned int m = geometry().pin.n_points();
        double             s = psi / (2 * pi);
        s -= std::floor(s);
        return std::min(m - 1, static_cast<unsigned int>(std::floor(s * m + 0.5)) % m);
      }

      const double thickness;
      const bool   nonlinear;
      double       stiffness = 0, modulus = 0;
      double       wear_compliance = 0;                ///< c of the state being worn (linear layer) [m/Pa]
      double       largest_pin = 0, smallest_bore = 0; ///< of the geometry set [m] (candidates_hold())
      /** The first half-width of the candidates around the load direction [rad] (evaluate()). */
      static constexpr double initial_half_window = pi / 6;
      double                  deepest_overlap     = 0;  ///< of the last evaluation [m]
      int                     single_sample       = -1; ///< see carry_on_one_sample(); −1: none
      double                  single_pressure     = 0;  ///< [Pa]
      SubGrid                 grid;
      Eigen::Vector2d         target;         ///< the load vector, bushing frame [N]
      Eigen::Vector2d         eccentricity;   ///< the rigid-body eccentricity, bushing frame [m]
      double                  base_slack = 0; ///< the window's slack of this solve [m], see equilibrium()
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
