// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/simulation.h"

#include "base/exceptions.h"
#include "mbs/body_trig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace wearlink::mbs
{

  void
  MechanismOde::rhs(double t, const double *y, double *dydt)
  {
    const unsigned int n = mechanism.n_coordinates();
    const double      *q = y;
    const double      *v = y + n;
    for (unsigned int i = 0; i < n; ++i)
      dydt[i] = v[i];
    PowerTerms power;
    mechanism.accelerations(t, q, v, dydt + n, power);
    double *z               = dydt + 2 * n;
    z[reaction_work]        = power.constraint;
    z[reaction_work_abs]    = std::abs(power.constraint);
    z[damping_dissipation]  = power.damping;
    z[friction_dissipation] = power.friction;
  }

  void
  MechanismOde::stiff_directions(double, const double *y, std::vector<StiffDirection> &out)
  {
    out.clear();
    const unsigned int n = mechanism.n_coordinates();
    const StateView    s(y, y + n);
    for (const auto &e : mechanism.get_force_elements())
      e->stiff_directions(s, n, out);
  }

  Simulation::Simulation(Mechanism &mechanism, const SimulationSettings &settings)
    : mechanism(mechanism)
    , settings(settings)
    , system(mechanism)
  {
    auto s = settings.integrator;
    // Error control on q and v only; the accumulators follow with the same order.
    if (s.absolute_tolerance.size() != system.size())
      {
        const double       pos = s.absolute_tolerance.empty() ? 1e-9 : s.absolute_tolerance[0];
        const double       vel = s.absolute_tolerance.size() < 2 ? 1e-6 : s.absolute_tolerance[1];
        const unsigned int n   = mechanism.n_coordinates();
        s.absolute_tolerance.assign(system.size(), 0.0);
        for (unsigned int i = 0; i < n; ++i)
          {
            s.absolute_tolerance[i]     = pos;
            s.absolute_tolerance[n + i] = vel;
          }
      }
    position_tolerance = s.absolute_tolerance[0];
    integrator         = make_integrator(system, s);
    locate_events      = s.type != IntegratorType::rk4;
    scratch.setZero(system.size());
    end_trig.assign(2 * mechanism.n_bodies(), 0.0);
  }

  void
  Simulation::initialize(double t0, const Eigen::VectorXd &q0, const Eigen::VectorXd &v0)
  {
    Eigen::VectorXd y0                       = Eigen::VectorXd::Zero(system.size());
    y0.segment(system.q_offset(), q0.size()) = q0;
    y0.segment(system.v_offset(), v0.size()) = v0;
    initialize_state(t0, y0);
  }

  void
  Simulation::initialize_state(double t0, const Eigen::VectorXd &y0)
  {
    // Modes consistent with the initial state (a joint starting in contact has no
    // located onset: it takes its impact velocity from the initial state).
    const unsigned int n = mechanism.n_coordinates();
    const StateView    s(y0.data(), y0.data() + n);
    for (const auto &e : mechanism.get_force_elements())
      if (e->has_event() && (e->event_value(s) > 0) != e->mode())
        e->on_event(t0, s, e->event_value(s) > 0);
    integrator->reset(t0, y0);
    budget_start_time  = t0;
    budget_start_steps = integrator->n_accepted + integrator->n_rejected;
  }

  void
  Simulation::state_at(double t, Eigen::VectorXd &y) const
  {
    y.resize(system.size());
    integrator->dense_output(t, y.data());
  }

  void
  Simulation::derivative_at(double t, const Eigen::VectorXd &y, Eigen::VectorXd &dydt)
  {
    dydt.resize(system.size());
    system.rhs(t, y.data(), dydt.data());
  }

  void
  Simulation::check_step_budget() const
  {
    if (!(settings.max_steps_per_second > 0))
      return;
    const long   steps   = integrator->n_accepted + integrator->n_rejected - budget_start_steps;
    const double elapsed = integrator->time() - budget_start_time;
    if (steps <= settings.step_budget_grace + settings.max_steps_per_second * elapsed)
      return;
    std::ostringstream os;
    os << "The integrator took " << steps << " steps for " << elapsed << " s of motion (t = " << integrator->time()
       << " s, mean step " << elapsed / static_cast<double>(steps)
       << " s), beyond the step budget of Integrator/Maximum steps per second = " << settings.max_steps_per_second
       << " (plus " << settings.step_budget_grace
       << "). Contact or constraints this stiff lie far outside the scene's model: check the joint "
          "geometry (attachment points), the elastic moduli and the loads; set Maximum steps per second = 0 "
          "to run on regardless.";
    throw NumericalError(os.str());
  }

  double
  Simulation::locate(const ForceElement &e, bool onset) const
  {
    // Bracket [lo, hi] with the "before" sign at lo and the "after" sign at hi.
    const unsigned int n   = mechanism.n_coordinates();
    auto               val = [&](double t) {
      integrator->dense_output(t, scratch.data());
      return e.event_value(StateView(scratch.data(), scratch.data() + n));
    };
    auto after = [&](double f) {
      return onset ? f > 0 : f <= 0;
    };

    double lo   = integrator->previous_time();
    double hi   = integrator->time();
    double f_lo = val(lo);
    double f_hi = val(hi);
    if (after(f_lo))
      return lo; // the mode was already out of date at the start of the step
    int side = 0;
    for (unsigned int it = 0; it < 200 && hi - lo > settings.event_time_tolerance; ++it)
      {
        double tm = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if (!(tm > lo && tm < hi))
          tm = 0.5 * (lo + hi);
        const double fm = val(tm);
        if (after(fm))
          {
            hi   = tm;
            f_hi = fm;
            if (side == -1)
              f_lo *= 0.5; // Illinois modification
            side = -1;
          }
        else
          {
            lo   = tm;
            f_lo = fm;
            if (side == +1)
              f_hi *= 0.5;
            side = +1;
          }
      }
    return hi;
  }

  double
  Simulation::step_limit(const double t_end, const std::vector<ForceElement *> &elements) const
  {
    const double t    = integrator->time();
    const double span = std::min(integrator->proposed_step(), t_end - t);
    if (!locate_events || !settings.predict_onsets || !(span > 0))
      return t_end;
    // Penetration of element e at the predicted positions after τ (velocities unused).
    const unsigned int     n         = mechanism.n_coordinates();
    const Eigen::VectorXd &y         = integrator->state();
    const Eigen::VectorXd &f         = integrator->derivative();
    auto                   predicted = [&](const ForceElement &e, const double tau) {
      for (unsigned int i = 0; i < n; ++i)
        scratch[i] = y[i] + tau * (y[n + i] + 0.5 * tau * f[n + i]);
      return e.event_value(StateView(scratch.data(), y.data() + n));
    };
    // Each free element's predicted time to a penetration of onset_penetration; the
    // step ends at the earliest one.
    const double depth = onset_penetration();
    double       first = span;
    for (const auto *e : elements)
      {
        if (e->mode())
          continue;
        // A crossing inside the first half is looked for first, so that a grazing
        // approach that leaves again before the step's end is not missed.
        double hi = 0.5 * first;
        if (!(predicted(*e, hi) > depth))
          {
            hi = first;
            if (!(predicted(*e, hi) > depth))
              continue;
          }
        double lo = 0; // free at lo (the element's mode says so), deeper than depth at hi
        for (int it = 0; it < 30 && hi - lo > 1e-3 * hi; ++it)
          {
            const double mid                       = 0.5 * (lo + hi);
            (predicted(*e, mid) > depth ? hi : lo) = mid;
          }
        // Already at the depth (a state on the contact surface): nothing to predict.
        if (lo > 0)
          first = lo;
      }
    if (first >= span)
      return t_end;
    ++predicted_onsets;
    return std::min(t_end, t + first);
  }

  void
  Simulation::run(double t_end, const std::vector<StepObserver *> &observers)
  {
    {
      const StepContext c{*this, integrator->time(), integrator->time(), integrator->state(), integrator->derivative()};
      for (auto *o : observers)
        o->on_start(c);
    }
    std::vector<ForceElement *> event_elements, hold_elements;
    for (const auto &e : mechanism.get_force_elements())
      {
        if (e->has_event())
          event_elements.push_back(e.get());
        if (e->can_hold())
          hold_elements.push_back(e.get());
      }

    Eigen::VectorXd             y_start;
    std::vector<ForceElement *> triggered;
    std::vector<double>         roots;
    while (integrator->time() < t_end)
      {
        const double t_start = integrator->time();
        y_start              = integrator->state();
        integrator->step(step_limit(t_end, event_elements));

        find_events(t_start, y_start, event_elements, triggered, roots);

        if (!hold_elements.empty() && triggered.empty())
          locate_hold_release(t_start, y_start, hold_elements);

        check_step_budget();
        if (!integrator->state().allFinite())
          throw NumericalError("The state became non-finite at t = " + std::to_string(integrator->time()) + " s.");
        {
          const StepContext c{*this,
                              integrator->previous_time(),
                              integrator->time(),
                              integrator->state(),
                              integrator->derivative()};
          for (auto *o : observers)
            o->on_step(c);
        }

        // The modes change after the observers saw the step; f changes with them.
        const bool switched = switch_modes(triggered, roots);
        const bool holds    = !hold_elements.empty() && update_holds(hold_elements);
        if (switched || holds)
          {
            const Eigen::VectorXd y_now = integrator->state();
            integrator->reset(integrator->time(), y_now);
          }
      }
  }

  void
  Simulation::find_events(const double                       t_start,
                          const Eigen::VectorXd             &y_start,
                          const std::vector<ForceElement *> &event_elements,
                          std::vector<ForceElement *>       &triggered,
                          std::vector<double>               &roots)
  {
    const unsigned int n = mechanism.n_coordinates();
    // Which elements' modes no longer match the state at the end of the step?
    double t_first = std::numeric_limits<double>::infinity();
    triggered.clear();
    roots.clear();
    if (!event_elements.empty())
      body_trig(integrator->state().data(), mechanism.n_bodies(), end_trig.data());
    for (auto *e : event_elements)
      {
        const double f =
          e->event_value(StateView(integrator->state().data(), integrator->state().data() + n, end_trig.data()));
        const bool onset = !e->mode() && f > 0;
        const bool sep   = e->mode() && f <= 0;
        if (onset || sep)
          {
            triggered.push_back(e);
            roots.push_back(locate(*e, onset));
            t_first = std::min(t_first, roots.back());
          }
      }

    // With event location, end the step at the first event; only the events at that
    // time switch now (later ones are found again).
    bool at_root = false;
    if (!triggered.empty() && locate_events && t_first - t_start > settings.event_time_tolerance &&
        t_first < integrator->time() - settings.event_time_tolerance)
      {
        ++restarts;
        integrator->end_step_at(t_first, t_start, y_start);
        at_root = integrator->time() >= t_first - settings.event_time_tolerance;
        std::vector<ForceElement *> now;
        std::vector<double>         now_roots;
        if (at_root)
          for (std::size_t k = 0; k < triggered.size(); ++k)
            if (roots[k] <= t_first + settings.event_time_tolerance)
              {
                now.push_back(triggered[k]);
                now_roots.push_back(integrator->time());
              }
        triggered.swap(now);
        roots.swap(now_roots);
      }
  }

  bool
  Simulation::switch_modes(const std::vector<ForceElement *> &triggered, const std::vector<double> &roots)
  {
    // The impact velocity is read from the state at the root.
    const unsigned int n = mechanism.n_coordinates();
    for (std::size_t k = 0; k < triggered.size(); ++k)
      {
        integrator->dense_output(roots[k], scratch.data());
        event_state = scratch;
        triggered[k]->on_event(roots[k], StateView(event_state.data(), event_state.data() + n), !triggered[k]->mode());
        ++events;
      }
    return !triggered.empty();
  }

  void
  Simulation::held_forces_here(double t, const Eigen::VectorXd &y)
  {
    const unsigned int n = mechanism.n_coordinates();
    if (mechanism.held_forces_at(y.data(), y.data() + n))
      return;
    hold_accelerations.resize(n);
    PowerTerms unused;
    mechanism.accelerations(t, y.data(), y.data() + n, hold_accelerations.data(), unused);
  }

  void
  Simulation::locate_hold_release(const double                       t_start,
                                  const Eigen::VectorXd             &y_start,
                                  const std::vector<ForceElement *> &elements)
  {
    if (std::none_of(elements.begin(), elements.end(), [](const ForceElement *e) { return e->holds_contact(); }))
      return;
    auto released = [&](const double t, const Eigen::VectorXd &y) {
      held_forces_here(t, y);
      return std::any_of(elements.begin(), elements.end(), [](const ForceElement *e) {
        return e->holds_contact() && !(e->held_force() > 0);
      });
    };
    if (!released(integrator->time(), integrator->state()))
      return;
    // The held force fell to zero inside the step: end the step there (bisection on the
    // dense output, each trial one right-hand side), so that no held contact pulls.
    double lo = integrator->previous_time(), hi = integrator->time();
    for (int it = 0; it < 60 && hi - lo > settings.event_time_tolerance; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        integrator->dense_output(mid, scratch.data());
        hold_state                            = scratch;
        (released(mid, hold_state) ? hi : lo) = mid;
      }
    if (hi < integrator->time() - settings.event_time_tolerance && hi > t_start + settings.event_time_tolerance)
      {
        ++restarts;
        integrator->reset(t_start, y_start);
        integrator->step(hi);
      }
  }

  bool
  Simulation::update_holds(const std::vector<ForceElement *> &elements)
  {
    const unsigned int     n = mechanism.n_coordinates();
    const Eigen::VectorXd &y = integrator->state();
    const double          *a = integrator->derivative().data() + n;
    // A held element reads its force at this point: the last evaluation may have been
    // elsewhere (a stiffness probe), so evaluate here.
    if (std::any_of(elements.begin(), elements.end(), [](const ForceElement *e) { return e->holds_contact(); }) &&
        !mechanism.held_forces_at(y.data(), y.data() + n))
      {
        held_forces_here(integrator->time(), y);
        a = hold_accelerations.data();
      }
    const StateView s(y.data(), y.data() + n);
    bool            changed = false;
    for (auto *e : elements)
      changed = e->update_hold(integrator->time(), s, a) || changed;
    hold_switches += changed ? 1 : 0;
    return changed;
  }
} // namespace wearlink::mbs
