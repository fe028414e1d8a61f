// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/scene_declarations.h"

#include "analysis/analyses_parameters.h"
#include "analysis/life_parameters.h"
#include "analysis/uncertainty_parameters.h"
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
#include "contact/clearance_parameters.h"
#include "mbs/mbs_parameters.h"
#include "wear/wear_settings.h"

namespace wearlink::io
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace P = dealii::Patterns;

    /** Bound of |Start time| and |End time| [s]. */
    constexpr double max_simulated_time = 1e6;

    // ------------------------------------------------------------------------------
    // Declarations.

    void
    declare_top(ParameterHandler &prm)
    {
      declare_required(prm,
                       "Scene format",
                       P::Integer(1, 1),
                       "Version of the scene file format; this wearlink reads format 1.",
                       "none");
      declare(prm, "Title", "", P::Anything(), "Free text shown in the run summary.", "none");
      prm.enter_subsection("Mechanism");
      declare_required(prm,
                       "Bodies",
                       P::List(P::Anything(), 1),
                       "Names of the moving bodies; each has a 'subsection Body <name>'. "
                       "'ground' is the fixed frame and is not listed.",
                       "none");
      declare_required(prm,
                       "Joints",
                       P::List(P::Anything(), 1),
                       "Names of the joints and drivers; each has a 'subsection Joint <name>'.",
                       "none");
      declare(prm,
              "Gravity",
              "0, -9.81",
              point_pattern(),
              "Gravitational acceleration (x, y). Set 0, 0 to switch gravity off.",
              "m/s²");
      prm.leave_subsection();
    }


    /** Simulation: the simulated interval. */
    void
    declare_simulation(ParameterHandler &prm)
    {
      prm.enter_subsection("Simulation");
      declare(prm,
              "Start time",
              "0",
              P::Double(-max_simulated_time, max_simulated_time),
              "Time at which assembly happens, |t| ≤ 1e6 s.",
              "s");
      declare_required(prm,
                       "End time",
                       P::Double(-max_simulated_time, max_simulated_time),
                       "Time at which the run stops, |t| ≤ 1e6 s: 11.6 days of motion, far more than "
                       "any run integrates step by step (wear runs represent long service by "
                       "extrapolation instead).",
                       "s");
      prm.leave_subsection();
    }

    /** Output: time series and plots. */
    void
    declare_output(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      declare(prm,
              "Time series",
              "true",
              P::Bool(),
              "Write time_series.csv (positions, velocities, accelerations, joint "
              "quantities, driver torques, energies).",
              "none");
      declare(prm,
              "Time series interval",
              "1e-3",
              P::Double(0),
              "Sampling interval of time_series.csv (dense output); 0 writes every "
              "accepted step.",
              "s");
      declare(prm,
              "Plots",
              "true",
              P::Bool(),
              "Write the first-look PNGs of `wearlink run` (read back from time_series.csv, "
              "so only with Time series = true): orbit_<J>.png, the journal-centre orbit of "
              "each clearance joint in its bushing's frame inside the clearance circle; "
              "contact_forces.png, the normal and friction force of each clearance joint "
              "against time; accelerations.png, the acceleration of the Plot bodies. false "
              "writes none (tests, benchmarks, sweeps).",
              "none");
      declare(prm,
              "Plot bodies",
              "",
              P::Anything(),
              "Comma-separated bodies whose acceleration accelerations.png shows and the "
              "printed summary reports. Empty: the bodies that slide on a translational "
              "joint (Body 2 of it, e.g. the slider of a press); if there is none, the body "
              "with the largest peak acceleration component of the run.",
              "none");
      prm.leave_subsection();
    }

    /**
     * A joint: the multibody layer's entries, and in "Clearance" the contact layer's
     * and the wear layer's (each declares its own).
     */
    void
    declare_joint(ParameterHandler &prm, const std::string &body_names)
    {
      mbs::declare_joint(prm, body_names);
      prm.enter_subsection("Clearance");
      contact::declare_clearance(prm);
      wear::declare_joint_wear(prm);
      prm.leave_subsection();
    }

    void
    declare_numerics(ParameterHandler &prm)
    {
      mbs::declare_integrator(prm);
      declare_simulation(prm);
      declare_output(prm);
    }
  } // namespace

  void
  declare_scene(ParameterHandler &prm, const std::vector<std::string> &bodies, const std::vector<std::string> &joints)
  {
    declare_top(prm);
    for (const auto &b : bodies)
      {
        prm.enter_subsection("Body " + b);
        mbs::declare_body(prm);
        prm.leave_subsection();
      }
    const std::string names = "ground|" + join(bodies, "|");
    for (const auto &j : joints)
      {
        prm.enter_subsection("Joint " + j);
        declare_joint(prm, names);
        prm.leave_subsection();
      }
    declare_numerics(prm);
    analysis::declare_analyses(prm);
    wear::declare_wear_loop(prm);
    analysis::declare_life(prm);
    analysis::declare_uncertainty(prm);
  }
} // namespace wearlink::io
