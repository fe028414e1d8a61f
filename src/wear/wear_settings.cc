// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_settings.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"

namespace wearlink::wear
{
  namespace
  {
    /** Bound of the wear coefficients [m³/(N m)] (see their documentation). */
    constexpr double max_wear_coefficient = 1e-8;
    /** Bound of the densities [kg/m³]. */
    constexpr double max_density = 3e4;
  } // namespace

  namespace P = dealii::Patterns;

  void
  declare_joint_wear(dealii::ParameterHandler &prm)
  {
    declare(prm,
            "Wear law",
            "none",
            P::Selection("none|archard"),
            "Wear of the pin and bore surfaces. 'none': no wear buffers, no pressure "
            "model, no re-meshing; 'archard': dh = k_D p ds on each surface, accumulated "
            "at its own material points (doc/models.md §4); the run becomes a wear loop "
            "(section Wear).",
            "none");
    declare_required(prm,
                     "Pressure model",
                     P::Selection(contact::pressure_models().pattern()),
                     "Contact pressure on both surfaces for Archard's law. Only used (and "
                     "only constructed) if Wear law = archard." +
                       contact::pressure_models().documentation(),
                     "none");
    contact::pressure_models().declare_all(prm);
    prm.enter_subsection("archard");
    declare_required(prm,
                     "Pin wear coefficient",
                     P::Double(0, max_wear_coefficient),
                     "Dimensional wear coefficient k_D = K/H of the pin surface (doc/models.md "
                     "§4: 1e-13 … 7e-11 m³/(N m) for Al alloys dry on steel; 1 mm³/(N m) = "
                     "1e-9 m³/(N m)), 0 … 1e-8 m³/(N m): 100 × the most severe dry wear measured; a "
                     "larger value is a mistake of units. Only used if Wear law = archard.",
                     "m³/(N m)");
    declare_required(prm,
                     "Bushing wear coefficient",
                     P::Double(0, max_wear_coefficient),
                     "Dimensional wear coefficient k_D of the bore surface, 0 … 1e-8 m³/(N m). Only "
                     "used if Wear law = archard.",
                     "m³/(N m)");
    declare_required(prm,
                     "Pin density",
                     P::Double(1, max_density),
                     "Density of the pin material, for the mass loss, 1 … 3e4 kg/m³ (the densest "
                     "element, osmium, has 22 590 kg/m³). Only used if Wear law = archard.",
                     "kg/m³");
    declare_required(prm,
                     "Bushing density",
                     P::Double(1, max_density),
                     "Density of the bushing material, for the mass loss, 1 … 3e4 kg/m³. Only used "
                     "if Wear law = archard.",
                     "kg/m³");
    prm.leave_subsection();
  }


  namespace
  {
    /** The iterations: cycle period, cycles per iteration, how many, extrapolation. */
    void
    declare_iteration_entries(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Cycle period",
              "0",
              P::Double(0, 1e6),
              "Duration of one mechanism cycle (one crank revolution); 0 takes 2π/|ω| of the "
              "first angle driver. Only used by wear runs (some joint has Wear law = "
              "archard), as are all entries of this section except Clearance model.",
              "s");
      declare(prm,
              "Cycles per iteration",
              "1",
              P::Double(0, 1e4),
              "Mechanism cycles simulated per wear iteration (wear is accumulated over them, "
              "then extrapolated), at most 1e4: the load history of an iteration is kept in "
              "memory, and extrapolation represents more cycles at no cost.",
              "cycles");
      declare(prm,
              "Settling cycles",
              "1",
              P::Double(0, 1e4),
              "Cycles simulated from the assembly before the first wear iteration and not "
              "counted in the wear, so that the start-up (the pins falling from their initial "
              "eccentricities onto the bores, the impacts that follow) is not extrapolated; "
              "summary.json reports it (wear_start_up). Later iterations continue from the "
              "state the previous one ended in, carried onto the worn profiles; the response "
              "after wear settles as many cycles before it is measured.",
              "cycles");
      declare(prm,
              "Number of iterations",
              "1",
              P::Integer(1, 100000),
              "Wear iterations (Extrapolation = fixed); the largest number of iterations "
              "(adaptive). At most 1e5 (each iteration simulates at least one cycle and keeps "
              "a row of history; raise Extrapolation factor instead).",
              "none");
      declare(prm,
              "Extrapolation",
              "fixed",
              P::Selection("fixed|adaptive"),
              "'fixed': each iteration's wear is multiplied by Extrapolation factor (the "
              "seed: 100 cycles × 500); 'adaptive': the factor is chosen so that the largest "
              "depth increment of any surface is Maximum depth increment (at most Maximum "
              "extrapolation factor), until Target revolutions are reached.",
              "none");
      declare(prm,
              "Extrapolation factor",
              "1",
              P::Double(0, 1e9),
              "fixed: revolutions represented by one simulated cycle.",
              "none");
      declare(prm,
              "Maximum depth increment",
              "1e-6",
              P::Double(0),
              "adaptive: cap of the largest wear-depth increment per iteration on any "
              "surface of any joint.",
              "m");
      declare(prm,
              "Maximum extrapolation factor",
              "1e6",
              P::Double(0, 1e9),
              "adaptive: largest factor per iteration.",
              "none");
      declare(prm,
              "Target revolutions",
              "0",
              P::Double(0),
              "adaptive: total mechanism revolutions (cycles) to represent; required > 0 "
              "with adaptive extrapolation.",
              "cycles");
    }

