// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed contact solver (contact_solver.h): one load state on its contact window,
// with the window's columns of the compliance gathered once and the Cholesky factor of
// the active block updated row by row from the first change.
#include "base/exceptions.h"
#include "base/text.h"
#include "base/timings.h"
#include "fe/active_set_rules.h"
#include "fe/blas_threads.h"
#include "fe/blas_trsm.h"
#include "fe/boundary_ids.h"
#include "fe/condensed_factor.h"
#include "fe/condensed_window.h"
#include "fe/contact_solver.h"
#include "fe/window_kernels.h"

#include <deal.II/base/parallel.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <set>
#include <tuple>

namespace wearlink::fe
{
  using namespace dealii;

  namespace condensed_detail
  {
    /**
     * g = g0 − n·U + A λ over the window, for the multipliers @p lambda (per position)
     * of @p active, at the positions @p rows names; the others keep their values. One
     * matrix–vector product of the gathered columns (BLAS) per run of positions.
     */
    void
    window_gaps(const ContactKinematics         &kin,
                WindowCompliance                &A,
                const std::vector<unsigned int> &active,
                const std::vector<double>       &lambda,
                const Tensor<1, 2>              &U,
                std::vector<double>             &gap,
                const Rows                       rows_wanted)
    {
      const unsigned int w = kin.g0.size();
      gap.resize(w);
      for (const auto p : active)
        A.ensure(p);
      const ScopedSeconds timer(A.timings().gaps);
      std::vector<double> x(A.n_slots(), 0.0);
      std::vector<char>   skip(w, rows_wanted == Rows::active);
      for (const auto p : active)
        {
          x[A.slot_of(p)] = lambda[p];
          skip[p]         = rows_wanted == Rows::inactive;
        }
      std::vector<std::pair<unsigned int, unsigned int>> runs; // [q0, q1) of wanted rows
      for (unsigned int q0 = 0; q0 < w;)
        {
          unsigned int q1 = q0;
          for (; q1 < w && !skip[q1]; ++q1)
            gap[q1] = kin.g0[q1] - kin.normal[q1] * U;
          if (q1 > q0)
            runs.emplace_back(q0, q1);
          q0 = q1 + 1;
        }
      // Each run's rows in two halves, the first halves one task, the second the other.
      std::size_t rows_total = 0;
      for (const auto &[q0, q1] : runs)
        rows_total += q1 - q0;
      const unsigned int parts = rows_total * x.size() >= gaps_parallel_from && blas_is_thread_safe() ? 2 : 1;
      const auto         part  = [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int n = begin; n < end; ++n)
          for (const auto &[q0, q1] : runs)
            {
              const unsigned int r0 = q0 + n * (q1 - q0) / parts, r1 = q0 + (n + 1) * (q1 - q0) / parts;
              const blas_int     rows = r1 - r0, cols = x.size(), ld = w, one = 1;
              const double       alpha = 1, beta = 1;
              if (rows > 0 && cols > 0)
                gemv("N", &rows, &cols, &alpha, A.data() + r0, &ld, x.data(), &one, &beta, gap.data() + r0, &one);
            }
      };
      parallel::apply_to_subranges(0u, parts, part, 1);
    }

    /** Everything one window solve carries between its phases. */
    struct WindowState
    {
      std::vector<unsigned int> active;
      std::vector<double>       lambda, gap; ///< per position of the window
      Tensor<1, 2>              U;
      unsigned int              iterations = 0;
      /**
       * max |g0_p| / A_pp over the active positions [N/m]: the line load that closing
       * the initial gaps alone would carry. The active solve cancels terms of this size
       * down to the load, so the balance holds to round-off of it, not of the load
       * (a vanishing load on a pin whose rigid translation closes gaps of ~1e-8 m).
       */
      double gap_force = 0;
    };

