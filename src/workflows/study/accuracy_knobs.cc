// SPDX-License-Identifier: LGPL-2.1-or-later
// The accuracy study's knobs (accuracy_study.h): their catalogue, the study file that
// selects and re-values them, and the knobs that apply to a scene.
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/configured_pressure_models.h"
#include "io/scene.h"
#include "workflows/study/accuracy_detail.h"
#include "workflows/study/accuracy_study.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace wearlink::workflows
{
  namespace accuracy_detail
  {
    /** The value of entry "Section/Sub/Entry" of the scene's parameters. */
    std::string
    entry_of(const io::Scene &scene, const std::string &path)
    {
      return entry_value(*scene.parameters, path);
    }

    /** @p base, then the settings of value @p v of knob @p k. */
    ParameterOverrides
    with_knob_value(const ParameterOverrides &base, const Knob &k, const std::vector<std::string> &v)
    {
      ParameterOverrides o = base;
      for (std::size_t p = 0; p < k.targets.size(); ++p)
        for (const auto &t : k.targets[p])
          o.set(t, v[p]);
      return o;
    }
  } // namespace accuracy_detail

  using namespace accuracy_detail;

  namespace
  {
    // ------------------------------------------------------------------------------
    // Small helpers.

    double
    number_of(const io::Scene &scene, const std::string &path)
    {
      return std::stod(entry_of(scene, path));
    }

    /** A knob value as a user would type it: 1e-05, 0.0025, 250. */
    std::string
    label(double v)
    {
      std::ostringstream os;
      os << std::setprecision(4) << v;
      return os.str();
    }

    /** Every knob wearlink knows, in the order the study runs them. */
    const std::vector<std::pair<std::string, std::string>> &
    catalogue()
    {
      static const std::vector<std::pair<std::string, std::string>> c = {
        {"integrator-tolerance", "dopri5 Relative tolerance (Position tolerance = 1e-3 m × it, Velocity = it m/s)"},
        {"integrator-method",
         "Integrator/Method dopri5 | dopri5-stiff | dop853 at the scene's tolerances, against dopri5 at a tenth of "
         "them"},
        {"integrator-step", "rk4 Time step"},
        {"event-point",
         "Integrator/Event point: a step crossing an event cut on dopri5's continuous extension against "
         "integrated to it"},
        {"baumgarte", "Baumgarte alpha = beta"},
        {"contact-law", "Normal force law of every clearance joint"},
        {"persistent-contact", "Persistent contact of every clearance joint: held (a constraint) against compliant"},
        {"discrete-areas", "Number of discrete areas of every wearing joint's profiles"},
        {"load-sampling", "Wear/Pressure evaluation and Load samples per cycle"},
        {"wear-step",
         "wear step: iterations × extrapolation factor at fixed revolutions (adaptive: Maximum "
         "depth increment)"},
        {"simulated-cycles",
         "Wear/Cycles per iteration × Extrapolation factor at fixed revolutions (how much of "
         "the chaotic load history is sampled)"},
        {"wear-update", "Wear/Wear update: simultaneous (the seed's route) against sequential"},
        {"wear-scheme", "Wear/Wear integration: adams-bashforth (second order) against euler (first order)"},
        {"smoothing", "Wear/Smoothing wavelength of the depth increments' low-pass filter, against none"},
        {"pressure-model", "Pressure model of every wearing joint"},
        {"fe-element-size", "fe Surface element size"},
        {"fe-degree", "fe Element degree"},
        {"remesh-depth", "fe Remesh depth: profile drift kept on one mesh, in surface element sizes"},
        {"fe-law-table",
         "fe law's conformal table of worn profiles: directions of the pin's displacement tabulated (Table bore "
         "directions)"},
        {"conformal-cells", "Wear/Conformal cells per area of the conformal foundation of worn profiles"},
        {"clearance-model", "Wear/Clearance model: the point contact at the deepest overlap against the conformal one"},
      };
      return c;
    }

    std::string
    description_of(const std::string &name)
    {
      for (const auto &[n, d] : catalogue())
        if (n == name)
          return d;
      return "";
    }

    /** A knob whose single part is written to @p targets. */
    Knob
    make_knob(const std::string              &name,
              const std::vector<std::string> &targets,
              const std::vector<std::string> &values,
              const std::string              &reference)
    {
      Knob k;
      k.name        = name;
      k.description = description_of(name);
      k.targets     = {targets};
      for (const auto &v : values)
        k.values.push_back({v});
      k.reference = reference;
      return k;
    }

    std::vector<std::string>
    paths(const std::vector<std::string> &joints, const std::string &tail)
    {
      std::vector<std::string> p;
      for (const auto &j : joints)
        p.push_back("Joint " + j + "/Clearance/" + tail);
      return p;
    }
  } // namespace

  // --------------------------------------------------------------------------------
  // Knobs.

  std::vector<std::string>
  known_knob_names()
  {
    std::vector<std::string> n;
    for (const auto &[name, d] : catalogue())
      n.push_back(name);
    return n;
  }

  std::string
  study_file_help()
  {
    return R"(A study file is a deal.II parameter file with one subsection:
  subsection Accuracy study
    set Knobs = integrator-tolerance, wear-step   # which knobs; empty: all that apply
    subsection wear-step
      set Values = 2;2500, 5;1000, 10;500          # coarse -> fine; the last is the reference
    end
  end
A value has one part per setting of the knob, separated by ';' (see accuracy.md's
'value' column for the parts of each knob). Knobs: )" +
           join(known_knob_names(), ", ") + ".\n";
  }

  void
  read_study_file(const std::string &file, StudyRequest &request)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Accuracy study");
    prm.declare_entry("Knobs",
                      "",
                      dealii::Patterns::Anything(),
                      "Knobs to vary, comma-separated; empty: every knob that applies to the scene.");
    for (const auto &name : known_knob_names())
      {
        prm.enter_subsection(name);
        prm.declare_entry("Values",
                          "",
                          dealii::Patterns::Anything(),
                          "Values of the knob, comma-separated, coarse to fine (the last is the "
                          "reference); the parts of one value are separated by ';'. Empty: built-in.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
    try
      {
        read_prm_file(prm, file, false);
      }
    catch (const InputError &e)
      {
        std::string m  = e.message();
        const auto  at = m.find("scene file");
        if (at != std::string::npos)
          m.replace(at, 10, "study file");
        throw InputError(m +
                         "\nA study file has one subsection 'Accuracy study' with 'Knobs' and one "
                         "subsection per knob; the knobs are " +
                         join(known_knob_names(), ", ") + ".");
      }
    prm.enter_subsection("Accuracy study");
    const auto known = known_knob_names();
    for (const auto &k : split(prm.get("Knobs"), ','))
      {
        if (k.empty())
          continue;
        if (std::find(known.begin(), known.end(), k) == known.end())
          throw InputError("In " + file + ", 'Accuracy study/Knobs' names '" + k +
                           "', which is not a knob; the knobs are " + join(known, ", ") + ".");
        request.knobs.push_back(k);
      }
    for (const auto &name : known)
      {
        prm.enter_subsection(name);
        const std::string v = prm.get("Values");
        prm.leave_subsection();
        if (!v.empty())
          request.values[name] = split(v, ',');
      }
    prm.leave_subsection();
  }

  namespace
  {
    /** What the knobs of a scene are built from. */
    struct KnobContext
    {
      const io::Scene         &scene;
      bool                     quick = false;
      std::vector<std::string> clearance, wearing, fe; ///< joint names
      std::vector<std::string> fe_law;                 ///< joints on the fe normal force law
      /** Scale factors, coarse -> fine, around the scene's value (×1 is the scene's). */
      std::vector<double> coarsen;

      /** The scene's value @p base times each factor, without repeats. */
      std::vector<std::string>
      scaled(const double base, const bool integer) const
      {
        std::vector<std::string> v;
        for (const double f : coarsen)
          {
            const double      x = base * f;
            const std::string s = integer ? std::to_string(std::max(1L, std::lround(x))) : label(x);
            if (std::find(v.begin(), v.end(), s) == v.end())
              v.push_back(s);
          }
        return v;
      }
    };

    /**
     * The embedded pairs at the scene's tolerance @p rel; the reference is dopri5 at a
     * tenth of it (the integrator-tolerance knob's tightest run, so measured once).
     */
    Knob
    method_knob(const double rel)
    {
      Knob k;
      k.name        = "integrator-method";
      k.description = description_of(k.name);
      k.targets     = {{"Integrator/Method"},
                       {"Integrator/Relative tolerance"},
                       {"Integrator/Position tolerance"},
                       {"Integrator/Velocity tolerance"}};
      for (const auto &[method, f] : std::vector<std::pair<std::string, double>>{{"dop853", 1},
                                                                                 {"dopri5-stiff", 1},
                                                                                 {"dopri5", 1},
                                                                                 {"dopri5", 0.1}})
        k.values.push_back({method, label(rel * f), label(rel * f * 1e-3), label(rel * f)});
      k.reference = "dopri5 at a tenth of the tolerances";
      return k;
    }

    /** The integrator's tolerance (dopri5) or step (rk4), and the Baumgarte factors. */
    void
    integrator_knobs(const KnobContext &c, std::vector<Knob> &knobs)
    {
      const auto &scene = c.scene;
      const bool  quick = c.quick;
      // Integrator: tolerance (dopri5) or step (rk4).
      const auto &in = scene.simulation.integrator;
      if (in.type != mbs::IntegratorType::rk4)
        {
          Knob k;
          k.name           = "integrator-tolerance";
          k.description    = description_of("integrator-tolerance");
          k.targets        = {{"Integrator/Relative tolerance"},
                              {"Integrator/Position tolerance"},
                              {"Integrator/Velocity tolerance"}};
          const double rel = in.relative_tolerance;
          for (const double f : quick ? std::vector<double>{100, 10, 1} : std::vector<double>{100, 10, 1, 0.1})
            {
              const double r = rel * f;
              k.values.push_back({label(r), label(r * 1e-3), label(r)});
            }
          k.reference = "tightest tolerance";
          knobs.push_back(k);
          if (!quick)
            knobs.push_back(method_knob(rel));
          // Events cut on dopri5's continuous extension against integrated to (not in --quick).
          if (!quick && (in.type == mbs::IntegratorType::dopri5 || in.type == mbs::IntegratorType::dopri5_stiff))
            knobs.push_back(make_knob("event-point",
                                      {"Integrator/Event point"},
                                      {"interpolated", "integrated"},
                                      "each event's step integrated"));
        }
      else
        knobs.push_back(
          make_knob("integrator-step", {"Integrator/Time step"}, c.scaled(in.time_step, false), "smallest step"));

      // Baumgarte factors: no "finer" value; the scene's is the reference.
      if (!quick)
        {
          Knob k;
          k.name         = "baumgarte";
          k.description  = "Baumgarte alpha = beta";
          k.targets      = {{"Integrator/Baumgarte alpha"}, {"Integrator/Baumgarte beta"}};
          const double a = number_of(scene, "Integrator/Baumgarte alpha");
          const double b = number_of(scene, "Integrator/Baumgarte beta");
          k.values       = {{label(a / 2), label(b / 2)}, {label(a * 2), label(b * 2)}, {label(a), label(b)}};
          k.reference    = "the scene's factors";
          knobs.push_back(k);
        }
    }

    /** The contact law of every clearance joint; the scene's (first joint's) law last. */
    void
    contact_law_knob(const KnobContext &c, std::vector<Knob> &knobs)
    {
      const auto &scene     = c.scene;
      const auto &clearance = c.clearance;
      // Contact law of every clearance joint; the scene's (first joint's) law last.
      if (!clearance.empty())
        {
          const std::string law = entry_of(scene, "Joint " + clearance[0] + "/Clearance/Normal force law");
          std::string       e   = "";
          for (const char *section : {"lankarani-nikravesh", "flores"})
            if (law == section)
              e = entry_of(scene, "Joint " + clearance[0] + "/Clearance/" + law + "/Restitution coefficient");
          Knob k;
          k.name        = "contact-law";
          k.description = "Normal force law of every clearance joint";
          k.targets     = {paths(clearance, "Normal force law")};
          if (!e.empty())
            {
              auto t = paths(clearance, "lankarani-nikravesh/Restitution coefficient");
              auto f = paths(clearance, "flores/Restitution coefficient");
              t.insert(t.end(), f.begin(), f.end());
              k.targets.push_back(t);
            }
          for (const char *l : {"hertz", "flores", "lankarani-nikravesh"})
            if (law != l)
              k.values.push_back(e.empty() ? std::vector<std::string>{l} : std::vector<std::string>{l, e});
          k.values.push_back(e.empty() ? std::vector<std::string>{law} : std::vector<std::string>{law, e});
          k.reference = "the scene's law";
          knobs.push_back(k);
        }
    }

    /**
     * The pressure model of every wearing joint, fe the reference. A scene that evaluates
     * every step without fe gets every model on sampled load states (50 per cycle) and fe
     * with 0.2 mm surface elements re-meshing beyond 2 of them: fe at every integrator
     * step of the nine-bar's 100 cycles takes hours, with the default 25 µm elements
     * re-meshing after every update 7 minutes and beyond 2 elements still 5 (the worn
     * meshes' compliance columns); 0.2 mm was within 3 % in worn volume of 0.1 mm in the
     * FE knobs' study (doc/tutorials/accuracy_study.md). What the sampling costs is the load-sampling row (with
     * hertz-strip), what the element size costs the fe-element-size knob of an fe scene.
     */
    Knob
    pressure_model_knob(const KnobContext &c)
    {
      const auto &wearing = c.wearing;
      // Every registered model the scene gives the parameters of; the last, fe (the FE
      // layer registers last), is the reference.
      const auto models = io::configured_pressure_models(c.scene, wearing);
      if (!c.fe.empty() || c.scene.wear_loop.evaluation != wear::PressureEvaluation::every_step)
        return make_knob("pressure-model", paths(wearing, "Pressure model"), models, models.back());
      Knob k;
      k.name        = "pressure-model";
      k.description = description_of(k.name);
      k.targets     = {paths(wearing, "Pressure model"),
                       {"Wear/Pressure evaluation"},
                       {"Wear/Load samples per cycle"},
                       paths(wearing, "fe/Remesh depth"),
                       paths(wearing, "fe/Surface element size")};
      for (const auto &model : models)
        k.values.push_back({model, "samples per cycle", "50", "2", "2e-4"});
      k.reference = models.back() + " at 0.2 mm elements re-meshing beyond 2 elements; every model on 50 load samples "
                                    "per cycle";
      return k;
    }

    /** Pressure evaluation at every step or N times per cycle (fe: only sampled). */
    Knob
    load_sampling_knob(const KnobContext &c)
    {
      Knob k;
      k.name        = "load-sampling";
      k.description = description_of("load-sampling");
      k.targets     = {{"Wear/Pressure evaluation"}, {"Wear/Load samples per cycle"}};
      if (c.fe.empty())
        {
          for (const int s : {25, 100})
            k.values.push_back({"samples per cycle", std::to_string(s)});
          k.values.push_back({"every step", std::to_string(c.scene.wear_loop.samples_per_cycle)});
          k.reference = "every step";
        }
      else // the fe model at every loaded step is what samples per cycle avoids
        {
          for (const int s : {25, 50, 100, 200})
            k.values.push_back({"samples per cycle", std::to_string(s)});
          k.reference = "200 samples per cycle";
        }
      return k;
    }

    /** The same revolutions in more, smaller steps (fixed extrapolation), or smaller depth increments (adaptive). */
    Knob
    wear_step_knob(const KnobContext &c)
    {
      const auto &ws = c.scene.wear_loop;
      if (ws.extrapolation != wear::Extrapolation::fixed)
        return make_knob("wear-step",
                         {"Wear/Maximum depth increment"},
                         c.scaled(ws.max_depth_increment, false),
                         "smallest depth increment");
      Knob k;
      k.name                  = "wear-step";
      k.description           = description_of("wear-step");
      k.targets               = {{"Wear/Number of iterations"}, {"Wear/Extrapolation factor"}};
      const double      total = ws.n_iterations * ws.extrapolation_factor;
      std::vector<long> counts;
      for (const double f : c.quick ? std::vector<double>{0.5, 1, 2} : std::vector<double>{0.2, 0.5, 1, 2})
        {
          const long n = std::max(1L, std::lround(ws.n_iterations * f));
          if (std::find(counts.begin(), counts.end(), n) == counts.end())
            counts.push_back(n);
        }
      for (const long n : counts)
        k.values.push_back({std::to_string(n), label(total / n)});
      k.reference = "most iterations";
      return k;
    }

    /** The same revolutions from more simulated cycles per iteration (fixed extrapolation). */
    Knob
    simulated_cycles_knob(const KnobContext &c)
    {
      const auto &ws = c.scene.wear_loop;
      Knob        k;
      k.name                     = "simulated-cycles";
      k.description              = description_of("simulated-cycles");
      k.targets                  = {{"Wear/Cycles per iteration"}, {"Wear/Extrapolation factor"}};
      const double per_iteration = ws.cycles_per_iteration * ws.extrapolation_factor;
      // The reference samples twice the scene's cycles (4× cost 4 times the scene's run
      // and stayed at the chaos floor in the study's 15 minutes).
      for (const double f : {0.5, 1.0, 2.0})
        {
          const double n = ws.cycles_per_iteration * f;
          k.values.push_back({label(n), label(per_iteration / n)});
        }
      k.reference = "most simulated cycles";
      return k;
    }

    /**
     * Discrete areas, load sampling, wear step, simulated cycles; and unless quick, the
     * wear update, the smoothing filter and the pressure model.
     */
    void
    wear_knobs(const KnobContext &c, std::vector<Knob> &knobs)
    {
      const auto &wearing = c.wearing;
      if (wearing.empty())
        return;
      const auto              &ws = c.scene.wear_loop;
      const double             n  = number_of(c.scene, "Joint " + wearing[0] + "/Clearance/Number of discrete areas");
      std::vector<std::string> areas;
      for (const double f : c.quick ? std::vector<double>{0.25, 0.5, 1} : std::vector<double>{0.25, 0.5, 1, 2})
        areas.push_back(std::to_string(std::max(8L, std::lround(n * f))));
      knobs.push_back(make_knob("discrete-areas", paths(wearing, "Number of discrete areas"), areas, "most areas"));
      knobs.push_back(load_sampling_knob(c));
      knobs.push_back(wear_step_knob(c));
      if (ws.extrapolation == wear::Extrapolation::fixed)
        knobs.push_back(simulated_cycles_knob(c));
      if (c.quick)
        return;
      knobs.push_back(make_knob("wear-update", {"Wear/Wear update"}, {"simultaneous", "sequential"}, "sequential"));
      knobs.push_back(make_knob("wear-scheme", {"Wear/Wear integration"}, {"adams-bashforth", "euler"}, "euler"));
      const double w = ws.smoothing_wavelength > 0 ? ws.smoothing_wavelength : 1e-3;
      knobs.push_back(
        make_knob("smoothing", {"Wear/Smoothing wavelength"}, {label(2 * w), label(w), "0"}, "no filter"));
      knobs.push_back(pressure_model_knob(c));
      knobs.push_back(
        make_knob("conformal-cells", {"Wear/Conformal cells per area"}, {"1", "2", "4", "8"}, "most cells"));
      knobs.push_back(
        make_knob("clearance-model", {"Wear/Clearance model"}, {"deepest-point", "conformal"}, "conformal"));
    }

    /**
     * FE element size and degree, re-mesh depth (joints with the fe pressure model); the
     * directions of the fe law's conformal tables of worn profiles.
     */
    void
    fe_knobs(const KnobContext &c, std::vector<Knob> &knobs)
    {
      const auto &scene = c.scene;
      const auto &fe    = c.fe;
      if (!fe.empty())
        {
          knobs.push_back(
            make_knob("fe-element-size",
                      paths(fe, "fe/Surface element size"),
                      c.scaled(number_of(scene, "Joint " + fe[0] + "/Clearance/fe/Surface element size"), false),
                      "smallest elements"));
          knobs.push_back(make_knob("fe-degree", paths(fe, "fe/Element degree"), {"1", "2"}, "degree 2"));
          knobs.push_back(
            make_knob("remesh-depth", paths(fe, "fe/Remesh depth"), {"2", "0.5", "0"}, "re-mesh at every update"));
        }
      if (!c.fe_law.empty() && !c.wearing.empty()) // worn profiles: the direction grid of the law's table
        {
          Knob k;
          k.name        = "fe-law-table";
          k.description = description_of(k.name);
          k.targets     = {paths(c.fe_law, "fe/Table bore directions")};
          for (const char *n : {"24", "48", "96"})
            k.values.push_back({n});
          k.reference = "most directions";
          knobs.push_back(k);
        }
    }
  } // namespace

  std::vector<Knob>
  knobs_for(const io::Scene &scene, bool quick)
  {
    KnobContext c{scene, quick, {}, {}, {}, {}, {}};
    for (const auto *j : scene.clearance_joints)
      {
        c.clearance.push_back(j->name());
        if (entry_of(scene, "Joint " + j->name() + "/Clearance/Normal force law") == "fe")
          c.fe_law.push_back(j->name());
      }
    for (const auto &w : scene.wear)
      {
        c.wearing.push_back(w->joint);
        if (w->pressure_model == "fe")
          c.fe.push_back(w->joint);
      }
    c.coarsen = quick ? std::vector<double>{4, 2, 1} : std::vector<double>{4, 2, 1, 0.5};
    std::vector<Knob> knobs;
    integrator_knobs(c, knobs);
    contact_law_knob(c, knobs);
    // Held persistent contact against the compliant law (doc/models.md §1.6); not in --quick.
    if (!c.clearance.empty() && !c.quick)
      knobs.push_back(make_knob("persistent-contact",
                                paths(c.clearance, "Persistent contact"),
                                {"held", "compliant"},
                                "every contact by its law"));
    wear_knobs(c, knobs);
    fe_knobs(c, knobs);
    return knobs;
  }
} // namespace wearlink::workflows
