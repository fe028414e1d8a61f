// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_loop.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/numbers.h"
#include "base/text.h"
#include "wear/depth_measures.h"
#include "wear/wear_step.h"

#include <algorithm>
#include <cmath>

namespace wearlink::wear
{
  namespace
  {
    double
    max_of(const std::vector<double> &v)
    {
      return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    }
  } // namespace

  // Periodic Gaussian of standard deviation σ = λ √(2 ln 2) / (2π) (transfer
  // exp(−q²σ²/2) = 1/2 at q = 2π/λ), in samples of spacing 2πR/n, truncated at 4σ and
  // renormalized: a circular convolution whose weights sum to 1, which keeps Σ h_k.
  std::vector<double>
  low_pass(const std::vector<double> &values, const double wavelength, const double radius)
  {
    const auto n = static_cast<long>(values.size());
    if (!(wavelength > 0) || !(radius > 0) || n < 3)
      return values;
    const double sigma = wavelength * std::sqrt(2 * std::log(2.0)) / (2 * numbers::pi) / (2 * numbers::pi * radius / n);
    const long   half  = std::min<long>(n / 2, static_cast<long>(std::ceil(4 * sigma)));
    if (half < 1)
      return values;
    std::vector<double> w(2 * half + 1);
    double              sum = 0;
    for (long d = -half; d <= half; ++d)
      sum += w[d + half] = std::exp(-0.5 * d * d / (sigma * sigma));
    std::vector<double> out(n, 0.0);
    for (long k = 0; k < n; ++k)
      for (long d = -half; d <= half; ++d)
        out[k] += w[d + half] / sum * values[((k + d) % n + n) % n];
    return out;
  }

  // low_pass at the mean radius, then scaled so that Σ h_k R_k (the volume over L Δψ) is
  // the unfiltered one: the radii of a worn profile differ from one area to the next.
  std::vector<double>
  smoothed(const std::vector<double> &depth, const double wavelength, const std::vector<double> &radii)
  {
    const auto n = depth.size();
    if (!(wavelength > 0) || n < 3 || radii.size() != n)
      return depth;
    double mean_radius = 0;
    for (const double r : radii)
      mean_radius += r / n;
    auto   out    = low_pass(depth, wavelength, mean_radius);
    double before = 0, after = 0;
    for (std::size_t k = 0; k < n; ++k)
      {
        before += depth[k] * radii[k];
        after += out[k] * radii[k];
      }
    if (after > 0)
      for (auto &h : out)
        h *= before / after;
    return out;
  }

  WearLoop::WearLoop(const WearLoopSettings                &settings,
                     std::vector<WearingJoint>              wearing,
                     std::vector<contact::ClearanceJoint *> clearance_joints,
                     const double                           cycle_period,
                     AdvanceDynamics                        advance)
    : settings(settings)
    , wearing(std::move(wearing))
    , clearance_joints(std::move(clearance_joints))
    , period(cycle_period)
    , advance(std::move(advance))
  {
  }

  void
  WearLoop::start(const double                              t0,
                  const Eigen::VectorXd                    &q0,
                  const Eigen::VectorXd                    &v0,
                  const std::string                        &fingerprint,
                  const std::map<std::string, std::string> &scene)
  {
    const auto n   = q0.size();
    st             = WearState();
    st.fingerprint = fingerprint;
    st.scene       = scene;
    own_timings    = PhaseTimings();
    earlier_total  = 0;
    process_time.restart();
    st.time                = t0;
    st.state               = Eigen::VectorXd::Zero(2 * n + mbs::MechanismOde::n_quadratures);
    st.state.head(n)       = q0;
    st.state.segment(n, n) = v0;
    st.modes.assign(2 * clearance_joints.size(), 0.0);
    for (const auto &w : wearing)
      {
        JointWearState js;
        js.name         = w.joint->name();
        js.initial_bore = js.bore = js.meshed_bore = w.joint->get_description().geometry.bore;
        js.initial_pin = js.pin = js.meshed_pin = w.joint->get_description().geometry.pin;
        st.joints.push_back(std::move(js));
      }
    update_clearance_model();
    settle();
  }

