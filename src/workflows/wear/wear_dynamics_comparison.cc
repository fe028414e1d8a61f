// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/wear/wear_dynamics_comparison.h"

#include "analysis/analyses_parameters.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/parameters.h"
#include "io/scene_periods.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /**
     * The two-trajectory exponent (workflows/run/shadow_trajectory.h) of the fresh and of the worn
     * mechanism: the scene read again with its overrides plus the analysis, duration and
     * tightened tolerances, and for the worn state the profiles written into @p dir
     * (bore_<J>.csv, pin_<J>.csv). Outputs in DIR/exponent_before, DIR/exponent_after.
     * A run the integrator cannot finish (a numerical failure) gives no exponent, with the
     * reason in the comparison, and the wear run goes on: on worn pockets that conform to
     * the pin, the deepest point of contact can jump between the pocket's flanks and
     * the force's direction with it, which the integrator may not get through at the
     * tight tolerance these runs need (the nine-bar after 50,000 revolutions: 76,828
     * steps for 2.7 ms at 1e-11).
     */
    SimulationExponents
    two_trajectory_exponents(const io::Scene       &scene,
                             const wear::WearState &st,
                             const std::string     &dir,
                             const bool             progress)
    {
      const auto         &a     = scene.analyses;
      const auto         &is    = scene.simulation.integrator;
      const double        scale = a.two_trajectory_tolerance / is.relative_tolerance;
      const double        T     = io::driving_period(scene);
      SimulationExponents out;
      out.separation            = a.two_trajectory_separation;
      out.interval              = a.renormalization_interval;
      out.tolerance             = a.two_trajectory_tolerance;
      out.duration              = a.two_trajectory_cycles * T;
      const std::string abs_dir = std::filesystem::absolute(dir).string();
      for (int k = 0; k < 2; ++k)
        {
          ParameterOverrides o = scene.overrides;
          o.set("Analyses/List of analyses", "lyapunov")
            .set("Analyses/Lyapunov/Methods", "two-trajectory")
            .set("Output/Time series", "false")
            .set("Simulation/End time", scene.start_time + a.transient + out.duration)
            .set("Integrator/Relative tolerance", a.two_trajectory_tolerance)
            .set("Integrator/Position tolerance", is.absolute_tolerance[0] * scale)
            .set("Integrator/Velocity tolerance", is.absolute_tolerance[1] * scale);
          if (k == 1)
            for (const auto &j : st.joints)
              o.set("Joint " + j.name + "/Clearance/Bore profile file", abs_dir + "/bore_" + j.name + ".csv")
                .set("Joint " + j.name + "/Clearance/Pin profile file", abs_dir + "/pin_" + j.name + ".csv");
          if (progress)
            std::cerr << "[wearlink] two-trajectory exponent " << (k == 0 ? "before" : "after") << " wear, "
                      << a.two_trajectory_cycles << " periods at relative tolerance " << a.two_trajectory_tolerance
                      << "\n";
          io::Scene  s = io::read_scene(scene.file, o);
          RunOptions ro;
          ro.output_directory = dir + (k == 0 ? "/exponent_before" : "/exponent_after");
          ro.progress         = progress;
          double &exponent    = k == 0 ? out.before : out.after;
          try
            {
              const Json  summary = run_scene(s, ro);
              const Json &l       = summary.at("analyses").at("lyapunov");
              for (std::size_t i = 0; i < l.size(); ++i)
                if (l[i].at("method").get<std::string>() == "two-trajectory")
                  exponent = json_number(l[i].at("exponent_per_s"));
            }
          catch (const NumericalError &e) // this estimate is lost, not the wear run
            {
              exponent                                          = std::numeric_limits<double>::quiet_NaN();
              (k == 0 ? out.failure_before : out.failure_after) = e.what();
              std::cerr << "[wearlink] warning: the two-trajectory exponent " << (k == 0 ? "before" : "after")
                        << " wear could not be computed: " << e.what() << "\n";
            }
        }
      return out;
    }
  } // namespace

  DynamicsComparison
  before_after_dynamics(io::Scene                                    &scene,
                        const wear::WearState                        &st,
                        const std::vector<contact::ClearanceJoint *> &joints,
                        const std::string                            &response,
                        const std::string                            &dir,
                        const bool                                    progress)
  {
    ComparedRun       runs[2];
    const char *const names[2] = {"before", "after"};
    // The shadow trajectory needs its own tolerance and the profiles as files (it
    // reads the scene again): separate runs below, not these.
    const bool                 two_trajectory = scene.analyses.lyapunov && scene.analyses.two_trajectory;
    analysis::AnalysesSettings without_shadow = scene.analyses;
    without_shadow.two_trajectory             = false;
    for (int k = 0; k < 2; ++k)
      {
        for (unsigned int i = 0; i < joints.size(); ++i)
          joints[i]->set_profiles(k == 0 ? st.joints[i].initial_bore : st.joints[i].bore,
                                  k == 0 ? st.joints[i].initial_pin : st.joints[i].pin);
        for (auto *j : scene.clearance_joints)
          j->set_mode(false, 0);
        if (progress)
          std::cerr << "[wearlink] dynamics " << names[k] << " wear with the scene's analyses, t = " << scene.start_time
                    << " … " << scene.end_time << " s\n";
        RunOptions ro;
        ro.output_directory  = dir.empty() ? std::string() : dir + "/dynamics_" + names[k];
        ro.progress          = progress;
        ro.recorded          = &runs[k].run;
        ro.analyses_settings = &without_shadow;
        runs[k].summary      = run_scene(scene, ro);
        std::ostringstream label;
        label << (k == 0 ? "before wear" : "after wear");
        if (k == 1)
          label << " (" << std::setprecision(6) << st.revolutions << " rev)";
        runs[k].run.label = label.str();
      }
    const auto                &a = scene.analyses;
    DynamicsComparisonSettings cs;
    cs.joints     = a.joints;
    cs.directions = a.directions;
    if (a.lyapunov)
      cs.methods = a.methods;
    cs.delay      = a.comparison_delay;
    cs.dimension  = a.comparison_dimension;
    cs.delay_scan = a.delay_scan;
    cs.bodies     = a.bodies;
    if (!response.empty() && std::find(cs.bodies.begin(), cs.bodies.end(), response) == cs.bodies.end())
      cs.bodies.push_back(response);
    cs.published      = analysis::parse_published_exponents(a.published_exponents, scene.file);
    cs.published_note = a.published_note;
    if (two_trajectory && !dir.empty())
      cs.simulation_exponents = two_trajectory_exponents(scene, st, dir, progress);
    return compare_dynamics(runs[0], runs[1], cs, dir);
  }
} // namespace wearlink::workflows
