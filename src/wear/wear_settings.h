// SPDX-License-Identifier: LGPL-2.1-or-later
// What a scene says about wear, declared once with units (doc/contributing.md §4):
//  - per clearance joint, inside "Joint <name>/Clearance":
//      Wear law        none | archard        (none: no buffers, no pressure model)
//      Pressure model  hertz-strip | winkler | fe   (only used, and only constructed,
//                      when Wear law = archard; no default: the choice is the user's)
//      archard/        Pin and Bushing wear coefficient k_D [m³/(N m)], Pin and
//                      Bushing density [kg/m³] — physical data, required when active
//  - once per scene, "Wear": the iteration loop (cycles per iteration, extrapolation,
//    clearance model, load sampling, outputs; the fe model's re-mesh depth is its own).
// Only deal.II's ParameterHandler is used here (no FE headers), so io/ and app/ may
// include it.
#pragma once

#include "base/parameters.h"
#include "contact/clearance_joint.h"
#include "contact/pressure_model.h"

#include <memory>
#include <string>
#include <vector>

namespace wearlink::wear
{
  /** Archard data of one joint (doc/models.md §4): dh = k_D p ds on each surface. */
  struct ArchardData
  {
    double pin_coefficient     = 0; ///< k_D of the pin surface [m³/(N m)] = [1/Pa]
    double bushing_coefficient = 0; ///< k_D of the bore surface [m³/(N m)]
    double pin_density         = 0; ///< [kg/m³], for the mass loss
    double bushing_density     = 0; ///< [kg/m³]
  };

  /** Wear of one clearance joint, as the scene chose it. */
  struct JointWear
  {
    std::string                             joint;          ///< joint name
    std::string                             pressure_model; ///< plugin name
    ArchardData                             archard;
    std::unique_ptr<contact::PressureModel> model; ///< constructed plugin
  };

  enum class Extrapolation
  {
    fixed,   ///< every iteration stands for Cycles per iteration × Extrapolation factor
    adaptive ///< the factor caps the largest depth increment per iteration
  };

  enum class PressureEvaluation
  {
    every_step, ///< the pressure model at every loaded integrator step
    samples     ///< once per 1/N cycle; the window's steps reuse that shape
  };

  /** How an iteration's wear is applied (wear/archard.h). */
  enum class WearUpdate
  {
    sequential,  ///< each load state's wear × f at once, in time order
    simultaneous ///< every state on the start geometry, × f at the end (the seed's route)
  };

  /** How the iterations integrate the wear over revolutions (wear/wear_step.h). */
  enum class WearStep
  {
    euler,          ///< first order: the iteration's own rate over the whole step
    adams_bashforth ///< second order: the rate extrapolated to the step's middle
  };

  /** The wear loop of a scene ("Wear" section). */
  struct WearLoopSettings
  {
    double                 cycle_period         = 0; ///< [s]; 0: 2π/|ω| of the first angle driver
    double                 cycles_per_iteration = 1; ///< simulated cycles per iteration [-]
    double                 settling_cycles      = 1; ///< simulated before the first iteration, not counted [-]
    unsigned int           n_iterations         = 1; ///< iterations (fixed), cap (adaptive)
    Extrapolation          extrapolation        = Extrapolation::fixed;
    double                 extrapolation_factor = 1; ///< fixed factor [-]
    double                 max_depth_increment  = 0; ///< adaptive: cap per iteration [m]
    double                 max_factor           = 0; ///< adaptive: largest factor [-]
    double                 target_revolutions   = 0; ///< adaptive: stop there [-]
    contact::ClearanceForm clearance_form       = contact::ClearanceForm::conformal;
    unsigned int           conformal_cells      = 4; ///< cells per bore area of the conformal foundation
    PressureEvaluation     evaluation           = PressureEvaluation::every_step;
    WearUpdate             update               = WearUpdate::sequential;
    WearStep               step                 = WearStep::euler;
    unsigned int           samples_per_cycle    = 100;
    double                 smoothing_wavelength = 0; ///< low-pass of the depth increments [m]; 0: none
    double                 response_cycles      = 1; ///< before/after response [cycles]
    std::string            response_body;            ///< body whose response is plotted
    double                 magnification = 0;        ///< profile plots; 0: automatic
    bool                   fe_output     = true;     ///< meshes and fields of fe joints into DIR/fe
    bool every_iteration_output          = false; ///< keep every iteration's profile frame and FE files (else the last)
  };

  /** Declare the per-joint wear entries (inside "Joint <name>/Clearance"). */
  void
  declare_joint_wear(dealii::ParameterHandler &prm);

  /** Declare the "Wear" section (at the top level). */
  void
  declare_wear_loop(dealii::ParameterHandler &prm);

  /**
   * Subsections of "Joint <joint>/Clearance/" whose required entries are not active:
   * the archard data when Wear law = none, and every pressure model not chosen.
   * @p prm must be inside that Clearance subsection.
   */
  std::vector<std::string>
  inactive_wear_sections(const dealii::ParameterHandler &prm);

  /**
   * Read the wear of one joint (reader inside "Joint <joint>/Clearance"). Returns null
   * for Wear law = none; otherwise constructs the chosen pressure model (only that one).
   */
  std::unique_ptr<JointWear>
  read_joint_wear(ParameterReader &reader, const std::string &joint);

  /** Read the "Wear" section (reader at the top level). */
  WearLoopSettings
  read_wear_loop(ParameterReader &reader);
} // namespace wearlink::wear
