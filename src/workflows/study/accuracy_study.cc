// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/study/accuracy_study.h"

#include "analysis/ensemble_statistics.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/scene.h"
#include "io/wear_outputs.h"
#include "wear/periodic_samples.h"
#include "workflows/ensemble/ensemble.h"
#include "workflows/run/run.h"
#include "workflows/study/accuracy_detail.h"
#include "workflows/study/accuracy_runs.h"
#include "workflows/wear/wear_run.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace wearlink::workflows
{
  FloorEnsemble
  floor_ensemble(const double members, const double seed, const double perturbation)
  {
    if (!(members == 0 || (members >= 2 && members <= 100)) || members != std::floor(members))
      throw InputError("--ensemble " + format_number(members) +
                       ": the chaos floor needs 2 … 100 members (0: no floor; default 4).");
    if (!(seed >= 0 && seed <= 9007199254740992.0 && seed == std::floor(seed)))
      throw InputError("--seed " + format_number(seed) + ": the seed must be a whole number from 0 to 2^53.");
    if (!(perturbation > 0 && perturbation <= 1e-3))
      throw InputError("--perturbation " + format_number(perturbation) +
                       ": the initial-angle perturbation must be > 0 and at most 1e-3 rad (default 1e-9 rad).");
    return {static_cast<unsigned int>(members), static_cast<std::uint64_t>(seed), perturbation};
  }

  using namespace accuracy_detail;

  namespace
  {
    using numbers::nan;

    /** The scene's effective parameters under @p overrides, as text: equal texts are equal runs. */
    std::string
    effective_parameters(const std::string &file, const ParameterOverrides &overrides)
    {
      const io::Scene    scene = io::read_scene(file, overrides);
      std::ostringstream os;
      scene.parameters->print_parameters(os, dealii::ParameterHandler::ShortText);
      return os.str();
    }

    double
    relative_error(double value, double reference)
    {
      if (!std::isfinite(value) || !std::isfinite(reference))
        return nan;
      if (reference == 0)
        return value == 0 ? 0.0 : nan;
      return std::abs(value - reference) / std::abs(reference);
    }

    /** Periodic moving average of @p h over @p window_deg degrees. */
    std::vector<double>
    smoothed(const std::vector<double> &h, double window_deg)
    {
      const long          n    = static_cast<long>(h.size());
      const long          half = std::lround(0.5 * window_deg / 360.0 * n);
      std::vector<double> out(h.size(), 0.0);
      for (long k = 0; k < n; ++k)
        {
          for (long j = -half; j <= half; ++j)
            out[k] += h[((k + j) % n + n) % n];
          out[k] /= 2 * half + 1;
        }
      return out;
    }

    /**
     * ‖h − h_ref‖/‖h_ref‖ on the reference's angles; with @p window_deg > 0 both are
     * first smoothed over that window (the shape without the impact-to-impact spikes).
     */
    double
    profile_difference(const std::vector<double> &h, const std::vector<double> &ref, double window_deg = 0)
    {
      if (h.empty() || ref.empty())
        return nan;
      std::vector<double> v = wear::periodic_resampled(h, ref.size()), r = ref;
      if (window_deg > 0)
        {
          v = smoothed(v, window_deg);
          r = smoothed(r, window_deg);
        }
      double d = 0, n = 0;
      for (std::size_t k = 0; k < r.size(); ++k)
        {
          d += (v[k] - r[k]) * (v[k] - r[k]);
          n += r[k] * r[k];
        }
      return n > 0 ? std::sqrt(d / n) : (d > 0 ? nan : 0.0);
    }

    /** Window of the "shape" comparison of worn profiles [deg]. */
    constexpr double shape_window_deg = 10;

    bool
    is_profile(const std::string &name)
    {
      return name.find(" profile_") != std::string::npos || name.find(" shape_") != std::string::npos;
    }

    /** The quantities "worst" is taken over: see the header. */
    bool
    counts_for_worst(const std::string &name, bool wears)
    {
      if (wears)
        return name.find(" V_") != std::string::npos || name.find(" shape_") != std::string::npos;
      return name.find(" F_peak") != std::string::npos || name == "a_peak";
    }

    /** Largest error among names containing @p tag (NaN if none is finite). */
    double
    max_error(const StudyRow &r, const std::string &tag)
    {
      double m = nan;
      for (const auto &[name, e] : r.errors)
        if (name.find(tag) != std::string::npos && std::isfinite(e))
          m = std::isfinite(m) ? std::max(m, e) : e;
      return m;
    }

    /** Largest of @p errors over the names containing @p tag (NaN if none is finite). */
    double
    max_of_tag(const std::map<std::string, double> &errors, const std::string &tag)
    {
      double m = nan;
      for (const auto &[name, e] : errors)
        if (name.find(tag) != std::string::npos && std::isfinite(e))
          m = std::isfinite(m) ? std::max(m, e) : e;
      return m;
    }

    std::string
    number(double v, int precision = 3)
    {
      if (!std::isfinite(v))
        return "–";
      return format_number(v, precision);
    }
  } // namespace

  // --------------------------------------------------------------------------------
  // The study.

  namespace
  {
    /**
     * The overrides every run starts from: --quick's shortening (left out for an entry
     * the user sets anyway) in front of the user's overrides (which win). The scene as
     * the user gave it is read first (an InputError there is the user's).
     */
    ParameterOverrides
    base_overrides(const std::string &scene_file, const StudyRequest &request)
    {
      const ParameterOverrides user(request.overrides);
      ParameterOverrides       study;
      {
        io::Scene scene = io::read_scene(scene_file, user);
        if (request.quick && has_wear(scene))
          study.set("Wear/Cycles per iteration", "1").set("Wear/Number of iterations", "2");
        else if (request.quick)
          study.set("Simulation/End time",
                    format_number(scene.start_time + std::min(1.0, scene.end_time - scene.start_time)));
        // Every row pays for its own fe-law tables: from a cache, a row that repeats an
        // earlier row's profiles would look cheaper than the same settings in a first run.
        for (const auto *j : scene.clearance_joints)
          if (entry_of(scene, "Joint " + j->name() + "/Clearance/Normal force law") == "fe")
            study.set("Joint " + j->name() + "/Clearance/fe/Table cache", "false");
      }
      return study.remove_paths_set_in(user).append(user);
    }

    /** The knobs studied (selection and replacement values), all checked before the first run. */
    std::vector<Knob>
    selected_knobs(std::vector<Knob>         all,
                   const std::string        &scene_file,
                   const StudyRequest       &request,
                   const ParameterOverrides &base)
    {
      // Selection and replacement values, all checked before the first run.
      std::vector<Knob>        knobs;
      const auto               known = known_knob_names();
      std::vector<std::string> applicable;
      for (const auto &k : all)
        applicable.push_back(k.name);
      for (const auto &name : request.knobs)
        {
          if (std::find(known.begin(), known.end(), name) == known.end())
            throw InputError("Unknown accuracy knob '" + name + "'; the knobs are " + join(known, ", ") + ".");
          if (std::find(applicable.begin(), applicable.end(), name) == applicable.end())
            throw InputError("The accuracy knob '" + name + "' does not apply to " + scene_file +
                             " (an effect the scene does not use is not a knob); the knobs of this scene are " +
                             join(applicable, ", ") + ".");
        }
      for (auto &k : all)
        if (request.knobs.empty() ||
            std::find(request.knobs.begin(), request.knobs.end(), k.name) != request.knobs.end())
          knobs.push_back(k);
      for (const auto &[name, values] : request.values)
        {
          auto it = std::find_if(knobs.begin(), knobs.end(), [&](const Knob &k) { return k.name == name; });
          if (it == knobs.end())
            throw InputError("Values are given for the accuracy knob '" + name +
                             "', which is not studied here; the knobs studied are " +
                             join(request.knobs.empty() ? applicable : request.knobs, ", ") + ".");
          it->values.clear();
          for (const auto &v : values)
            {
              const auto parts = split(v, ';');
              if (parts.size() != it->targets.size())
                throw InputError("A value of the accuracy knob '" + name + "' is '" + v + "'; it needs " +
                                 std::to_string(it->targets.size()) + " part(s) separated by ';' (" +
                                 std::to_string(it->targets.size()) + " settings: first entries " +
                                 [&] {
                                   std::vector<std::string> f;
                                   for (const auto &t : it->targets)
                                     f.push_back(t.front());
                                   return join(f, ", ");
                                 }() +
                                 ").");
              it->values.push_back(parts);
              // A value the user typed must make a valid scene.
              io::read_scene(scene_file, with_knob_value(base, *it, parts));
            }
          if (it->values.size() < 2)
            throw InputError("The accuracy knob '" + name + "' needs at least 2 values (the last is the reference).");
          it->reference = "the last value given";
        }

      return knobs;
    }

    /**
     * The errors of @p m's quantities and profiles against @p ref into @p errors (the
     * names seen into @p names); returns the worst that counts (see the header).
     */
    double
    errors_of(const Measurement             &m,
              const Measurement             &ref,
              const bool                     wears,
              std::map<std::string, double> &errors,
              std::set<std::string>         &names)
    {
      for (const auto &[q, v] : m.quantities)
        {
          errors[q] = ref.quantities.count(q) ? relative_error(v, ref.quantities.at(q)) : nan;
          names.insert(q);
        }
      for (const auto &[q, h] : m.profiles)
        {
          const bool  has   = ref.profiles.count(q) > 0;
          std::string shape = q;
          shape.replace(shape.find("profile_"), 8, "shape_");
          errors[q]     = has ? profile_difference(h, ref.profiles.at(q)) : nan;
          errors[shape] = has ? profile_difference(h, ref.profiles.at(q), shape_window_deg) : nan;
          names.insert(q);
          names.insert(shape);
        }
      double worst = 0;
      for (const auto &[q, e] : errors)
        if (counts_for_worst(q, wears))
          worst = std::isfinite(e) ? std::max(worst, e) : nan;
      return worst;
    }

    /**
     * The errors of each row's quantities and profiles against the knob's reference
     * (its last value), and the worst that counts; the names seen go into @p names.
     */
    void
    errors_against_reference(std::vector<StudyRow>          &rows,
                             const std::vector<Measurement> &ms,
                             const bool                      wears,
                             std::set<std::string>          &names)
    {
      const Measurement &ref = ms.back();
      for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i].worst = rows[i].ok && ref.ok ? errors_of(ms[i], ref, wears, rows[i].errors, names) : nan;
    }

    /** The runs of a study: one job per distinct effective scene, the rows' jobs, the floor's. */
    struct Plan
    {
      std::vector<StudyJob>                 jobs;
      std::vector<std::vector<std::size_t>> rows;  ///< per knob, per value: the job
      std::vector<std::size_t>              floor; ///< the chaos floor's members (the scene's own run first)
    };

    /** Plan the runs of @p knobs and of a chaos floor of @p request.floor_members members. */
    Plan
    plan_study(const std::string        &file,
               const ParameterOverrides &base,
               const std::vector<Knob>  &knobs,
               const StudyRequest       &request,
               const io::Scene          &scene)
    {
      Plan                               plan;
      std::map<std::string, std::size_t> by_key; // equal effective scenes are one run
      const auto                         job = [&](const ParameterOverrides &o, const std::string &label) {
        const std::string key = effective_parameters(file, o);
        if (by_key.count(key) == 0)
          {
            by_key[key] = plan.jobs.size();
            plan.jobs.push_back({o, label, predicted_cost(io::read_scene(file, o), scene)});
          }
        return by_key.at(key);
      };
      for (const auto &k : knobs)
        {
          plan.rows.emplace_back();
          for (const auto &v : k.values)
            plan.rows.back().push_back(job(with_knob_value(base, k, v), k.name + " = " + join(v, "; ")));
        }
      if (request.floor_members >= 2 && !scene.drivers.empty())
        {
          EnsembleRequest e{request.floor_members, request.seed, request.perturbation};
          plan.floor.push_back(job(base, "the scene's own settings (chaos floor member 0)"));
          for (unsigned int m = 1; m < request.floor_members; ++m)
            plan.floor.push_back(
              job(member_overrides(scene, base, e, m), "chaos floor member " + std::to_string(m) + " (perturbed)"));
        }
      return plan;
    }

    /** The rows of knob @p k from the plan's measurements; the names seen go into @p names. */
    std::vector<StudyRow>
    rows_of(const Knob                     &k,
            const std::vector<std::size_t> &jobs,
            const std::vector<Measurement> &measured,
            const bool                      wears,
            std::set<std::string>          &names)
    {
      std::vector<Measurement> ms;
      std::vector<StudyRow>    rows;
      for (std::size_t i = 0; i < k.values.size(); ++i)
        {
          ms.push_back(measured[jobs[i]]);
          StudyRow r;
          r.knob         = k.name;
          r.value        = join(k.values[i], "; ");
          r.reference    = join(k.values.back(), "; ") + " (" + k.reference + ")";
          r.is_reference = i + 1 == k.values.size();
          r.ok           = ms.back().ok;
          r.failure      = ms.back().failure;
          r.wall_time    = ms.back().wall_time;
          r.cpu_time     = ms.back().cpu_time;
          r.quantities   = ms.back().quantities;
          rows.push_back(r);
        }
      errors_against_reference(rows, ms, wears, names);
      return rows;
    }

    /**
     * The chaos floor from its members' measurements: every error of every pair of
     * members (one as the other's reference, as a knob's row against its reference),
     * their mean and largest, and the members' quantities' statistics.
     */
    ChaosFloor
    chaos_floor(const std::vector<Measurement> &members, const StudyRequest &request, const bool wears)
    {
      ChaosFloor f;
      f.members      = static_cast<unsigned int>(members.size());
      f.seed         = request.seed;
      f.perturbation = request.perturbation;
      std::map<std::string, std::vector<double>> errors;
      std::vector<double>                        worst, volume;
      std::set<std::string>                      names;
      std::vector<std::map<std::string, double>> quantities;
      for (std::size_t i = 0; i < members.size(); ++i)
        {
          if (!members[i].ok)
            {
              f.failures.push_back(members[i].failure);
              continue;
            }
          quantities.push_back(members[i].quantities);
          for (std::size_t j = i + 1; j < members.size(); ++j)
            if (members[j].ok)
              {
                std::map<std::string, double> e;
                worst.push_back(errors_of(members[i], members[j], wears, e, names));
                volume.push_back(max_of_tag(e, " V_"));
                for (const auto &[q, v] : e)
                  errors[q].push_back(v);
              }
        }
      for (const auto &[q, v] : errors)
        {
          f.mean_error[q] = analysis::ensemble_figure(v).mean;
          f.max_error[q]  = *std::max_element(v.begin(), v.end());
        }
      if (!worst.empty())
        {
          f.worst_mean = analysis::ensemble_figure(worst).mean;
          f.worst_min  = *std::min_element(worst.begin(), worst.end());
          f.worst_max  = *std::max_element(worst.begin(), worst.end());
        }
      if (wears && !volume.empty())
        {
          f.volume_mean = analysis::ensemble_figure(volume).mean;
          f.volume_min  = *std::min_element(volume.begin(), volume.end());
          f.volume_max  = *std::max_element(volume.begin(), volume.end());
        }
      f.quantities = analysis::ensemble_figures(quantities);
      return f;
    }
  } // namespace

  AccuracyStudy
  run_accuracy_study(const std::string &scene_file, const StudyRequest &request)
  {
    AccuracyStudy study;
    study.scene_file = scene_file;

    const ParameterOverrides base = base_overrides(scene_file, request);
    study.base_overrides          = base.settings();
    io::Scene scene               = io::read_scene(scene_file, base);
    study.wears                   = has_wear(scene);
    std::vector<Knob> all         = knobs_for(scene, request.quick);

    const std::vector<Knob> knobs = selected_knobs(all, scene_file, request, base);
    const Plan              plan  = plan_study(scene_file, base, knobs, request, scene);
    if (request.progress && is_study_root())
      std::cerr << "[wearlink] study: " << plan.jobs.size() << " runs (" << plan.floor.size()
                << " of them the chaos floor's members)\n";
    const auto measured = measure_jobs(scene_file, plan.jobs, request.progress);
    study.root          = is_study_root();
    if (!study.root)
      return study;
    std::set<std::string> names;
    for (std::size_t k = 0; k < knobs.size(); ++k)
      {
        const auto rows = rows_of(knobs[k], plan.rows[k], measured, study.wears, names);
        study.rows.insert(study.rows.end(), rows.begin(), rows.end());
      }
    std::vector<Measurement> members;
    for (const std::size_t j : plan.floor)
      members.push_back(measured[j]);
    if (!members.empty())
      study.floor = chaos_floor(members, request, study.wears);
    study.quantity_names.assign(names.begin(), names.end());
    return study;
  }

  // --------------------------------------------------------------------------------
  // Outputs.

  namespace
  {
    /** The columns of the error table after "time ratio": tags of the quantities they take the largest of. */
    std::vector<const char *>
    error_tags(const bool wears)
    {
      std::vector<const char *> tags = {" F_peak", "a_peak"};
      if (wears)
        tags.insert(tags.begin(), {" V_", " h_", " profile_", " shape_"});
      return tags;
    }

    /** What the columns mean. */
    std::string
    markdown_intro(const AccuracyStudy &study)
    {
      std::ostringstream os;
      os << "Accuracy study of `" << study.scene_file << "`";
      if (!study.base_overrides.empty())
        os << " with `" << join(study.base_overrides, "`, `") << "`";
      os << ". Each knob is varied alone (everything else at the scene's value); errors are relative to that "
            "knob's reference run (the row marked **ref**; 'reference' says what it is). ";
      if (study.wears)
        os << "V: worn volume, h: largest wear depth (each the largest error over pin and bushing of every "
              "wearing joint), profile: ‖h − h_ref‖/‖h_ref‖ of the worn-depth profiles point by point, shape: "
              "the same after a "
           << shape_window_deg << "° moving average (the profile without its impact-to-impact spikes), ";
      os
        << "F: peak contact force (largest over the joints), a: peak acceleration of the response body; "
           "worst: the largest of "
        << (study.wears ? "V and shape" : "F and a")
        << "; floor: the chaos floor of worst (below the table), worst/floor: the row's worst over it (≲ 1: not "
           "resolved from the chaos). CPU s: the run's CPU time, its wall time on a core of its own (wall times on a shared "
           "machine vary with its load); time ratio: CPU time / reference's. Rows with the same effective scene are "
           "one run, measured once; fe-law tables are built in every run (no table cache).\n\n";
      return os.str();
    }

    /** The paragraph below the table: the chaos floor of each column. */
    std::string
    floor_paragraph(const AccuracyStudy &study)
    {
      const ChaosFloor  &f = study.floor;
      std::ostringstream os;
      if (f.members < 2)
        return "\nNo chaos floor was measured (`--ensemble 0`, or a scene without angle drivers).\n";
      os << "\nChaos floor: " << f.members << " runs at the scene's own settings — its own run and " << f.members - 1
         << " with every angle driver's initial angle shifted by ~" << f.perturbation << " rad (seed " << f.seed
         << ") — compared pairwise as a row is with its reference; mean over the " << f.members * (f.members - 1) / 2
         << " pairs (largest pair):";
      const char *names[] = {"V", "h", "profile", "shape", "F", "a"};
      const auto  tags    = error_tags(true);
      for (std::size_t i = 0; i < tags.size(); ++i)
        {
          const double mean = max_of_tag(f.mean_error, tags[i]);
          if (std::isfinite(mean))
            os << ' ' << names[i] << ' ' << number(mean, 2) << " (" << number(max_of_tag(f.max_error, tags[i]), 2)
               << "),";
        }
      os << " worst " << number(f.worst_mean, 2) << " (pairs " << number(f.worst_min, 2) << " … "
         << number(f.worst_max, 2)
         << "). An error inside that range is not resolved from the chaos of the "
            "clearance dynamics.";
      if (!f.failures.empty())
        os << " " << f.failures.size() << " member(s) failed: " << f.failures.front();
      return os.str() + "\n";
    }
  } // namespace

  std::string
  AccuracyStudy::markdown() const
  {
    std::ostringstream os;
    os << markdown_intro(*this);
    const auto tags = error_tags(wears);
    os << "| knob | value | reference | wall s | CPU s | time ratio | " << (wears ? "V | h | profile | shape | " : "")
       << "F | a | worst | floor | worst/floor |\n"
       << "|---|---|---|---:|---:|---:|";
    for (std::size_t i = 0; i <= tags.size() + 2; ++i)
      os << "---:|";
    os << '\n';
    std::map<std::string, double> ref_time;
    for (const auto &r : rows)
      if (r.is_reference)
        ref_time[r.knob] = r.cpu_time;
    const double f = floor.worst_mean;
    for (const auto &r : rows)
      {
        os << "| " << r.knob << " | " << r.value << (r.is_reference ? " **ref**" : "") << " | " << r.reference << " | "
           << number(r.wall_time) << " | " << number(r.cpu_time) << " | " << number(r.cpu_time / ref_time[r.knob], 2)
           << " | ";
        if (!r.ok)
          {
            os << "failed: " << r.failure << " |";
            for (std::size_t i = 0; i < tags.size() + 2; ++i)
              os << " |";
            os << '\n';
          }
        else if (r.is_reference)
          {
            for (std::size_t i = 0; i <= tags.size(); ++i)
              os << "ref | ";
            os << number(f, 2) << " | ref |\n";
          }
        else
          {
            for (const char *tag : tags)
              os << number(max_error(r, tag), 2) << " | ";
            os << number(r.worst, 2) << " | " << number(f, 2) << " | " << number(r.worst / f, 2) << " |\n";
          }
      }
    return os.str() + floor_paragraph(*this);
  }

  std::string
  AccuracyStudy::csv() const
  {
    std::ostringstream os;
    os
      << "knob,value,reference,is_reference,status,wall_time_s,cpu_time_s,worst_error,floor_worst_mean,floor_worst_max,"
         "worst_over_floor";
    for (const auto &q : quantity_names)
      {
        if (!is_profile(q))
          os << ',' << q;
        os << ',' << q << " error";
      }
    os << '\n' << std::setprecision(10);
    auto quoted = [](const std::string &s) {
      std::string t = "\"";
      for (const char c : s)
        t += c == '"' ? std::string("\"\"") : std::string(1, c);
      return t + "\"";
    };
    for (const auto &r : rows)
      {
        os << r.knob << ',' << quoted(r.value) << ',' << quoted(r.reference) << ',' << (r.is_reference ? 1 : 0) << ','
           << quoted(r.ok ? "ok" : "failed: " + r.failure) << ',' << r.wall_time << ',' << r.cpu_time << ',' << r.worst
           << ',' << floor.worst_mean << ',' << floor.worst_max << ','
           << (r.is_reference ? nan : r.worst / floor.worst_mean);
        for (const auto &q : quantity_names)
          {
            if (!is_profile(q))
              os << ',' << (r.quantities.count(q) ? r.quantities.at(q) : nan);
            os << ',' << (r.errors.count(q) ? r.errors.at(q) : nan);
          }
        os << '\n';
      }
    return os.str();
  }

  std::string
  AccuracyStudy::floor_csv() const
  {
    std::ostringstream os;
    os << "quantity,pair_mean_error,pair_max_error,member_mean,member_std,member_ci95_low,member_ci95_high,members\n"
       << std::setprecision(10);
    for (const auto &[q, e] : floor.mean_error)
      {
        os << '"' << q << "\"," << e << ',' << floor.max_error.at(q);
        if (floor.quantities.count(q))
          {
            const auto &f = floor.quantities.at(q);
            os << ',' << f.mean << ',' << f.std << ',' << f.ci95_low << ',' << f.ci95_high << ',' << f.members;
          }
        else
          os << ",,,,," << floor.members;
        os << '\n';
      }
    return os.str();
  }

  namespace
  {
    /**
     * Error against wall time, log–log, one series per knob, the value of each row by
     * @p error (reference rows and errors ≤ 0 left out), and the chaos floor as a band
     * from its smallest to its largest pair with a dashed line at their mean.
     */
    io::PlotSpec
    pareto_plot(const AccuracyStudy                           &study,
                const std::function<double(const StudyRow &)> &error,
                const std::string                             &y_label,
                const std::array<double, 3>                   &floor)
    {
      io::PlotSpec spec;
      spec.title   = "What accuracy costs in time: " + study.scene_file + " (reference runs, error 0, not shown)";
      spec.x_label = "CPU time of the run [s] (its wall time on a core of its own)";
      spec.y_label = y_label;
      spec.log_x   = true;
      spec.log_y   = true;
      if (std::isfinite(floor[0]) && floor[0] > 0 && floor[2] >= floor[0])
        spec.band = io::Band{floor[0],
                             floor[2],
                             floor[1],
                             "chaos floor: " + std::to_string(study.floor.members) +
                               " runs at the scene settings: pairs (band), their mean (dashed)"};
      std::vector<std::string> knobs;
      for (const auto &r : study.rows)
        if (std::find(knobs.begin(), knobs.end(), r.knob) == knobs.end())
          knobs.push_back(r.knob);
      unsigned shape = 4;
      for (const auto &k : knobs)
        {
          io::PlotSeries s{k, {}, {}, io::numbered_shape(io::line_points("", 2, io::Marker::automatic, 2), shape++)};
          for (const auto &r : study.rows)
            if (r.knob == k && !r.is_reference && r.ok && std::isfinite(error(r)) && error(r) > 0)
              {
                s.x.push_back(r.cpu_time);
                s.y.push_back(error(r));
              }
          if (!s.x.empty())
            spec.series.push_back(s);
        }
      return spec;
    }
  } // namespace

  void
  write_accuracy_study(const std::string &dir, const AccuracyStudy &study)
  {
    make_output_directory(dir);
    const auto &f     = study.floor;
    const auto  worst = pareto_plot(study,
                                   [](const StudyRow &r) { return r.worst; },
                                   std::string("worst relative error vs the knob's reference") +
                                     (study.wears ? " (worn volume, profile shape)" : " (peak force, acceleration)"),
                                   {{f.worst_min, f.worst_mean, f.worst_max}});
    // The worn volume alone: robust where depths and profiles meet the chaos floor.
    const auto volume = pareto_plot(study,
                                    [](const StudyRow &r) { return max_error(r, " V_"); },
                                    "relative error of the worn volume (largest over surfaces and joints)",
                                    {{f.volume_min, f.volume_mean, f.volume_max}});
    write_file_atomically(dir + "/" + io::outputs::accuracy_table, study.csv());
    write_file_atomically(dir + "/" + io::outputs::accuracy_report, study.markdown());
    if (f.members >= 2)
      write_file_atomically(dir + "/" + io::outputs::accuracy_floor, study.floor_csv());
    if (!worst.series.empty())
      io::plot_png(worst, dir + "/accuracy_pareto.png");
    if (study.wears && !volume.series.empty())
      io::plot_png(volume, dir + "/accuracy_pareto_volume.png");
  }
} // namespace wearlink::workflows