    /** Apply an active solution: λ on the window, U, and the gaps (see window_gaps()). */
    void
    accept(const ContactKinematics &kin, WindowCompliance &A, const ActiveSolution &x, WindowState &st, const Rows rows)
    {
      std::fill(st.lambda.begin(), st.lambda.end(), 0.0);
      for (unsigned int s = 0; s < st.active.size(); ++s)
        st.lambda[st.active[s]] = x.lambda[s];
      st.U = x.U;
      window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, rows);
    }

    /**
     * Iterative refinement of the applied active solution in @p st, whose gaps are
     * those of the active positions (accept()): the residuals of the active system are
     * −g there (from the double-precision columns) and P − Nᵀλ; the correction solves
     * the same system for them with the factor again. Ends when the error left is below
     * 1e-12 of λ (two corrections from a single-precision factor at 100 kN), with the
     * gaps of the inactive positions; false if that takes more than max_refinements.
     */
    bool
    refine(const ContactKinematics &kin,
           WindowCompliance        &A,
           ActiveFactor            &factor,
           const bool               force_control,
           const Tensor<1, 2>      &P,
           WindowState             &st)
    {
      constexpr unsigned int max_refinements = 6;
      const auto            &order           = factor.ordered();
      const unsigned int     k               = order.size();
      double                 previous        = 0; // the size of the last correction
      for (unsigned int step = 0; step < max_refinements; ++step)
        {
          std::vector<double> x(k);
          Tensor<1, 2>        balance = P, dU;
          double              largest = 0;
          for (unsigned int r = 0; r < k; ++r)
            {
              x[r] = -st.gap[order[r]];
              balance -= st.lambda[order[r]] * kin.normal[order[r]];
              largest = std::max(largest, std::abs(st.lambda[order[r]]));
            }
          factor.forward_full(x);
          if (force_control && !schur_step(factor, balance, x, dU))
            return false;
          factor.backward(x);
          double correction = 0;
          for (unsigned int r = 0; r < k; ++r)
            {
              st.lambda[order[r]] += x[r];
              correction = std::max(correction, std::abs(x[r]));
            }
          st.U += dU;
          // Converged when this correction, or the next one that the contraction of the
          // last two predicts (each correction leaves ρ = c_k / c_(k−1) of itself, ~3e-5
          // from a float factor at 100 kN), is below 1e-12 of λ; the active gaps then
          // move by A δλ, below round-off.
          const double next = step > 0 && previous > 0 ? correction * (correction / previous) : correction;
          if (std::max(next, correction * 1e-4) <= 1e-12 * largest || correction <= 1e-12 * largest)
            {
              window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::inactive);
              return true;
            }
          previous = correction;
          window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::active);
        }
      return false;
    }

    /**
     * Solve the active system on st.active and apply it (accept()), to double precision
     * if @p exact (refine() after a single-precision factor; a double factor if that
     * does not converge). False if a factorization fails.
     */
    bool
    solve_and_accept(const ContactKinematics &kin,
                     WindowCompliance        &A,
                     ActiveFactor            &factor,
                     const bool               force_control,
                     const Tensor<1, 2>      &P,
                     const bool               exact,
                     const bool               inactive_only,
                     WindowState             &st)
    {
      auto x = solve_active(kin, factor, st.active, force_control, P);
      if (!x.ok)
        return false;
      const bool refining = exact && factor.single_precision();
      accept(kin, A, x, st, refining ? Rows::active : inactive_only ? Rows::inactive : Rows::all);
      if (!refining || refine(kin, A, factor, force_control, P, st))
        return true;
      factor.make_double();
      x = solve_active(kin, factor, st.active, force_control, P);
      if (!x.ok)
        return false;
      accept(kin, A, x, st, inactive_only ? Rows::inactive : Rows::all);
      return true;
    }

    /**
     * The primal–dual iteration from @p st.active; true when the active set repeats
     * (converged), false when it cycles, stalls at @p limit, or a factorization fails.
     * Each active solve to double precision if @p exact, else to the factor's.
     */
    bool
    primal_dual(const ContactKinematics &kin,
                WindowCompliance        &A,
                ActiveFactor            &factor,
                const bool               force_control,
                const Tensor<1, 2>      &P,
                const unsigned int       limit,
                const bool               exact,
                WindowState             &st)
    {
      std::set<std::vector<unsigned int>> history;
      for (unsigned int it = 1; it <= limit; ++it)
        {
          ++st.iterations;
          if (!solve_and_accept(kin, A, factor, force_control, P, exact, true, st))
            return false;
          auto next = active_set::update(st.active, st.lambda, st.gap, kin.tolerance, history);
          if (force_control)
            active_set::ensure_two_active(next, st.gap, kin.normal, P);
          if (next == st.active)
            return true;
          if (history.count(next) != 0)
            return false;
          st.active = next;
        }
      return false;
    }

    /**
     * A feasible start of the monotone phase: λ ≥ 0 with Σ λ n = P (force control) on the
     * two positions of ensure_two_active (closest, and the one bracketing P with it), or
     * λ = 0 (displacement control).
     */
    void
    feasible_start(const ContactKinematics &kin, const bool force_control, const Tensor<1, 2> &P, WindowState &st)
    {
      std::fill(st.lambda.begin(), st.lambda.end(), 0.0);
      st.active.clear();
      if (!force_control)
        return;
      active_set::ensure_two_active(st.active, kin.g0, kin.normal, P);
      if (st.active.size() < 2)
        return;
      const auto  &a = kin.normal[st.active[0]], &b = kin.normal[st.active[1]];
      const double d = a[0] * b[1] - a[1] * b[0];
      if (d == 0.0)
        return;
      // Clipped at 0 when the pair does not bracket the load (then the start is not
      // quite feasible; the first full step restores the balance).
      st.lambda[st.active[0]] = std::max(0.0, (P[0] * b[1] - P[1] * b[0]) / d);
      st.lambda[st.active[1]] = std::max(0.0, (a[0] * P[1] - a[1] * P[0]) / d);
    }

    /**
     * The monotone (Lawson–Hanson type) step from the feasible λ towards the minimizer
     * @p x of the current active set: the longest step α ∈ [0, 1) that keeps λ ≥ 0; the
     * positions whose force reaches zero leave the set. Returns α, or 1 (changing
     * nothing) if @p x is feasible itself.
     */
    double
    step_back_to_feasible(std::vector<unsigned int> &active, const std::vector<double> &x, std::vector<double> &lambda)
    {
      double       alpha = 1, tolerance = 0; // forces this close to zero are zero (active_set::update)
      unsigned int blocker = active.size();
      for (const double v : x)
        tolerance = std::max(tolerance, 1e-10 * std::abs(v));
      for (unsigned int s = 0; s < active.size(); ++s)
        if (x[s] < -tolerance)
          {
            const double l = lambda[active[s]];
            const double a = l > 0 ? l / (l - x[s]) : 0.0;
            if (blocker == active.size() || a < alpha)
              {
                alpha   = a;
                blocker = s;
              }
          }
      if (blocker == active.size())
        return 1;
      std::vector<unsigned int> kept;
      if (alpha == 0)
        {
          // Degenerate: positions at zero force that the minimizer wants tensile leave;
          // the point does not move, and the others stay.
          for (unsigned int s = 0; s < active.size(); ++s)
            if (lambda[active[s]] > 0 || x[s] >= -tolerance)
              kept.push_back(active[s]);
          active = kept;
          return 0;
        }
      double max_lambda = 0;
      for (unsigned int s = 0; s < active.size(); ++s)
        {
          double &l = lambda[active[s]];
          l += alpha * (x[s] - l);
          max_lambda = std::max(max_lambda, l);
        }
      lambda[active[blocker]] = 0;
      for (const auto i : active)
        if (lambda[i] > 1e-14 * max_lambda)
          kept.push_back(i);
        else
          lambda[i] = 0;
      active = kept;
      return alpha;
    }

    /** The penetrating positions outside the active set, the worst first. */
    std::vector<unsigned int>
    penetrating(const std::vector<double> &lambda, const std::vector<double> &gap, const double tolerance)
    {
      std::vector<unsigned int> out;
      for (unsigned int i = 0; i < gap.size(); ++i)
        if (lambda[i] == 0.0 && gap[i] < -tolerance)
          out.push_back(i);
      std::stable_sort(out.begin(), out.end(), [&](unsigned int a, unsigned int b) { return gap[a] < gap[b]; });
      return out;
    }

    /**
     * The monotone primal active-set method (see CondensedContactSolver::solve): from the
     * feasible pair, the worst penetrating position joins, one at a time; a step that
     * would make a force tensile stops where it reaches zero and that position leaves.
     * The objective never increases and drops at every step that is not degenerate, so
     * no active set repeats. True when it ends within @p limit steps.
     */
    bool
    monotone(const ContactKinematics &kin,
             WindowCompliance        &A,
             ActiveFactor            &factor,
             const bool               force_control,
             const Tensor<1, 2>      &P,
             const unsigned int       limit,
             WindowState             &st)
    {
      feasible_start(kin, force_control, P, st);
      // A position that joins and is dropped again at once without the point moving
      // (round-off at a penetration near the tolerance) is blocked until the point
      // moves; violations left only at blocked positions below 1 nm count as solved.
      const unsigned int w = kin.g0.size();
      std::vector<char>  blocked(w, 0);
      unsigned int       joined = w;
      for (unsigned int it = 0; it < limit; ++it, ++st.iterations)
        {
          if (force_control)
            active_set::ensure_two_active(st.active, kin.g0, kin.normal, P);
          const auto x = solve_active(kin, factor, st.active, force_control, P);
          if (!x.ok)
            return false;
          const double alpha = step_back_to_feasible(st.active, x.lambda, st.lambda);
          if (alpha == 0 && joined < w && !std::binary_search(st.active.begin(), st.active.end(), joined))
            blocked[joined] = 1;
          else if ((alpha > 0 && alpha < 1) || (alpha == 1 && joined < w)) // the point moved
            std::fill(blocked.begin(), blocked.end(), 0);
          joined = w;
          if (alpha < 1)
            continue;
          accept(kin, A, x, st, Rows::all);
          double worst_blocked = 0;
          for (const auto i : penetrating(st.lambda, st.gap, kin.tolerance))
            if (!blocked[i])
              {
                joined = i;
                break;
              }
            else
              worst_blocked = std::min(worst_blocked, st.gap[i]);
          if (joined == w)
            return worst_blocked > -1e-9;
          st.active.insert(std::upper_bound(st.active.begin(), st.active.end(), joined), joined);
        }
      return false;
    }

    /** Whether some of @p normal lie on either side of @p load (or along it). */
    bool
    brackets(const std::vector<Tensor<1, 2>> &normal, const Tensor<1, 2> &load)
    {
      bool left = false, right = false;
      for (const auto &n : normal)
        if (n * load > 0)
          {
            const double side = load[0] * n[1] - load[1] * n[0];
            left              = left || side >= 0;
            right             = right || side <= 0;
          }
      return left && right;
    }

    /** The starting active set: @p warm (candidates) in the window, else the overlapping positions. */
    std::vector<unsigned int>
    starting_set(const ContactKinematics         &kin,
                 const double                     clearance,
                 const std::vector<unsigned int> &warm,
                 const bool                       force_control,
                 const Tensor<1, 2>              &P)
    {
      std::vector<unsigned int> active;
      for (const auto c : warm)
        {
          const auto it = std::lower_bound(kin.candidates.begin(), kin.candidates.end(), c);
          if (it != kin.candidates.end() && *it == c)
            active.push_back(it - kin.candidates.begin());
        }
      if (active.empty())
        {
          // The rigid overlap of the pose (of depth δ) reaches farther than the contact,
          // whose edges the elastic deformation carries: on the round steel pair the
          // contact's half-angle is r = 0.45, 0.52, 0.63, 0.78 of the overlap's at
          // δ/c = 5e-4, 4e-3, 0.027, 0.16 (100 N … 100 kN; r ≈ 0.89 + 0.134 log10(δ/c)).
          // An overlap δ − (c + δ)θ²/2 ≥ (1 − r²) δ marks that arc; the iteration
          // corrects the rest (this only saves iterations).
          const double overlap = -*std::min_element(kin.g0.begin(), kin.g0.end());
          const double r       = std::clamp(0.89 + 0.134 * std::log10(std::max(overlap, 1e-30) / clearance), 0.3, 1.0);
          for (unsigned int p = 0; p < kin.g0.size(); ++p)
            if (kin.g0[p] < -std::max((1 - r * r) * overlap, kin.tolerance))
              active.push_back(p);
        }
      if (force_control)
        active_set::ensure_two_active(active, kin.g0, kin.normal, P);
      return active;
    }

    /** Largest elastic opening of the gap, n·U − g0, over the active positions [m] (≥ 0). */
    double
    largest_opening(const ContactKinematics &kin, const WindowState &st)
    {
      double c = 0;
      for (const auto p : st.active)
        c = std::max(c, kin.normal[p] * st.U - kin.g0[p]);
      return c;
    }

    /** Mean bore radius − mean pin radius of the meshed surfaces [m] (> 0). */
    double
    mean_clearance(const ElasticityProblem &problem)
    {
      double r1 = 0, r2 = 0;
      for (const auto &n : problem.bore_nodes)
        r1 += n.point.norm() / problem.bore_nodes.size();
      for (const auto &n : problem.pin_nodes)
        r2 += n.point.norm() / problem.pin_nodes.size();
      return std::max(r1 - r2, 1e-9);
    }

  } // namespace condensed_detail

  using namespace condensed_detail;


  CondensedContactSolver::CondensedContactSolver(const ElasticityProblem &problem,
                                                 BoundaryCompliance      &compliance,
                                                 unsigned int             max_iterations,
                                                 unsigned int             primal_dual_limit)
    : problem(problem)
    , compliance(compliance)
    , max_iterations(max_iterations)
    , primal_dual_limit(primal_dual_limit)
    , clearance(mean_clearance(problem))
    , pin_radius(smallest_pin_radius(problem))
    , spacing(candidate_spacing(problem))
    , workspace(std::make_unique<Workspace>())
  {
  }


  CondensedContactSolver::~CondensedContactSolver() = default;


  const CondensedTimings &
  CondensedContactSolver::timings() const
  {
    return workspace->timings;
  }


  // The window: every candidate whose initial gap is below T. A candidate outside it
  // stays open unless the elastic deformation closes the gap there by more than
  // T − |U|. Near a compressive contact the elastic part of the gap (A λ) opens it; it
  // closes it only where the surfaces bulge, far from the contact: measured on the
  // steel pair (50 µm elements, 10 N … 100 kN, round and with a 30 µm / 10 µm worn
  // dent, three load directions, every candidate evaluated), the elastic part outside
  // the contact was never below −0.055 × its largest value at the contact (the
  // opening). So the window is accepted when T − |U| ≥ 0.25 × the opening (a margin
  // of 4.5), and widened to twice what that needs otherwise. T starts at half the
  // expected approach, at least half the overlap of the pose, and 1e-3 of the
  // candidate spacing above the smallest gap.
  // In the window: the primal–dual iteration (fast; may cycle on worn, conforming
  // pairs), and when it revisits an active set or after primal_dual_limit iterations the
  // monotone method from a feasible point (slower, but the objective ½λᵀAλ + g0ᵀλ never
  // increases, so it ends).
  // The active-set phases of one linearization on the window: primal–dual, then the
  // monotone method if that did not converge. Throws if neither does.
  void
  CondensedContactSolver::solve_linearized(const ContactKinematics &kin,
                                           WindowCompliance        &A,
                                           ActiveFactor            &factor,
                                           const bool               force_control,
                                           const Tensor<1, 2>      &load,
                                           const bool               exact,
                                           WindowState             &st,
                                           bool                    &monotone_used)
  {
    bool done =
      primal_dual(kin, A, factor, force_control, load, std::min(max_iterations, primal_dual_limit), exact, st);
    if (!done)
      {
        ++n_monotone;
        monotone_used = true;
        factor.make_double(); // the monotone phase decides on exact solutions
        done = monotone(kin, A, factor, force_control, load, 10 * max_iterations, st);
      }
    if (!done)
      active_set::not_converged("condensed", st.iterations);
  }


  // The accepted linearization, solved with a single-precision factor, to double
  // precision: its solution refined (refine()) and the active set checked with the
  // refined gaps; if the set changes, the primal–dual iteration goes on with refined
  // solves. Leaves the gaps of every position.
  void
  CondensedContactSolver::solve_exactly(const ContactKinematics &kin,
                                        WindowCompliance        &A,
                                        ActiveFactor            &factor,
                                        const bool               force_control,
                                        const Tensor<1, 2>      &load,
                                        WindowState             &st,
                                        bool                    &monotone_used)
  {
    window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::active);
    if (refine(kin, A, factor, force_control, load, st))
      {
        std::set<std::vector<unsigned int>> history;
        auto next = active_set::update(st.active, st.lambda, st.gap, kin.tolerance, history);
        if (force_control)
          active_set::ensure_two_active(next, st.gap, kin.normal, load);
        if (next == st.active)
          return;
      }
    else
      factor.make_double();
    solve_linearized(kin, A, factor, force_control, load, true, st, monotone_used);
    window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::all);
  }


  // The linearizations of one pairing: each refreshes the gaps about the translated pin
  // (refresh_gaps(), the pairing kept) until the translation of the last one is small
  // (relinearization_done()). First the window is checked (so that the path is the
  // reference solver's, which sees every candidate): too narrow, @p widen receives the
  // threshold it needs; then the linearization and the pairing: a pin that slid by
  // more than pairing_outdated() ends the pairing. U_pair: the translation since it.
  CondensedContactSolver::PairingEnd
  CondensedContactSolver::linearize(const PinPose      &paired,
                                    const double        threshold,
                                    const bool          force_control,
                                    const Tensor<1, 2> &load,
                                    ContactKinematics  &kin,
                                    WindowCompliance   &A,
                                    ActiveFactor       &factor,
                                    WindowState        &st,
                                    Tensor<1, 2>       &U_pair,
                                    unsigned int       &updates,
                                    double             &widen,
                                    bool               &monotone_used)
  {
    PinPose moved = paired;
    for (;;)
      {
        solve_linearized(kin, A, factor, force_control, load, false, st, monotone_used);
        U_pair += st.U;
        const double needed = U_pair.norm() + 0.25 * largest_opening(kin, st) + kin.tolerance;
        if (needed > threshold && threshold < 4 * paired.bore->max_radius())
          {
            widen = 2 * needed;
            return PairingEnd::narrow;
          }
        // Converged: accepted if paired at the solution, else paired there once more.
        const bool done = relinearization_done(st.U, pin_radius);
        if (!force_control || (done && !pairing_off_the_solution(U_pair, load / load.norm(), spacing)) ||
            ++updates >= max_relinearizations)
          return PairingEnd::accepted;
        if (done || pairing_outdated(U_pair, spacing))
          return PairingEnd::slid;
        moved.eccentricity = paired.eccentricity + U_pair;
        refresh_gaps(problem, moved, kin);
        factor.gaps_changed();
      }
  }


  // On a worn, jagged bore the window's few candidates (9 at 87 N, 0.2 mm elements,
  // bores worn ~50 µm) can all face one side of the load: their normals span −22.3° …
  // −10.4° against a load at −9.0°. Then no λ ≥ 0 balances the load, the monotone
  // phase's feasible start is not feasible, and its step drops the pair's second
  // position that ensure_two_active() adds back, forever. The window is widened
  // (the threshold doubled, at least by 5 % of the candidate spacing) until some normal
  // lies on either side of the load; a closed bore always has such normals.
  ContactKinematics
  CondensedContactSolver::load_bracketing_window(const PinPose      &pose,
                                                 const bool          force_control,
                                                 const Tensor<1, 2> &load,
                                                 double             &T,
                                                 double             &threshold) const
  {
    const double largest = 4 * pose.bore->max_radius();
    for (;;)
      {
        auto kin = compute_window_kinematics(problem, pose, {T, 1e-3 * spacing, 0.5}, &threshold);
        if (!force_control || brackets(kin.normal, load) || threshold >= largest)
          return kin;
        T = std::max(2 * threshold, threshold + 0.05 * spacing);
      }
  }


  // Pairings: the window kinematics at a pose, its compliance and factor, and its
  // linearizations (linearize()). A pin that slides by more than a quarter of the
  // candidate spacing since the pairing (a light load on a worn, inclined bore: 70 µm
  // measured) is paired anew at its new pose, warm-started from the active candidates;
  // a window too narrow for the solution's deformation is widened and the pairing
  // solved again. The accepted linearization of a single-precision factor is taken to
  // double precision (solve_exactly()).
  ContactSolution
  CondensedContactSolver::solve(const PinPose      &pose,
                                const bool          force_control,
                                const Tensor<1, 2> &load,
                                const double        closure_estimate,
                                ContactKinematics  &kin)
  {
    const ScopedSeconds timer(workspace->timings.total);
    ++workspace->timings.solves;
    double                    T = 0.5 * std::max(closure_estimate, 0.0);
    std::vector<unsigned int> warm;
    ContactSolution           sol;
    PinPose                   paired  = pose;
    unsigned int              updates = 0;
    for (unsigned int pairing = 0; pairing < 4 * max_relinearizations; ++pairing)
      {
        double threshold = 0;
        kin              = load_bracketing_window(paired, force_control, load, T, threshold);
        WindowCompliance A(problem, compliance, kin, *workspace, wear_diagonal);
        WindowState      st;
        st.lambda.assign(kin.g0.size(), 0.0);
        st.active = starting_set(kin, clearance, warm, force_control, load);
        ActiveFactor factor(A, kin, problem.pin_nodes.size(), *workspace, st.active.size() >= single_precision_from);
        Tensor<1, 2> U_pair;                         // since `paired`
        const unsigned int updates_before = updates; // a widened window solves this pairing again
        const auto         end =
          linearize(paired, threshold, force_control, load, kin, A, factor, st, U_pair, updates, T, sol.monotone);
        sol.iterations += st.iterations;
        warm.clear();
        for (const auto p : st.active)
          warm.push_back(kin.candidates[p]);
        if (end == PairingEnd::narrow)
          {
            updates = updates_before;
            continue;
          }
        if (end == PairingEnd::slid)
          {
            paired.eccentricity += U_pair;
            T = 0.5 * std::max(closure_estimate, 0.0);
            continue;
          }
        if (factor.single_precision())
          {
            const unsigned int before = st.iterations;
            U_pair -= st.U;
            solve_exactly(kin, A, factor, force_control, load, st, sol.monotone);
            U_pair += st.U;
            sol.iterations += st.iterations - before;
          }
        else
          window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::all);
        A.ensure(st.active);
        for (const auto p : st.active)
          st.gap_force = std::max(st.gap_force, std::abs(kin.g0[p]) / A.column(p)[p]);
        finish(kin, st, force_control, load, sol);
        sol.pin_translation = paired.eccentricity - pose.eccentricity + U_pair;
        return sol;
      }
    throw NumericalError("The condensed contact solver could not find a contact window that holds the contact.");
  }


  // The solution of the last linearization: the balance checked (a gross failure, not
  // round-off: the 2 × 2 Schur complement of two nearly parallel normals has a condition
  // of ~1e6, so it holds to ~1e-10 of the load, not to machine precision — and to
  // round-off of the gaps' line load for a vanishing load), forces zero up to round-off
  // made zero.
  void
  CondensedContactSolver::finish(const ContactKinematics &kin,
                                 WindowState             &st,
                                 const bool               force_control,
                                 const Tensor<1, 2>      &load,
                                 ContactSolution         &sol) const
  {
    sol.resultant = 0;
    for (const auto p : st.active)
      sol.resultant += st.lambda[p] * kin.normal[p];
    // The balance to 1e-8 of the load, or to 1e-12 of the gaps' line load (see
    // WindowState::gap_force) where the load is far smaller than that.
    const double imbalance = (sol.resultant - load).norm();
    const double residual  = imbalance / load.norm();
    if (force_control && !(imbalance <= 1e-8 * load.norm() + 1e-12 * st.gap_force))
      throw NumericalError("The condensed contact solver ended out of equilibrium (resultant off the load by " +
                           format_number(residual, 3) +
                           " of it). Refine the contact surfaces ('Surface element size').");
    for (auto &l : st.lambda) // round-off of a force that is zero (active_set::update)
      l = std::max(l, 0.0);
    sol.lambda           = st.lambda;
    sol.gap              = st.gap;
    sol.active           = st.active;
    sol.last_translation = st.U;
    sol.n_active         = st.active.size();
  }


  // The displacement field for a condensed solution: the contact forces −λ_i ν_i on
  // the pin and +λ_i n_i (interpolated) on the bore, one solve with the clamped
  // factorization, plus the pin's rigid translation U (in the pin frame) on its DoFs.
  Vector<double>
  CondensedContactSolver::displacement_field(const ContactKinematics &kin, const ContactSolution &sol) const
  {
    Vector<double> u(problem.dof_handler.n_dofs());
    for (unsigned int p = 0; p < kin.candidates.size(); ++p)
      if (sol.lambda[p] != 0)
        {
          const auto &node = problem.pin_nodes[kin.candidates[p]];
          u(node.dofs[0]) -= sol.lambda[p] * node.normal[0];
          u(node.dofs[1]) -= sol.lambda[p] * node.normal[1];
          for (unsigned int a = 0; a < kin.n_masters[p]; ++a)
            {
              const auto &b = problem.bore_nodes[kin.masters[p][a]];
              u(b.dofs[0]) += sol.lambda[p] * kin.weights[p][a] * kin.normal[p][0];
              u(b.dofs[1]) += sol.lambda[p] * kin.weights[p][a] * kin.normal[p][1];
            }
        }
    compliance.solve_clamped(u);
    const Tensor<1, 2>            U_pin = rotate(sol.pin_translation, -kin.relative_angle);
    std::vector<char>             done(u.size(), 0);
    std::vector<global_dof_index> dofs(problem.fe.n_dofs_per_cell());
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->material_id() == material_ids::pin)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (!done[dofs[i]])
              {
                done[dofs[i]] = 1;
                u(dofs[i]) += U_pin[problem.fe.system_to_component_index(i).first];
              }
        }
    return u;
  }
} // namespace wearlink::fe
