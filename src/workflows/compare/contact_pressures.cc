// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/contact_pressures.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "base/timings.h"
#include "io/configured_pressure_models.h"
#include "io/output_names.h"
#include "io/plot.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::nan;
    using numbers::pi;
    using numbers::two_pi;

    /** @p x [N] to three significant digits. */
    double
    three_digits(const double x)
    {
      const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2);
      return std::round(x / unit) * unit;
    }

    /** A load as it appears in column names: whole newtons from 100 N on. */
    std::string
    load_label(const double load)
    {
      return load >= 100 ? std::to_string(std::llround(load)) : format_number(load, 3);
    }

    /** Angle @p a − @p b wrapped to [−π, π] [rad]. */
    double
    angle_from(const double a, const double b)
    {
      return std::remainder(a - b, two_pi);
    }

    /**
     * The load state of @p load [N] pushing the pin into the bore at ψ0 = j.direction:
     * bushing at rest in the global frame, the pin turned so that its angle
     * j.pin_direction faces the contact, the pin centre where the rigid profiles touch.
     */
    contact::ContactLoad
    load_state(const PressureJoint &j, const contact::JointGeometry &g, const double load)
    {
      const double         psi = j.direction;
      const double         c   = g.bore.radius(psi) - g.pin.radius(j.pin_direction);
      contact::ContactLoad l;
      l.bushing_angle = 0;
      l.pin_angle     = psi - j.pin_direction;
      l.contact_angle = psi;
      l.normal_force  = load;
      l.force         = {{-load * std::cos(psi), -load * std::sin(psi)}};
      l.eccentricity  = {{c * std::cos(psi), c * std::sin(psi)}};
      return l;
    }

    /** α_c of the area pressures @p p on @p bore about ψ0 (see the header) [rad]. */
    double
    half_angle(const std::vector<double> &p, const Profile &bore, const double direction)
    {
      double force = 0, first = 0, second = 0;
      for (unsigned int k = 0; k < bore.n_points(); ++k)
        {
          const double w = p[k] * bore[k]; // ∝ p_k A_k, A_k = L R_k Δψ
          const double x = angle_from(bore.angle(k), direction);
          force += w;
          first += w * x;
          second += w * x * x;
        }
      if (!(force > 0))
        return 0;
      const double mean = first / force, width = two_pi / bore.n_points();
      return 2 * std::sqrt(std::max(second / force - mean * mean - width * width / 12, 0.0));
    }

    /** Periodic area values @p p on @p n areas (linear interpolation if the count differs). */
    std::vector<double>
    on_areas(const std::vector<double> &p, const std::size_t n)
    {
      if (p.size() == n)
        return p;
      std::vector<double> out(n);
      const std::size_t   m = p.size();
      for (std::size_t i = 0; i < n; ++i)
        {
          const double      s = double(i) * m / n;
          const std::size_t k = static_cast<std::size_t>(s);
          out[i]              = (1 - (s - k)) * p[k % m] + (s - k) * p[(k + 1) % m];
        }
      return out;
    }

    /** Pressure model @p name with joint @p joint's parameters (its Clearance section). */
    std::unique_ptr<contact::PressureModel>
    make_model(io::Scene &scene, const std::string &joint, const std::string &name)
    {
      ParameterReader r(*scene.parameters, scene.file);
      r.enter("Joint " + joint);
      r.enter("Clearance");
      auto model = contact::pressure_models().create(name, r, "Pressure model");
      r.leave();
      r.leave(); // the handler is shared: leave it where it was
      return model;
    }

    /** The curves of joint @p j, model @p name in one state, at each of its loads. */
    void
    add_curves(PressureDistributions  &d,
               const PressureJoint    &j,
               contact::PressureModel &model,
               const std::string      &name,
               const bool              worn)
    {
      const auto &g = worn ? j.worn : j.fresh;
      model.update_geometry(g);
      contact::SurfacePressure out;
      for (const double load : j.loads)
        {
          PressureCurve c;
          c.joint      = j.name;
          c.model      = name;
          c.state      = worn ? "worn" : "fresh";
          c.load       = load;
          c.direction  = j.direction;
          c.area_width = two_pi / g.bore.n_points();
          try
            {
              model.evaluate(load_state(j, g, load), out);
            }
          catch (const NumericalError &e)
            {
              // One failed solve leaves its curve empty (NaN, "failed" in the table), not the comparison.
              c.failure = e.what();
              std::cerr << "\nwarning: joint " << j.name << ", " << name << " (" << c.state << ") at " << load
                        << " N: " << c.failure << '\n';
              c.peak = c.half_angle = nan;
              c.pressure.assign(d.bore_angle.size(), nan);
              d.curves.push_back(std::move(c));
              continue;
            }
          c.peak       = *std::max_element(out.bore.begin(), out.bore.end());
          c.half_angle = half_angle(out.bore, g.bore, j.direction);
          c.pressure   = on_areas(out.bore, d.bore_angle.size());
          d.curves.push_back(std::move(c));
        }
    }
  } // namespace

  std::vector<double>
  spanning_loads(const double mean, const double peak)
  {
    if (!(mean > 0) || !(peak > mean))
      return {};
    std::vector<double> loads;
    for (int k = 0; k < 4; ++k)
      loads.push_back(three_digits(mean * std::pow(peak / mean, k / 3.0)));
    return loads;
  }

  PressureDistributions
  contact_pressures(io::Scene &scene, const std::vector<PressureJoint> &joints, const bool progress)
  {
    PressureDistributions d;
    Profile               finest;
    for (const auto &j : joints)
      if (j.fresh.bore.n_points() > finest.n_points())
        finest = j.fresh.bore;
    for (unsigned int k = 0; k < finest.n_points(); ++k)
      d.bore_angle.push_back(finest.angle(k));
    // Every joint's models live to the end, so that equal joints share one FE model
    // (fe/model_pool.h) and the fresh models of all joints are made before the worn ones.
    std::vector<std::vector<std::pair<std::string, std::unique_ptr<contact::PressureModel>>>> models(joints.size());
    for (std::size_t i = 0; i < joints.size(); ++i)
      for (const auto &name : io::configured_pressure_models(scene, {joints[i].name}))
        models[i].emplace_back(name, make_model(scene, joints[i].name, name));
    for (const bool worn : {false, true})
      for (std::size_t i = 0; i < joints.size(); ++i)
        {
          if (worn && !joints[i].has_worn)
            continue;
          for (auto &[name, model] : models[i])
            {
              if (progress)
                std::cerr << "[wearlink] joint " << joints[i].name << ": pressure, " << name << " ("
                          << (worn ? "worn" : "fresh") << ") at " << format_number(joints[i].loads.front(), 4) << " … "
                          << format_number(joints[i].loads.back(), 4) << " N" << std::flush;
              const Stopwatch clock;
              add_curves(d, joints[i], *model, name, worn);
              if (progress)
                std::cerr << " in " << format_number(clock.seconds(), 3) << " s\n";
            }
        }
    return d;
  }

  namespace
  {
    /**
     * True if α_c of @p c is resolved: from 1.5 areas on (within 6 % for a Hertz strip;
     * below it the estimate is off by up to 25 %, see the header).
     */
    bool
    resolved(const PressureCurve &c)
    {
      return c.half_angle >= 1.5 * c.area_width;
    }

    /** α_c in degrees, or "<1.5 Δψ" (in degrees) where it is not resolved. */
    std::string
    half_angle_text(const PressureCurve &c)
    {
      return resolved(c) ? format_or_na(c.half_angle * 180 / pi, 3) :
                           "<" + format_or_na(1.5 * c.area_width * 180 / pi, 2);
    }

    /** The fe curve of @p c's joint, state and load (nullptr if there is none). */
    const PressureCurve *
    fe_curve_of(const std::vector<PressureCurve> &curves, const PressureCurve &c)
    {
      for (const auto &f : curves)
        if (f.model == "fe" && f.joint == c.joint && f.state == c.state && f.load == c.load)
          return &f;
      return nullptr;
    }
  } // namespace

  std::string
  PressureDistributions::table() const
  {
    std::ostringstream os;
    os
      << "Contact pressure on the bore at four loads: " << load_range << "\n"
      << "p_max: largest pressure of a discrete area; α_c: contact half-angle (2 × the angular standard deviation of "
         "the pressure, the area width's share removed; Hertz: b/R; \"<x\": below 1.5 areas, not resolved); /fe: ratio to "
         "the fe model.\n";
    os << std::left << std::setw(7) << "joint" << std::setw(7) << "state" << std::right << std::setw(9) << "load N"
       << "  " << std::left << std::setw(13) << "model" << std::right << std::setw(11) << "p_max MPa" << std::setw(8)
       << "/fe" << std::setw(11) << "α_c deg" << std::setw(8) << "/fe" << '\n';
    for (const auto &c : curves)
      {
        const PressureCurve *fe = fe_curve_of(curves, c);
        if (!c.failure.empty())
          {
            os << std::left << std::setw(7) << c.joint << std::setw(7) << c.state << std::right << std::setw(9)
               << load_label(c.load) << "  " << std::left << std::setw(13) << c.model << "failed: " << c.failure
               << '\n';
            continue;
          }
        os << std::left << std::setw(7) << c.joint << std::setw(7) << c.state << std::right << std::setw(9)
           << load_label(c.load) << "  " << std::left << std::setw(13) << c.model << std::right << std::setw(11)
           << format_or_na(c.peak * 1e-6, 4) << std::setw(8) << format_or_na(fe ? c.peak / fe->peak : nan, 3)
           << std::setw(10) << half_angle_text(c) << std::setw(8)
           << format_or_na(resolved(c) && fe && resolved(*fe) ? c.half_angle / fe->half_angle : nan, 3) << '\n';
      }
    return os.str();
  }

  namespace
  {
    /** One panel of pressure.png: joint @p joint in state @p state, near the contact. */
    io::PlotSpec
    pressure_panel(const PressureDistributions &d, const std::string &joint, const std::string &state)
    {
      io::PlotSpec spec;
      spec.title   = "joint " + joint + ", " + state + " profiles";
      spec.x_label = "bore angle ψ [deg] (bushing frame)";
      spec.y_label = "contact pressure p [MPa]";
      double span = 0, centre = 0;
      for (const auto &c : d.curves)
        if (c.joint == joint && c.state == state)
          {
            span   = std::max(span, 1.5 * c.half_angle + 2 * c.area_width);
            centre = c.direction;
          }
      std::vector<double>      loads;
      std::vector<std::string> others; // the models other than fe, in the order of their curves
      for (const auto &c : d.curves)
        {
          if (c.joint != joint || c.state != state)
            continue;
          auto colour = std::find(loads.begin(), loads.end(), c.load);
          if (colour == loads.end())
            colour = loads.insert(loads.end(), c.load);
          io::PlotSeries s;
          s.title     = c.model + ", " + load_label(c.load) + " N";
          s.look      = io::palette_line(static_cast<unsigned>(colour - loads.begin() + 1), c.model == "fe" ? 3 : 2);
          s.look.mark = io::Mark::steps;
          if (c.model != "fe") // the reference solid, the others dashed and dotted in turn
            {
              auto other = std::find(others.begin(), others.end(), c.model);
              if (other == others.end())
                other = others.insert(others.end(), c.model);
              if ((other - others.begin()) % 2 == 0)
                s.look.dashed();
              else
                s.look.dotted();
            }
          for (std::size_t k = 0; k < d.bore_angle.size(); ++k)
            {
              const double x = angle_from(d.bore_angle[k], centre);
              if (std::abs(x) <= span)
                {
                  s.x.push_back((centre + x) * 180 / pi);
                  s.y.push_back(c.pressure[k] * 1e-6);
                }
            }
          spec.series.push_back(std::move(s));
        }
      spec.x_range = io::Range{(centre - span) * 180 / pi, (centre + span) * 180 / pi};
      spec.y_range = io::Range{0, NAN};
      return spec;
    }
  } // namespace

  // pressure.csv: the first column bore_angle_rad (the centres ψ_k = 2πk/N of the bore's
  // discrete areas, bushing frame, of the joint with the most areas; the curves of a
  // joint with fewer areas are interpolated linearly onto them), then one column
  // pressure_Pa_<model>_<state>_<joint>_<load>N per curve: the contact pressure [Pa] on
  // area k for the model (every registered one the scene configures, in the registry's
  // order: hertz-strip, winkler, fe as shipped), the state (fresh, worn), the joint
  // and the load (whole newtons from 100 N on), in the order state, joint, model, load.
  // pressure.png: one panel per joint and state (columns: joints), the pressures within
  // 1.5 α_c + 2 areas of the contact direction, one colour per load, fe solid and the
  // other models dashed and dotted in turn.
  void
  write_contact_pressures(const std::string &dir, const PressureDistributions &d)
  {
    if (d.curves.empty())
      return;
    std::ostringstream csv;
    csv << std::setprecision(10) << "bore_angle_rad";
    for (const auto &c : d.curves)
      csv << ",pressure_Pa_" << c.model << '_' << c.state << '_' << c.joint << '_' << load_label(c.load) << 'N';
    csv << '\n';
    for (std::size_t k = 0; k < d.bore_angle.size(); ++k)
      {
        csv << d.bore_angle[k];
        for (const auto &c : d.curves)
          csv << ',' << c.pressure[k];
        csv << '\n';
      }
    write_file_atomically(dir + "/" + io::outputs::pressure_table, csv.str());
    std::vector<std::string> joints;
    bool                     worn = false;
    for (const auto &c : d.curves)
      {
        if (std::find(joints.begin(), joints.end(), c.joint) == joints.end())
          joints.push_back(c.joint);
        worn = worn || c.state == "worn";
      }
    std::vector<io::PlotSpec> panels;
    for (const char *state : {"fresh", "worn"})
      for (const auto &j : joints)
        if (state == std::string("fresh") || worn)
          panels.push_back(pressure_panel(d, j, state));
    const int columns = static_cast<int>(joints.size()), rows = static_cast<int>(panels.size()) / columns;
    io::plot_panels_png(panels,
                        static_cast<unsigned int>(columns),
                        "Contact pressure on the bore per discrete area at four loads: fe solid, the other "
                        "models dashed and dotted in turn (see the key); one colour per load",
                        dir + "/" + io::outputs::pressure_plot,
                        1000 * columns,
                        600 * rows);
  }
} // namespace wearlink::workflows