    /** How the worn geometry reaches the clearance and pressure models. */
    void
    declare_model_entries(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Clearance model",
              "conformal",
              P::Selection("conformal|deepest-point|per-area"),
              "How the clearance joints carry the contact of worn (non-round) profiles "
              "(doc/models.md §1.5, §1.7): 'conformal' the resultant of the pressure over the "
              "whole arc where the rigid profiles overlap, as a function of the pin's "
              "displacement (an elastic foundation over the overlap that carries the normal "
              "force law of the round pair; with Normal force law = fe, the FE resultant); "
              "'deepest-point' the normal force law at the deepest overlap of the gap "
              "g(φ) = R1*(φ − θ_b) − R2*(φ − θ_p) − e·u(φ), along its radial direction, "
              "nominal stiffness; 'per-area' the seed's eqs 28–33 (the area facing the "
              "eccentricity decides c*(n), δ*(n), K*(n)). Round profiles use the point law "
              "with any choice. Applies to every clearance joint with a worn profile (from a "
              "profile file or from a wear iteration).",
              "none");
      declare(prm,
              "Conformal cells per area",
              "4",
              P::Integer(1, 64),
              "Cells per discrete bore area over which the conformal foundation integrates "
              "the pressure of the overlap (linear across a cell, integrated exactly): more "
              "resolve narrower contacts on worn profiles at proportional cost.",
              "none");
      declare(prm,
              "Pressure evaluation",
              "every step",
              P::Selection("every step|samples per cycle"),
              "When the pressure model is evaluated. The load history is always taken at "
              "every accepted integrator step (trapezoidal rule in time). 'every step': the "
              "model is evaluated for each loaded step; 'samples per cycle': once per "
              "window of 1/N cycle, at the window's largest load, and the steps of the "
              "window reuse that pressure shape, scaled to their own F_n and turned to their "
              "own contact direction in each body's frame (N model calls per cycle: the "
              "affordable setting for fe).",
              "none");
      declare(prm,
              "Wear update",
              "sequential",
              P::Selection("sequential|simultaneous"),
              "How an iteration's wear reaches the surfaces. 'sequential': the load states "
              "of the iteration are taken in time order and each one's wear, × the "
              "extrapolation factor, is removed from the pressure model's surfaces at once, "
              "so that the next state meets the worn surfaces (as f repetitions of the "
              "history would); each state is a step of the wear–pressure feedback, implicit "
              "for winkler and fe, split into stable parts for hertz-strip. 'simultaneous': "
              "every state is evaluated on the iteration's start geometry and the sum is "
              "extrapolated at the end (the seed's route): where a load dwells, one step × "
              "f digs far deeper than the contact's elastic approach and the profile grows "
              "saw-tooth spikes between neighbouring areas.",
              "none");
      declare(prm,
              "Wear integration",
              "euler",
              P::Selection("euler|adams-bashforth"),
              "How the iterations integrate the wear over the revolutions they stand for. "
              "An iteration's dynamics run on the profiles of its start, so its wear rate "
              "is that of the start: 'euler' applies it over the whole step, first order in "
              "the step (where the worn pocket draws the contact the deepest point lags by "
              "about half a step's change of rate: more, shorter iterations at the same "
              "simulated cycles reduce it at no cost). 'adams-bashforth' applies the rate "
              "extrapolated to the step's middle from this iteration's and the previous "
              "one's, (1 + ω/2) r_n − (ω/2) r_(n−1), ω = f_n / f_(n−1) ≤ 2, the change of "
              "rate taken over the contact width: second order in the mean, but it "
              "amplifies the iterations' chaotic samples (one run's scatter about doubles "
              "at 10 iterations). See doc/models.md §4.",
              "none");
      declare(prm,
              "Load samples per cycle",
              "100",
              P::Integer(8, 100000),
              "Pressure evaluations per cycle with Pressure evaluation = samples per cycle, 8 … "
              "1e5 (more windows than integrator steps give nothing).",
              "none");
      declare(prm,
              "Smoothing wavelength",
              "0",
              P::Double(0),
              "Low-pass filter of each iteration's depth increments (periodic Gaussian whose "
              "transfer is 1/2 at this wavelength along the surface; the volume is kept "
              "exactly). With Wear update = sequential the surfaces need none: the worn "
              "pockets conform to the pins and the profiles converge without it. It is kept "
              "for the simultaneous update, whose one explicit step × Extrapolation factor "
              "overshoots features shorter than the contact width (saw-tooth spikes between "
              "neighbouring areas): set it to about the contact width there. 0: no filter.",
              "m");
    }

    /** The before/after response and the profile plots. */
    void
    declare_output_entries(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Response cycles",
              "1",
              P::Double(0, 1e4),
              "Cycles of the dynamic response recorded before wear (start of the first "
              "iteration) and after wear (a run with the final profiles from the same "
              "initial state), both after the Settling cycles, for the before/after plot and "
              "the response ratios of summary.json, > 0 … 1e4 (the ratios compare whole "
              "cycles' peaks: below one cycle they compare the part simulated; with no "
              "settling cycles the mean per-cycle peak leaves out the first, the start-up).",
              "cycles");
      declare(prm,
              "Response body",
              "",
              P::Anything(),
              "Body whose acceleration is compared before and after wear; empty: the last "
              "body of Mechanism/Bodies.",
              "none");
      declare(prm,
              "FE output",
              "true",
              P::Bool(),
              "For joints on the fe pressure model: write into the run's folder fe/ the gmsh "
              "mesh in use (mesh_<J>_<k>.msh, k the iteration after which it was made) and, at "
              "the peak-load state of the last iteration k, the FE fields "
              "(fields_<J>_iteration<k>.vtu: displacement, stresses, von Mises, contact "
              "traction; _pressure.csv: contact pressure per node) with their ParaView "
              "collection fields_<J>.pvd, each replacing the one before as the run goes on "
              "(about 15 MB per joint at 25 µm surface elements; every iteration's: 'Output "
              "every iteration'). false writes none.",
              "none");
      declare(prm,
              "Output every iteration",
              "false",
              P::Bool(),
              "Keep the files of every wear iteration k: the profile frames "
              "profiles/profile_<J>_<k>.vtu (a ParaView series to play the wear, "
              "profiles_<J>.pvd) and, with FE output, every FE mesh and the FE fields of every "
              "iteration (about 10 MB per fe joint and iteration at 25 µm surface elements: "
              "400 MB for the 20 iterations of nine_bar_wear_fe.prm). false: only the frames "
              "of the unworn profiles (k = 0) and of the last iteration, and the last FE fields "
              "and mesh, each replacing the one before.",
              "none");
      declare(prm,
              "Profile magnification",
              "0",
              P::Double(0),
              "Magnification of the wear in the reconstructed-profile plots (plotted radius "
              "= R + M (R* − R)); 0 chooses M so that the deepest wear shows as 15 % of the "
              "radius. The plot title states it.",
              "none");
    }
  } // namespace

  void
  declare_wear_loop(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Wear");
    declare_iteration_entries(prm);
    declare_model_entries(prm);
    declare_output_entries(prm);
    prm.leave_subsection();
  }


  std::vector<std::string>
  inactive_wear_sections(const dealii::ParameterHandler &prm)
  {
    std::vector<std::string> inactive;
    const bool               wear = prm.get("Wear law") == "archard";
    if (!wear)
      {
        inactive.push_back("archard/");
        inactive.push_back("Pressure model");
      }
    for (const auto &name : contact::pressure_models().names())
      if (!wear || name != prm.get("Pressure model"))
        inactive.push_back(name + "/");
    return inactive;
  }


  std::unique_ptr<JointWear>
  read_joint_wear(ParameterReader &r, const std::string &joint)
  {
    if (r.get("Wear law") != "archard")
      return nullptr;
    auto w   = std::make_unique<JointWear>();
    w->joint = joint;
    r.enter("archard");
    w->archard.pin_coefficient     = r.get_double("Pin wear coefficient");
    w->archard.bushing_coefficient = r.get_double("Bushing wear coefficient");
    w->archard.pin_density         = r.get_positive("Pin density");
    w->archard.bushing_density     = r.get_positive("Bushing density");
    if (!(w->archard.pin_coefficient >= 0))
      r.fail("Pin wear coefficient", "it must be ≥ 0 m³/(N m)");
    if (!(w->archard.bushing_coefficient >= 0))
      r.fail("Bushing wear coefficient", "it must be ≥ 0 m³/(N m)");
    r.leave();
    EffectLedger::instance().record_construction("wear law", "archard");
    w->pressure_model = r.get("Pressure model");
    w->model          = contact::pressure_models().create(w->pressure_model, r, "Pressure model");
    return w;
  }


  WearLoopSettings
  read_wear_loop(ParameterReader &r)
  {
    WearLoopSettings s;
    r.enter("Wear");
    s.cycle_period         = r.get_double("Cycle period");
    s.cycles_per_iteration = r.get_double("Cycles per iteration");
    if (!(s.cycles_per_iteration > 0))
      r.fail("Cycles per iteration", "it must be > 0 cycles");
    s.settling_cycles      = r.get_double("Settling cycles");
    s.n_iterations         = static_cast<unsigned int>(r.get_integer("Number of iterations"));
    s.extrapolation        = r.get("Extrapolation") == "fixed" ? Extrapolation::fixed : Extrapolation::adaptive;
    s.extrapolation_factor = r.get_double("Extrapolation factor");
    s.max_depth_increment  = r.get_double("Maximum depth increment");
    s.max_factor           = r.get_double("Maximum extrapolation factor");
    s.target_revolutions   = r.get_double("Target revolutions");
    if (s.extrapolation == Extrapolation::fixed && !(s.extrapolation_factor >= 1))
      r.fail("Extrapolation factor", "it must be ≥ 1 (1: no extrapolation)");
    if (s.extrapolation == Extrapolation::adaptive)
      {
        if (!(s.target_revolutions > 0))
          r.fail("Target revolutions",
                 "it must be > 0 cycles with Extrapolation = adaptive",
                 "Set the number of mechanism revolutions the wear run should represent.");
        if (!(s.max_depth_increment > 0))
          r.fail("Maximum depth increment", "it must be > 0 m");
        if (!(s.max_factor >= 1))
          r.fail("Maximum extrapolation factor", "it must be ≥ 1");
      }
    const std::string form = r.get("Clearance model");
    s.clearance_form       = form == "conformal"     ? contact::ClearanceForm::conformal :
                             form == "deepest-point" ? contact::ClearanceForm::deepest_point :
                                                       contact::ClearanceForm::per_area;
    s.conformal_cells      = static_cast<unsigned int>(r.get_integer("Conformal cells per area"));
    s.evaluation =
      r.get("Pressure evaluation") == "every step" ? PressureEvaluation::every_step : PressureEvaluation::samples;
    s.update            = r.get("Wear update") == "sequential" ? WearUpdate::sequential : WearUpdate::simultaneous;
    s.step              = r.get("Wear integration") == "adams-bashforth" ? WearStep::adams_bashforth : WearStep::euler;
    s.samples_per_cycle = static_cast<unsigned int>(r.get_integer("Load samples per cycle"));
    s.smoothing_wavelength = r.get_double("Smoothing wavelength");
    s.response_cycles      = r.get_double("Response cycles");
    if (!(s.response_cycles > 0))
      r.fail("Response cycles",
             "it must be > 0 cycles",
             "Record at least part of a cycle before and after wear (1 or more for a response ratio "
             "of whole cycles).");
    s.response_body          = r.get("Response body");
    s.magnification          = r.get_double("Profile magnification");
    s.fe_output              = r.get_bool("FE output");
    s.every_iteration_output = r.get_bool("Output every iteration");
    r.leave();
    return s;
  }
} // namespace wearlink::wear