  void
  WearLoop::resume(WearState state, const std::string &where)
  {
    bool match = state.joints.size() == wearing.size() && state.modes.size() == 2 * clearance_joints.size();
    for (unsigned int i = 0; match && i < wearing.size(); ++i)
      {
        const auto &g = wearing[i].joint->get_description().geometry;
        match         = state.joints[i].name == wearing[i].joint->name() &&
                state.joints[i].bore.n_points() == g.bore.n_points() &&
                state.joints[i].pin.n_points() == g.pin.n_points();
      }
    if (!match)
      throw InputError("Cannot resume from '" + where + "': its joints do not match the scene's wearing joints.");
    st                = std::move(state);
    own_timings       = st.timings;
    earlier_total     = st.timings.total;
    own_timings.total = 0;
    process_time.restart();
    EffectLedger::instance().restore(st.ledger);
    if (warnings)
      warnings->merge(st.warnings);
    // A pressure model that keeps its mesh across small updates (fe, 'Remesh depth')
    // meshes the geometry it had meshed before, then takes the current profiles.
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        const auto &js = st.joints[i];
        wearing[i].joint->set_profiles(js.bore, js.pin);
        auto &model = *wearing[i].wear->model;
        if (auto *hooks = model.fe_hooks())
          hooks->restore_geometry(geometry(i, js.meshed_bore, js.meshed_pin), geometry(i, js.bore, js.pin));
        else
          model.update_geometry(geometry(i, js.bore, js.pin));
      }
  }

  bool
  WearLoop::finished() const
  {
    const bool target_reached =
      settings.extrapolation == Extrapolation::adaptive && st.revolutions >= settings.target_revolutions * (1 - 1e-12);
    return st.iterations_done >= settings.n_iterations || target_reached;
  }

  void
  WearLoop::iterate(const std::vector<mbs::StepObserver *> &extra_observers)
  {
    throw_if_interrupted();
    const double t_start    = st.time;
    const auto   loads      = record_loads(extra_observers, t_start + settings.cycles_per_iteration * period);
    const double planned    = planned_factor(*loads, t_start);
    auto         increments = archard_increments(*loads, t_start, planned);
    Stopwatch    bookkeeping;
    double       factor = extrapolation_factor(increments);
    auto         rates  = own_rates(increments, *loads);
    if (factor_limit)
      factor = std::max(0.0, std::min(factor, factor_limit(preview(rates, factor))));
    if (settings.update == WearUpdate::sequential && factor < planned * (1 - 1e-9))
      { // the wear took its path at the planned factor
        increments = archard_increments(*loads, t_start, factor);
        rates      = own_rates(increments, *loads);
      }
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        update_profiles(i, applied_rate(i, rates[i], factor), *loads, factor);
        st.joints[i].last_rate = rates[i];
      }
    st.factors.push_back(factor);
    st.revolutions += factor * settings.cycles_per_iteration;
    store_contact_modes();
    ++st.iterations_done;
    own_timings.wear_bookkeeping += bookkeeping.seconds();
    update_clearance_model(true);
  }

  std::unique_ptr<LoadRecorder>
  WearLoop::record_loads(const std::vector<mbs::StepObserver *> &extra_observers, const double t_end)
  {
    restore_contact_modes();
    Eigen::VectorXd y0 = st.state;
    y0.tail(mbs::MechanismOde::n_quadratures).setZero();
    std::vector<const contact::ClearanceJoint *> recorded;
    for (const auto &w : wearing)
      recorded.push_back(w.joint);
    auto      loads = std::make_unique<LoadRecorder>(recorded);
    Stopwatch dynamics;
    st.state = advance(st.time, t_end, y0, loads.get(), extra_observers);
    st.time  = t_end;
    loads->finish();
    own_timings.dynamics += dynamics.seconds();
    return loads;
  }

  double
  WearLoop::planned_factor(const LoadRecorder &loads, const double t_start)
  {
    if (settings.update != WearUpdate::sequential)
      return 0;
    if (settings.extrapolation != Extrapolation::adaptive)
      return settings.extrapolation_factor;
    const double remaining = (settings.target_revolutions - st.revolutions) / settings.cycles_per_iteration;
    if (!st.factors.empty() && st.factors.back() > 0)
      return std::min(st.factors.back(), remaining);
    return extrapolation_factor(archard_increments(loads, t_start, 0)); // the first: as a simultaneous step says
  }

  std::vector<std::unique_ptr<ArchardAccumulator>>
  WearLoop::archard_increments(const LoadRecorder &loads, const double t_start, const double sequential_factor)
  {
    std::vector<std::unique_ptr<ArchardAccumulator>> increments;
    peaks.assign(wearing.size(), contact::ContactLoad());
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        for (const auto &s : loads.samples(i))
          if (s.load.normal_force > peaks[i].normal_force)
            peaks[i] = s.load;
        set_contact_width(i);
        const auto &w = *wearing[i].wear;
        if (const int twin = twin_of(i, loads); twin >= 0)
          {
            increments.push_back(std::make_unique<ArchardAccumulator>(*increments[twin]));
            if (warnings) // the twin's model saw the loads
              wearing[twin].wear->model->check_validity(wearing[i].joint->name(), *warnings);
            continue;
          }
        const auto g = geometry(i, st.joints[i].bore, st.joints[i].pin);
        Stopwatch  evaluation;
        if (sequential_factor > 0) // the surfaces of the iteration's start (a second pass meets worn ones)
          w.model->update_geometry(g);
        increments.push_back(
          std::make_unique<ArchardAccumulator>(g, w.archard.bushing_coefficient, w.archard.pin_coefficient, *w.model));
        increments[i]->set_sequential_factor(sequential_factor);
        increments[i]->add_history(loads.samples(i),
                                   settings.evaluation == PressureEvaluation::every_step,
                                   period / settings.samples_per_cycle,
                                   t_start);
        own_timings.pressure_evaluation += evaluation.seconds();
        if (warnings)
          w.model->check_validity(wearing[i].joint->name(), *warnings);
      }
    return increments;
  }

  int
  WearLoop::twin_of(const unsigned int i, const LoadRecorder &loads) const
  {
    const auto &slice = wearing[i].joint->get_description().slice;
    const auto &w     = *wearing[i].wear;
    if (slice.count <= 1 || w.model->fe_hooks() != nullptr)
      return -1;
    const auto &js = st.joints[i];
    for (unsigned int j = 0; j < i; ++j)
      {
        const auto &other = *wearing[j].wear;
        if (wearing[j].joint->get_description().slice.joint != slice.joint ||
            other.pressure_model != w.pressure_model || other.archard.pin_coefficient != w.archard.pin_coefficient ||
            other.archard.bushing_coefficient != w.archard.bushing_coefficient)
          continue;
        const auto &ks = st.joints[j];
        if (ks.bore.samples() == js.bore.samples() && ks.pin.samples() == js.pin.samples() &&
            identical_histories(loads.samples(j), loads.samples(i)))
          return static_cast<int>(j);
      }
    return -1;
  }

  double
  WearLoop::extrapolation_factor(const std::vector<std::unique_ptr<ArchardAccumulator>> &increments) const
  {
    if (settings.extrapolation != Extrapolation::adaptive)
      return settings.extrapolation_factor;
    double max_depth = 0;
    for (const auto &a : increments)
      max_depth = std::max({max_depth, max_of(a->pin_depth()), max_of(a->bore_depth())});
    const double factor =
      max_depth > 0 ? std::min(settings.max_factor, settings.max_depth_increment / max_depth) : settings.max_factor;
    return std::min(factor, (settings.target_revolutions - st.revolutions) / settings.cycles_per_iteration);
  }

  std::vector<WearRate>
  WearLoop::own_rates(const std::vector<std::unique_ptr<ArchardAccumulator>> &increments,
                      const LoadRecorder                                     &loads) const
  {
    std::vector<WearRate> rates(wearing.size());
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        const auto &js         = st.joints[i];
        const auto &a          = *increments[i];
        auto       &r          = rates[i];
        r.depth_pin            = smoothed(a.pin_depth(), settings.smoothing_wavelength, js.pin.samples());
        r.depth_bore           = smoothed(a.bore_depth(), settings.smoothing_wavelength, js.bore.samples());
        r.volume_pin           = a.pin_volume;
        r.volume_bore          = a.bore_volume;
        r.archard_pin          = a.pin_archard;
        r.archard_bore         = a.bore_archard;
        r.sliding_distance     = a.sliding_distance;
        r.relative_revolutions = loads.relative_revolutions(i);
      }
    return rates;
  }

  WearRate
  WearLoop::applied_rate(const unsigned int i, const WearRate &own, const double factor) const
  {
    const auto  &js       = st.joints[i];
    const double previous = st.factors.empty() ? 0.0 : st.factors.back();
    return step_rate(own,
                     js.last_rate,
                     factor,
                     previous,
                     settings.step,
                     {js.contact_width, js.initial_pin.mean_radius(), js.initial_bore.mean_radius()});
  }

  StepPreview
  WearLoop::preview(const std::vector<WearRate> &rates, const double factor) const
  {
    StepPreview p;
    p.revolutions = st.revolutions;
    p.cycles      = settings.cycles_per_iteration;
    p.factor      = factor;
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        const auto           &js = st.joints[i];
        StepPreview::Joint    j;
        const IterationRecord r = js.history.empty() ? IterationRecord() : js.history.back();
        j.state                 = &js;
        j.depth_pin             = r.depth_pin.empty() ? std::vector<double>(js.pin.n_points(), 0.0) : r.depth_pin;
        j.depth_bore            = r.depth_bore.empty() ? std::vector<double>(js.bore.n_points(), 0.0) : r.depth_bore;
        j.volume_pin            = r.volume_pin;
        j.volume_bore           = r.volume_bore;
        const WearRate applied  = applied_rate(i, rates[i], factor); // ω at the loop's own factor
        j.pin_increment         = applied.depth_pin;
        j.bore_increment        = applied.depth_bore;
        j.pin_volume_increment  = applied.volume_pin;
        j.bore_volume_increment = applied.volume_bore;
        p.joints.push_back(std::move(j));
      }
    return p;
  }

  void
  WearLoop::update_profiles(const unsigned int i, const WearRate &rate, const LoadRecorder &loads, const double factor)
  {
    auto &js   = st.joints[i];
    auto  bore = js.bore.samples();
    auto  pin  = js.pin.samples();
    for (unsigned int k = 0; k < bore.size(); ++k)
      bore[k] += factor * rate.depth_bore[k];
    for (unsigned int k = 0; k < pin.size(); ++k)
      pin[k] -= factor * rate.depth_pin[k];
    const bool worn_through = std::any_of(pin.begin(), pin.end(), [](const double r) { return !(r > 0); });
    if (worn_through)
      throw NumericalError("Wear iteration " + std::to_string(st.iterations_done + 1) + ": the pin of joint " +
                           js.name + " is worn through (a radius ≤ 0). Reduce the extrapolation.");
    js.bore           = Profile::from_samples(bore, "worn bore of joint " + js.name);
    js.pin            = Profile::from_samples(pin, "worn pin of joint " + js.name);
    IterationRecord r = js.history.empty() ? IterationRecord() : js.history.back();
    r.volume_pin += factor * rate.volume_pin;
    r.volume_bore += factor * rate.volume_bore;
    r.archard_pin += factor * rate.archard_pin;
    r.archard_bore += factor * rate.archard_bore;
    r.sliding_distance += factor * rate.sliding_distance;
    r.relative_revolutions += factor * rate.relative_revolutions;
    double impulse = 0;
    for (const auto &s : loads.samples(i))
      impulse += s.load.normal_force * s.weight;
    r.mean_normal_force = impulse / (settings.cycles_per_iteration * period);
    r.depth_pin.resize(pin.size());
    r.depth_bore.resize(bore.size());
    for (unsigned int k = 0; k < pin.size(); ++k)
      r.depth_pin[k] = js.initial_pin[k] - js.pin[k];
    for (unsigned int k = 0; k < bore.size(); ++k)
      r.depth_bore[k] = js.bore[k] - js.initial_bore[k];
    r.max_depth_pin  = max_of(r.depth_pin);
    r.max_depth_bore = max_of(r.depth_bore);
    depth_measures(i, r);
    js.history.push_back(std::move(r));
  }

  void
  WearLoop::set_contact_width(const unsigned int i)
  {
    auto &js = st.joints[i];
    if (js.contact_width > 0 || !(peaks[i].normal_force > 0))
      return;
    const auto &g    = wearing[i].joint->get_description().geometry;
    js.contact_width = hertz_contact_width(peaks[i].normal_force,
                                           js.initial_bore.mean_radius(),
                                           js.initial_pin.mean_radius(),
                                           contact::effective_modulus(g.bushing, g.pin_material),
                                           g.axial_length);
  }

  // The envelope depths and the roughness of the cumulative depths.
  void
  WearLoop::depth_measures(const unsigned int i, IterationRecord &r) const
  {
    const auto        &js     = st.joints[i];
    const unsigned int w_pin  = window_areas(js.contact_width, js.initial_pin.mean_radius(), js.pin.n_points());
    const unsigned int w_bore = window_areas(js.contact_width, js.initial_bore.mean_radius(), js.bore.n_points());
    r.envelope_depth_pin      = envelope_depth(r.depth_pin, w_pin);
    r.envelope_depth_bore     = envelope_depth(r.depth_bore, w_bore);
    r.roughness_pin           = roughness(r.depth_pin, w_pin);
    r.roughness_bore          = roughness(r.depth_bore, w_bore);
  }

  void
  check_roughness(const WearState &state, ValidityWarnings &warnings)
  {
    for (const auto &js : state.joints)
      {
        if (js.history.empty())
          continue;
        const auto &r = js.history.back();
        for (const auto &[surface, value] : {std::pair<std::string, double>{"pin", r.roughness_pin},
                                             std::pair<std::string, double>{"bore", r.roughness_bore}})
          warnings.check({"joint " + js.name + ": roughness of the worn " + surface,
                          100 * value,
                          100 * roughness_limit,
                          "%",
                          "the largest deviation of the depth from its local parabola over the contact width (" +
                            format_number(js.contact_width * 1e3, 3) + " mm), relative to the largest depth",
                          "the worn profile is not resolved at its discrete areas (steps or a saw-tooth between "
                          "neighbouring areas), and its largest depth is not a result; use Wear/Wear update = "
                          "sequential, more discrete areas or a smaller extrapolation factor"});
      }
  }

  /** What a wearing joint in contact carried before its profiles changed (bushing frame). */
  struct CarriedContact
  {
    bool      active = false;
    mbs::Vec2 eccentricity{0, 0}, force{0, 0};
    mbs::Vec2 offset{0, 0}; ///< the joint's bore offset (a slice's; contact/axial_slices.h)
    double    relative_angle = 0, direction = 0, bore_radius = 0, pin_radius = 0;
  };

  namespace
  {
    mbs::StateView
    view_of(const Eigen::VectorXd &y)
    {
      const auto n = (y.size() - mbs::MechanismOde::n_quadratures) / 2;
      return mbs::StateView(y.data(), y.data() + n);
    }

    /** Pin centre − bore centre of @p j at @p s, global [m]. */
    mbs::Vec2
    eccentricity_of(const contact::ClearanceJoint &j, const mbs::StateView &s)
    {
      const auto &d = j.get_description();
      return s.point(d.pin_body, d.pin_point) - s.point(d.bushing_body, d.bushing_point);
    }

    CarriedContact
    carried_contact(const contact::ClearanceJoint &j, const mbs::StateView &s)
    {
      CarriedContact c;
      if (!j.mode())
        return c;
      const auto  &d   = j.get_description();
      const double tb  = s.angle(d.bushing_body);
      c.eccentricity   = s.to_local(d.bushing_body, eccentricity_of(j, s));
      c.relative_angle = s.angle(d.pin_body) - tb;
      c.force          = j.elastic_force(c.eccentricity, c.relative_angle);
      if (!(c.force.norm() > 0))
        return c;
      c.active      = true;
      c.offset      = d.slice.bore_offset;
      c.direction   = std::atan2(-c.force.y(), -c.force.x());
      c.bore_radius = d.geometry.bore.radius(c.direction);
      c.pin_radius  = d.geometry.pin.radius(c.direction - c.relative_angle);
      return c;
    }

    /** Per clearance joint, the time mean and the peak of F_n and the contact onsets over a run. */
    class StartUpRecorder : public mbs::StepObserver
    {
    public:
      explicit StartUpRecorder(std::vector<const contact::ClearanceJoint *> joints)
        : joints(std::move(joints))
        , mean(this->joints.size(), 0.0)
        , peak(this->joints.size(), 0.0)
        , last(this->joints.size(), 0.0)
        , onsets(this->joints.size(), 0)
      {
        for (std::size_t k = 0; k < this->joints.size(); ++k)
          onsets[k] = this->joints[k]->n_impacts();
      }
      void
      on_start(const mbs::StepContext &c) override
      {
        t0 = t_last = c.t;
        sample(c.y, 0);
      }
      void
      on_step(const mbs::StepContext &c) override
      {
        sample(c.y, c.t - t_last);
        t_last = c.t;
      }
      /** Fill the settling part of @p start_up of joint @p k. */
      void
      result(std::size_t k, StartUp &start_up) const
      {
        start_up.impacts           = static_cast<double>(joints[k]->n_impacts() - onsets[k]);
        start_up.mean_normal_force = t_last > t0 ? mean[k] / (t_last - t0) : 0.0;
        start_up.peak_normal_force = peak[k];
      }

    private:
      void
      sample(const Eigen::VectorXd &y, const double dt)
      {
        const auto s = view_of(y);
        for (std::size_t k = 0; k < joints.size(); ++k)
          {
            const double f = joints[k]->diagnostics(s).normal_force;
            mean[k] += 0.5 * (f + last[k]) * dt; // trapezoidal in time
            peak[k] = std::max(peak[k], f);
            last[k] = f;
          }
      }
      std::vector<const contact::ClearanceJoint *> joints;
      std::vector<double>                          mean, peak, last;
      std::vector<long>                            onsets;
      double                                       t0 = 0, t_last = 0;
    };
  } // namespace

  void
  WearLoop::settle()
  {
    st.settling_cycles = settings.settling_cycles;
    if (!(settings.settling_cycles > 0))
      return;
    std::vector<const contact::ClearanceJoint *> joints;
    for (const auto &w : wearing)
      joints.push_back(w.joint);
    StartUpRecorder recorder(joints);
    restore_contact_modes();
    Eigen::VectorXd y0 = st.state;
    y0.tail(mbs::MechanismOde::n_quadratures).setZero();
    const Stopwatch dynamics;
    const double    t_end = st.time + settings.settling_cycles * period;
    st.state              = advance(st.time, t_end, y0, nullptr, {&recorder});
    st.time               = t_end;
    own_timings.dynamics += dynamics.seconds();
    store_contact_modes();
    for (std::size_t i = 0; i < wearing.size(); ++i)
      recorder.result(i, st.joints[i].start_up);
  }

  void
  WearLoop::update_clearance_model(const bool carry)
  {
    const bool                  carrying = carry && carry_state;
    std::vector<CarriedContact> carried(wearing.size());
    if (carrying)
      for (unsigned int i = 0; i < wearing.size(); ++i)
        carried[i] = carried_contact(*wearing[i].joint, view_of(st.state));
    for (unsigned int i = 0; i < wearing.size(); ++i)
      {
        auto &js = st.joints[i];
        wearing[i].joint->set_profiles(js.bore, js.pin);
        auto     &model = *wearing[i].wear->model;
        Stopwatch update;
        model.update_geometry(geometry(i, js.bore, js.pin));
        const auto *hooks = model.fe_hooks();
        if (!hooks) // the fe model times its own phases
          own_timings.pressure_evaluation += update.seconds();
        const auto *meshed = hooks ? hooks->meshed_geometry() : nullptr;
        js.meshed_bore     = meshed ? meshed->bore : js.bore;
        js.meshed_pin      = meshed ? meshed->pin : js.pin;
      }
    if (carrying)
      carry_contacts(carried);
  }

  namespace
  {
    /** The wearing joints by the joint they cut: a sliced joint's slices together, in order. */
    std::vector<std::vector<unsigned int>>
    joint_groups(const std::vector<WearingJoint> &wearing)
    {
      std::vector<std::vector<unsigned int>> groups;
      std::map<std::string, std::size_t>     where;
      for (unsigned int i = 0; i < wearing.size(); ++i)
        {
          const auto &d   = wearing[i].joint->get_description();
          const auto  key = d.slice.count > 1 ? d.slice.joint : d.name;
          const auto  it  = where.emplace(key, groups.size()).first;
          if (it->second == groups.size())
            groups.emplace_back();
          groups[it->second].push_back(i);
        }
      return groups;
    }
  } // namespace

  void
  WearLoop::carry_contacts(const std::vector<CarriedContact> &carried)
  {
    const auto             s = view_of(st.state);
    std::vector<mbs::Vec2> targets;
    for (const auto *j : clearance_joints)
      targets.push_back(eccentricity_of(*j, s));
    bool moved = false;
    for (const auto &group : joint_groups(wearing))
      {
        // The joint's carried force (a sliced joint's: the sum over its slices), and the
        // slice that carried most of it.
        mbs::Vec2                                    force(0, 0);
        const CarriedContact                        *most = nullptr;
        std::vector<const contact::ClearanceJoint *> slices;
        for (const auto i : group)
          {
            slices.push_back(wearing[i].joint);
            const auto &c = carried[i];
            if (!c.active)
              continue;
            force += c.force;
            if (most == nullptr || c.force.norm() > most->force.norm())
              most = &c;
          }
        if (most == nullptr)
          continue;
        // Start from the old position moved by the depth worn at the contact on both
        // surfaces (of the slice that carried most).
        const auto  &first = wearing[group.front()].joint->get_description();
        const auto  &g     = wearing[static_cast<std::size_t>(most - carried.data())].joint->get_description().geometry;
        const double worn  = (g.bore.radius(most->direction) - most->bore_radius) +
                            (most->pin_radius - g.pin.radius(most->direction - most->relative_angle));
        const mbs::Vec2 old_first = most->eccentricity + most->offset - first.slice.bore_offset;
        const mbs::Vec2 start     = old_first + worn * mbs::Vec2(std::cos(most->direction), std::sin(most->direction));
        bool            converged = false;
        const mbs::Vec2 e = contact::eccentricity_carrying(slices, force, most->relative_angle, start, converged);
        auto           &u = st.joints[group.front()].start_up;
        u.carries += 1;
        u.carry_failures += converged ? 0 : 1;
        u.largest_carry = std::max(u.largest_carry, (e - old_first).norm());
        for (const auto i : group)
          {
            const auto &d = wearing[i].joint->get_description();
            const auto  k = static_cast<std::size_t>(
              std::find(clearance_joints.begin(), clearance_joints.end(), wearing[i].joint) - clearance_joints.begin());
            targets[k] = s.to_global(d.bushing_body, e + first.slice.bore_offset - d.slice.bore_offset);
          }
        moved = true;
      }
    if (moved)
      carry_state(st.time, st.state, targets);
  }

  void
  WearLoop::commit()
  {
    const Stopwatch bookkeeping;
    EffectLedger::instance().add_calls("wear iterations", 1);
    st.ledger        = EffectLedger::instance().snapshot();
    st.timings       = timings();
    st.timings.total = earlier_total + process_time.seconds();
    if (warnings)
      st.warnings = *warnings;
    if (!checkpoint_path.empty())
      st.write(checkpoint_path);
    own_timings.wear_bookkeeping += bookkeeping.seconds();
  }

  void
  WearLoop::restore_contact_modes()
  {
    for (unsigned int k = 0; k < clearance_joints.size(); ++k)
      clearance_joints[k]->set_mode(st.modes[2 * k] != 0, st.modes[2 * k + 1], st.modes[2 * k] == 2);
  }

  void
  WearLoop::store_contact_modes()
  {
    for (unsigned int k = 0; k < clearance_joints.size(); ++k)
      {
        // 0 free, 1 in contact, 2 in contact and held (Persistent contact = held).
        st.modes[2 * k]     = clearance_joints[k]->holds_contact() ? 2 : (clearance_joints[k]->mode() ? 1 : 0);
        st.modes[2 * k + 1] = clearance_joints[k]->impact_velocity();
      }
  }

  contact::JointGeometry
  WearLoop::geometry(const unsigned int i, const Profile &bore, const Profile &pin) const
  {
    auto g = wearing[i].joint->get_description().geometry;
    g.bore = bore;
    g.pin  = pin;
    return g;
  }

  PhaseTimings
  WearLoop::timings() const
  {
    PhaseTimings t = own_timings;
    for (const auto &w : wearing)
      if (const auto *hooks = w.wear->model->fe_hooks())
        t += hooks->timings();
    for (const auto *j : clearance_joints)
      t += j->normal_force_law().timings();
    return t;
  }
} // namespace wearlink::wear
