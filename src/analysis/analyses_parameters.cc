// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/analyses_parameters.h"

#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink::analysis
{
  namespace
  {
    namespace P                      = dealii::Patterns;
    const char *const analysis_names = "phase-portrait|poincare|lyapunov";
  } // namespace

  namespace
  {
    /** Which analyses, of which joints and bodies, sampled how. */
    void
    declare_general_entries(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "List of analyses",
              "",
              P::MultipleSelection(analysis_names),
              "Nonlinear-dynamics analyses of this run (none by default; an analysis not "
              "listed is not built and records nothing). phase-portrait: journal-centre "
              "motion of each analysed clearance joint relative to its bushing (e_x vs de_x/dt, "
              "e_y vs de_y/dt), PNG + CSV; poincare: one point per driving period from the "
              "integrator's dense output at the exact section time, CSV + PNG + spread in "
              "summary.json; lyapunov: largest Lyapunov exponent of the journal-centre "
              "coordinates (subsection Lyapunov), in 1/s with natural log.",
              "none");
      declare(prm,
              "Joints",
              "",
              P::List(P::Anything()),
              "Clearance joints analysed; empty: every clearance joint of the scene.",
              "none");
      declare(prm,
              "Bodies",
              "",
              P::List(P::Anything()),
              "Bodies whose centre-of-mass motion (x, y, angle) is analysed as well; empty: "
              "none.",
              "none");
      declare(prm,
              "Driving period",
              "0",
              P::Double(0),
              "Period T of the driving: one Poincaré point per T. 0: 2π/|ω| of the angle "
              "drivers, which must then all turn at the same rate.",
              "s");
      declare(prm,
              "Section phase",
              "0",
              P::Double(0),
              "Poincaré sections are taken at Start time + Section phase + k T (k = 0, 1, ...); "
              "must be smaller than T.",
              "s");
      declare(prm,
              "Transient",
              "0",
              P::Double(0),
              "Nothing is recorded for the analyses before Start time + Transient (let the "
              "initial transient die out).",
              "s");
      declare(prm,
              "Sample interval",
              "1e-3",
              P::Double(0),
              "Sampling interval of the phase-portrait and Lyapunov series (dense output).",
              "s");
    }

    /** `Analyses/Lyapunov`: methods, directions, embedding. */
    void
    declare_lyapunov_entries(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Lyapunov");
      declare(prm,
              "Methods",
              "wolf, rosenstein",
              P::MultipleSelection("wolf|rosenstein|two-trajectory"),
              "Estimators of the largest Lyapunov exponent: wolf (Wolf et al. 1985, fixed "
              "evolution time, the seed's method) and rosenstein (Rosenstein et al. 1993) from "
              "the journal-centre series; two-trajectory (Benettin et al. 1980) from the "
              "simulation itself: a shadow copy of the scene a small distance away, "
              "renormalized every Renormalization interval (doubles the simulation cost). "
              "Only used if List of analyses has lyapunov.",
              "none");
      declare(prm,
              "Two-trajectory separation",
              "1e-6",
              P::Double(0),
              "two-trajectory: distance d0 of the shadow from the reference (positions, and "
              "velocities times T/2π); far above the integration tolerance, far below the "
              "clearance.",
              "m");
      declare(prm,
              "Renormalization interval",
              "0.02",
              P::Double(0),
              "two-trajectory: the shadow is put back at distance d0 this often.",
              "s");
      declare(prm,
              "Directions",
              "x",
              P::MultipleSelection("x|y"),
              "Coordinates analysed (global axes): of each analysed joint's journal centre "
              "relative to its bushing, and of each analysed body's centre of mass. x is the "
              "seed's choice (Figs 11–12).",
              "none");
      declare(
        prm,
        "Delay",
        "0",
        P::Integer(0, 100000),
        "Delay of the embedding in samples (at most 1e5; a series has at most 1e7 samples); 0: from the average mutual information "
        "(its first minimum; a map-like series: 1; a flow that decorrelates without a "
        "minimum: the first delay with I <= I(0)/e).",
        "samples");
      declare(prm,
              "Embedding dimension",
              "0",
              P::Integer(0, 64),
              "Embedding dimension; 0: false nearest neighbours (first dimension with < 1 % "
              "false).",
              "none");
      prm.leave_subsection();
    }

    /** `Analyses/Before-after wear`: the comparison of a wear scene. */
    void
    declare_before_after_entries(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Before-after wear");
      declare(prm,
              "Delay",
              "0.005",
              P::Double(0),
              "Wear scenes with analyses run the dynamics once with the fresh and once with the "
              "worn profiles (Start time to End time) and compare them. Their exponents are "
              "computed at ONE embedding: this delay for both runs (0: the before-wear run's "
              "mutual-information choice). On clearance-joint series the exponent falls "
              "roughly like 1/delay, so exponents at different delays are not comparable. "
              "The default 5 ms is about the automatic choice before wear at 1 ms sampling "
              "on the nine-bar.",
              "s");
      declare(prm,
              "Embedding dimension",
              "0",
              P::Integer(0, 64),
              "Common embedding dimension; 0: false nearest neighbours on the before-wear run.",
              "none");
      declare(prm,
              "Delay scan",
              "0.002, 0.005, 0.01, 0.02, 0.05",
              P::List(P::Double(0)),
              "The comparison is repeated at these delays (same dimension) to show whether "
              "after > before holds at every scale; delays below the sample interval are "
              "skipped; empty: no scan.",
              "s");
      declare(prm,
              "Two-trajectory cycles",
              "10",
              P::Double(0),
              "If Lyapunov/Methods has two-trajectory: the exponent of the simulation itself "
              "is measured, before and after wear, in two separate runs of this many driving "
              "periods after Transient (the worn one reads the worn profiles back from the "
              "output directory), at the tolerance below. The main before/after runs do not "
              "carry the shadow trajectory.",
              "driving periods");
      declare(prm,
              "Two-trajectory tolerance",
              "1e-11",
              P::Double(0),
              "Relative tolerance of the two-trajectory runs; the scene's position and "
              "velocity tolerances are scaled by the same factor. The shadow's separation d0 "
              "(Lyapunov/Two-trajectory separation) must stay far above the integration "
              "error: on the nine-bar the scene's 1e-6 gives 285–1380 1/s for d0 = 1e-6 … "
              "1e-9 m (noise), 1e-11 gives 100–145 1/s before and 346–362 1/s after wear.",
              "none");
      declare(prm,
              "Published exponents",
              "",
              P::Anything(),
              "Published exponents printed next to ours, 'CHANNEL: BEFORE AFTER, ...' (e.g. "
              "the seed's 'A_ex_m: 0.041 0.076, B_ex_m: 0.030 0.052'); empty: none.",
              "as published");
      declare(prm,
              "Published note",
              "",
              P::Anything(),
              "Where the published exponents come from and in which units (printed with them).",
              "none");
      prm.leave_subsection();
    }
  } // namespace

  void
  declare_analyses(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Analyses");
    declare_general_entries(prm);
    declare_lyapunov_entries(prm);
    declare_before_after_entries(prm);
    prm.leave_subsection();
  }

  namespace
  {
    /** `Analyses/Lyapunov` into @p s (reader inside that subsection). */
    void
    parse_lyapunov(ParameterReader &r, AnalysesSettings &s)
    {
      for (const auto &m : r.get_list("Methods"))
        if (m == "two-trajectory")
          s.two_trajectory = true;
        else if (const auto method = parse_method(m))
          s.methods.push_back(*method);
      s.two_trajectory_separation = r.get_double("Two-trajectory separation");
      s.renormalization_interval  = r.get_double("Renormalization interval");
      if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_separation > 0.0))
        r.fail("Two-trajectory separation", "it must be > 0 m");
      if (s.lyapunov && s.two_trajectory && !(s.renormalization_interval > 0.0))
        r.fail("Renormalization interval", "it must be > 0 s");
      s.directions = r.get_list("Directions");
      if (s.lyapunov && s.methods.empty() && !s.two_trajectory)
        r.fail("Methods", "at least one of wolf, rosenstein, two-trajectory is needed when lyapunov is listed");
      if (s.lyapunov && s.directions.empty())
        r.fail("Directions", "at least one of x, y is needed when lyapunov is listed");
      if (const long d = r.get_integer("Delay"); d > 0)
        s.delay = static_cast<std::size_t>(d);
      if (const long m = r.get_integer("Embedding dimension"); m > 0)
        s.dimension = static_cast<unsigned int>(m);
    }

    /** `Analyses/Before-after wear` into @p s (reader inside that subsection). */
    void
    parse_before_after(ParameterReader &r, AnalysesSettings &s)
    {
      s.comparison_delay     = r.get_double("Delay");
      s.comparison_dimension = static_cast<unsigned int>(r.get_integer("Embedding dimension"));
      for (const auto &v : r.get_list("Delay scan"))
        s.delay_scan.push_back(std::stod(v));
      s.two_trajectory_cycles    = r.get_double("Two-trajectory cycles");
      s.two_trajectory_tolerance = r.get_double("Two-trajectory tolerance");
      if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_cycles > 0.0))
        r.fail("Two-trajectory cycles", "it must be > 0 when Lyapunov/Methods has two-trajectory");
      if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_tolerance > 0.0))
        r.fail("Two-trajectory tolerance", "it must be > 0");
      s.published_exponents = r.get("Published exponents");
      s.published_note      = r.get("Published note");
      try
        {
          parse_published_exponents(s.published_exponents, "");
        }
      catch (const InputError &e)
        {
          r.fail("Published exponents", e.message());
        }
    }
  } // namespace

  namespace
  {
    /**
     * A run that lists lyapunov records (End time − Start time − Transient) / Sample
     * interval samples of each channel after the transient; fewer than the methods can
     * ever use is refused before the run (it would simulate, write the series and fail
     * only at the estimate).
     */
    void
    check_lyapunov_samples(const ParameterReader &r, const AnalysedScene &scene, const AnalysesSettings &s)
    {
      if (!s.lyapunov)
        return;
      const double span    = scene.end_time - scene.start_time - s.transient;
      const double samples = std::floor(span / s.sample_interval + 1e-9) + 1;
      if (samples < static_cast<double>(min_lyapunov_samples))
        r.fail("Sample interval",
               "the run records " + format_number(samples, 6) + " samples of each channel after the Transient ((" +
                 format_number(span, 6) + " s) / Sample interval + 1); the Lyapunov exponent needs at least " +
                 std::to_string(min_lyapunov_samples) + " (in practice thousands)",
               "Lengthen Simulation/End time, shorten Analyses/Sample interval or Transient, or remove lyapunov "
               "from 'List of analyses'.");
    }
  } // namespace

  AnalysesSettings
  read_analyses(dealii::ParameterHandler &prm, const AnalysedScene &scene)
  {
    AnalysesSettings s;
    ParameterReader  r(prm, scene.file);
    r.enter("Analyses");
    for (const auto &name : r.get_list("List of analyses"))
      {
        if (name == "phase-portrait")
          s.phase_portrait = true;
        else if (name == "poincare")
          s.poincare = true;
        else if (name == "lyapunov")
          s.lyapunov = true;
        else
          r.fail("List of analyses", "valid analyses are " + std::string(analysis_names));
      }

    const auto &clearance = scene.clearance_joints;
    s.joints              = r.get_list("Joints");
    if (s.joints.empty())
      s.joints = clearance;
    for (const auto &j : s.joints)
      if (std::find(clearance.begin(), clearance.end(), j) == clearance.end())
        {
          std::string list;
          for (const auto &c : clearance)
            list += (list.empty() ? "" : ", ") + c;
          r.fail("Joints",
                 "'" + j + "' is not a clearance joint of this scene; the clearance joints are: " +
                   (list.empty() ? std::string("none") : list),
                 "Journal-centre motion exists only for joints with Model = clearance; analyse an "
                 "ideal mechanism through 'Bodies'.");
        }
    s.bodies = r.get_list("Bodies");
    for (const auto &b : s.bodies)
      if (std::find(scene.bodies.begin(), scene.bodies.end(), b) == scene.bodies.end())
        r.fail("Bodies", "'" + b + "' is not a body of this scene (ground cannot be analysed)");

    s.given_driving_period = r.get_double("Driving period");
    s.section_phase        = r.get_double("Section phase");
    s.transient            = r.get_double("Transient");
    s.sample_interval      = r.get_double("Sample interval");
    if ((s.phase_portrait || s.lyapunov) && !(s.sample_interval > 0.0))
      r.fail("Sample interval", "it must be > 0 s when phase-portrait or lyapunov is listed");
    // The analysed series is kept in memory (a few dozen channels of doubles per sample).
    const double samples = (scene.end_time - scene.start_time) / s.sample_interval;
    if ((s.phase_portrait || s.lyapunov) && samples > 1e7)
      r.fail("Sample interval",
             "it would record " + format_number(samples, 3) + " samples over the run; at most 1e7 fit in memory",
             "Choose a longer interval or a shorter run.");
    if (!(scene.start_time + s.transient < scene.end_time))
      r.fail("Transient",
             "it must end before the run does (End time − Start time = " +
               format_number(scene.end_time - scene.start_time) + " s)");
    check_lyapunov_samples(r, scene, s);

    r.enter("Lyapunov");
    parse_lyapunov(r, s);
    r.leave();
    r.enter("Before-after wear");
    parse_before_after(r, s);
    r.leave();
    r.leave();
    if (s.lyapunov && !s.methods.empty() && s.joints.empty() && s.bodies.empty())
      throw InputError("In " + scene.file +
                       ", 'Analyses/List of analyses' has lyapunov but there is nothing to "
                       "analyse: the scene has no clearance joints and 'Analyses/Bodies' is empty.");
    return s;
  }

  std::vector<PublishedExponents>
  parse_published_exponents(const std::string &text, const std::string &where)
  {
    std::vector<PublishedExponents> out;
    for (const auto &item : dealii::Utilities::split_string_list(text, ','))
      {
        if (item.empty())
          continue;
        const auto         colon = item.find(':');
        std::istringstream values(colon == std::string::npos ? std::string() : item.substr(colon + 1));
        PublishedExponents p;
        p.channel = dealii::Utilities::trim(item.substr(0, colon));
        std::string rest;
        if (colon == std::string::npos || p.channel.empty() || !(values >> p.before >> p.after) || (values >> rest) ||
            !std::isfinite(p.before) || !std::isfinite(p.after))
          {
            const std::string what = "'" + item +
                                     "' is not 'CHANNEL: BEFORE AFTER' (two numbers, e.g. "
                                     "'A_ex_m: 0.041 0.076')";
            throw InputError(where.empty() ? what : where + ": " + what + ".");
          }
        out.push_back(p);
      }
    return out;
  }

} // namespace wearlink::analysis
