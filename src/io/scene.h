// SPDX-License-Identifier: LGPL-2.1-or-later
// A scene read from a .prm file: the mechanism it describes (bodies, joints, drivers,
// clearance joints as force elements with the laws the scene chose), the numerics, and
// the outputs it asks for. Mechanisms are data: nothing here knows a particular linkage.
//
// Reading follows doc/contributing.md §4: pre-scan the body and joint names, declare one
// subsection per name (every registry's plugins inside each clearance joint), strict
// parse (typos are errors with file and line), apply --set overrides, check required
// entries of the parts that are active, construct only the chosen plugins, cross-check.
#pragma once

#include "analysis/analyses_settings.h"
#include "analysis/input_distributions.h"
#include "analysis/life_criteria.h"
#include "base/parameters.h"
#include "base/validity_warnings.h"
#include "contact/clearance_joint.h"
#include "mbs/mechanism.h"
#include "mbs/simulation.h"
#include "wear/wear_settings.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace wearlink::io
{
  struct Scene
  {
    std::string file; ///< the scene file as given
    /** The --set overrides it was read with (to read the same scene again). */
    ParameterOverrides overrides;
    std::string        title;

    std::unique_ptr<mbs::Mechanism> mechanism;
    /** The clearance joints (owned by the mechanism as force elements). */
    std::vector<contact::ClearanceJoint *> clearance_joints;
    /** Clearance joints pinned at their initial eccentricity, for assembly only. */
    std::vector<std::unique_ptr<mbs::Constraint>> assembly_constraints;
    /** Indices (in mechanism->get_constraints()) of the angle drivers. */
    std::vector<unsigned int> drivers;

    mbs::SimulationSettings simulation;
    double                  start_time = 0; ///< [s]
    double                  end_time   = 0; ///< [s]

    double output_interval   = 1e-3; ///< time-series sampling [s]; 0: every step
    bool   write_time_series = true;
    /** Output/Plots: the first-look PNGs of a run (workflows/run/first_look.h). */
    bool plots = true;
    /**
     * The bodies whose acceleration the first look plots: Output/Plot bodies if given,
     * else the bodies that slide on a translational joint; if none, empty (the first
     * look then takes the body with the largest peak acceleration).
     */
    std::vector<std::string> plot_bodies;

    /** The nonlinear-dynamics analyses the scene lists (analysis/analyses_settings.h). */
    analysis::AnalysesSettings analyses;
    /** Joints with Wear law = archard (their chosen pressure model inside). */
    std::vector<std::unique_ptr<wear::JointWear>> wear;
    /** The "Wear" section (used when wear is non-empty). */
    wear::WearLoopSettings wear_loop;
    /** The "Life" section: the stop criteria of `wearlink life` (analysis/life_parameters.h). */
    analysis::LifeSettings life;
    /** The "Uncertainty" section: the uncertain inputs of an ensemble (io/uncertainty_parameters.h). */
    analysis::UncertaintySettings uncertainty;

    /**
     * Entries that are valid one by one but implausible (a friction coefficient above 1,
     * a wear cycle that is no whole number of driving periods): reported with the
     * validity warnings of every run of the scene (summary.json `warnings`, stderr).
     */
    ValidityWarnings warnings;

    /** The parsed parameters (for echoing the effective scene next to the results). */
    std::unique_ptr<dealii::ParameterHandler> parameters;
  };

  /**
   * The joint that the wearing joint @p wearing of @p scene is part of: a slice's sliced
   * joint ("B" for "B.s03", doc/models.md §1.8), else @p wearing itself.
   */
  inline std::string
  whole_joint(const Scene &scene, const std::string &wearing)
  {
    for (const auto *j : scene.clearance_joints)
      if (j->name() == wearing && j->get_description().slice.count > 1)
        return j->get_description().slice.joint;
    return wearing;
  }

  /**
   * Read, validate and build the scene in @p file with command-line @p overrides
   * ("Section/Entry=value"). Every problem with the input is an InputError naming the
   * file, the entry and the allowed values.
   */
  Scene
  read_scene(const std::string &file, const ParameterOverrides &overrides = {});

  /**
   * Print every entry a scene can have, with documentation, units and defaults. With a
   * scene file, its own bodies and joints are used; otherwise one placeholder of each.
   */
  void
  print_scene_parameters(std::ostream &out, const std::string &file = "");
} // namespace wearlink::io
