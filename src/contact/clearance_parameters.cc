// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/clearance_parameters.h"

#include "base/numbers.h"
#include "base/text.h"
#include "contact/friction_law.h"
#include "contact/normal_force_law.h"

namespace wearlink::contact
{
  using dealii::ParameterHandler;
  namespace P = dealii::Patterns;

  /**
   * The entries of "Joint <name>/Clearance": geometry, materials, profiles, and every
   * registered normal force law and friction law (each in its own subsection; only the
   * chosen ones are read).
   */
  namespace
  {
    /** How a persisting contact is integrated (doc/models.md §1.6). */
    void
    declare_persistent_contact(ParameterHandler &prm)
    {
      declare(prm,
              "Persistent contact",
              "compliant",
              P::Selection("compliant|held"),
              "How a contact that persists is integrated (doc/models.md §1.6). 'compliant': the "
              "normal force law throughout, its normal mode (the pin on the bore's compliance, "
              "kHz) resolved by the integrator. 'held': after a step that ends in contact with "
              "|δ̇| below 'Hold velocity' and |δ̈| below 'Hold acceleration', the pin slides on "
              "the bore as a constraint whose multiplier is the normal force, the penetration "
              "at that force's quasi-static value; the compliant law takes over again when "
              "the force is no longer compressive, and at every impact. Round profiles only: "
              "worn ones are integrated with the compliant law.",
              "none");
      declare(prm,
              "Hold velocity",
              "1e-3",
              P::Double(0),
              "|δ̇| below which a persisting contact may be held ('Persistent contact = held').",
              "m/s");
      declare(prm,
              "Hold acceleration",
              "50",
              P::Double(0),
              "|δ̈| below which a persisting contact may be held: far below the deceleration of "
              "an impact at its deepest point ('Persistent contact = held').",
              "m/s²");
    }

    /** "Slices": the joint cut along its pin (doc/models.md §1.8; contact/axial_slices.h). */
    void
    declare_slices(ParameterHandler &prm)
    {
      prm.enter_subsection("Slices");
      declare(prm,
              "Axial slices",
              "1",
              P::Integer(1, max_axial_slices),
              "n: the joint is cut into n slices of Axial length / n along the pin, each with its "
              "own gap, pressure and wear, and the joint's planar force is their sum (doc/models.md "
              "§1.8). 1: the two-dimensional joint (pressure and wear uniform along the pin). "
              "Misalignment, a crown and an edge relief need n ≥ 2; 10 resolve the edge load of a "
              "misaligned pin to a few per cent of the largest slice force. At most 200.",
              "none");
      declare(prm,
              "Misalignment",
              "0",
              P::Double(0, 0.05),
              "γ, the tilt of the bore's axis against the pin's, 0 … 0.05 rad: the bore centre at "
              "height z along the pin lies z tan γ off the nominal one. Tolerances of bored joints "
              "are 1e-4 … 1e-3 rad; the offset over the half-length must stay inside the radial "
              "clearance, or the pin does not fit.",
              "rad");
      declare(prm,
              "Misalignment direction",
              "0",
              P::Double(-360, 360),
              "ψ, the direction of the tilt's axis in the bushing body's frame (0: its x axis): the "
              "bore centres move along (sin ψ, −cos ψ), opposite at the two ends of the bushing.",
              "deg");
      declare(prm,
              "Pin crown",
              "none",
              P::Selection("none|circular|logarithmic"),
              "The pin's profile along its axis. 'none': straight. 'circular': the radius falls by "
              "Crown drop × (2z/L)² towards the ends. 'logarithmic': Lundberg's profile "
              "2Q/(π E' L) ln(1/(1 − (2z/L)²)) for the design load Q = Crown design load, "
              "1/E' = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.",
              "none");
      declare(prm,
              "Crown drop",
              "0",
              P::Double(0, 1e-3),
              "The circular crown's radius loss at the pin's ends (Pin crown = circular), 0 … 1 mm.",
              "m");
      declare(prm,
              "Crown design load",
              "0",
              P::Double(0, 1e8),
              "Q of the logarithmic crown (Pin crown = logarithmic): the load under which it makes "
              "the axial pressure of an aligned stiff pin uniform in an elastic half-space.",
              "N");
      declare(prm,
              "Edge relief depth",
              "0",
              P::Double(0, 1e-3),
              "The bore's radius gain at the bushing's ends, growing as the square of the distance "
              "into the relief, 0 … 1 mm.",
              "m");
      declare(prm,
              "Edge relief length",
              "0",
              P::Double(0, 1),
              "How far the edge relief reaches in from each end of the bushing; at most half the "
              "Axial length.",
              "m");
      declare(prm,
              "Pin support",
              "rigid",
              P::Selection("rigid|pinned|clamped|cantilever"),
              "How the pin bends under the slices' forces (an Euler–Bernoulli beam, doc/models.md "
              "§1.8). 'rigid': it does not. 'pinned': simply supported, 'clamped': built in, both "
              "Support distance beyond the bushing's ends (a pin in a fork). 'cantilever': built in "
              "Support distance beyond the bushing's −z end, free at its other end (a pin pressed "
              "into one link). A bending pin sags away from the bore between its supports and loads "
              "the bushing's edges. Needs Axial slices ≥ 2.",
              "none");
      declare(prm,
              "Pin bending stiffness",
              "0",
              P::Double(0, 1e9),
              "EI of the pin (Pin support ≠ rigid). 0: a solid pin of the joint's pin radius r and "
              "Pin elastic modulus E, EI = E π r⁴/4; give it for a hollow or stepped pin.",
              "N m2");
      declare(prm,
              "Support distance",
              "0",
              P::Double(0, 1),
              "How far beyond the bushing's ends the pin is held (Pin support ≠ rigid), 0 … 1 m: "
              "the fork's half-width between the bushing and the middle of each cheek.",
              "m");
      prm.leave_subsection();
    }
  } // namespace

  void
  declare_clearance(ParameterHandler &prm)
  {
    declare(prm,
            "Bushing on",
            "body 2",
            P::Selection("body 1|body 2"),
            "Which body holds the bore (bushing); the other holds the pin. The joint's "
            "attachment points are the bore and pin centres.",
            "none");
    declare_required(prm,
                     "Bore radius",
                     P::Double(1e-6, 1),
                     "Nominal bore radius R1, 1 µm … 1 m (the range of pin joints; beyond it the "
                     "value is a mistake of units).",
                     "m");
    declare_required(prm,
                     "Radial clearance",
                     P::Double(0, 0.5),
                     "c = R1 − R2 (> 0); the pin radius is R1 − c. At most half the Bore radius: a "
                     "pin less than half the bore's size is no clearance joint (the contact laws "
                     "assume nearly conforming surfaces).",
                     "m");
    declare_required(prm,
                     "Axial length",
                     P::Double(1e-6, 1),
                     "Contact length along the pin axis (used by pressure models), 1 µm … 1 m.",
                     "m");
    declare_required(prm,
                     "Bushing elastic modulus",
                     P::Double(1e6, 1e13),
                     "E of the bushing, 1e6 … 1e13 Pa: from soft rubber (~1 MPa) to beyond diamond "
                     "(1.2e12 Pa); outside it the value is a mistake of units.",
                     "Pa");
    declare_required(prm, "Bushing Poisson ratio", P::Double(0, 0.5), "ν of the bushing, 0 ≤ ν < 0.5.", "none");
    declare_required(prm, "Pin elastic modulus", P::Double(1e6, 1e13), "E of the pin, 1e6 … 1e13 Pa.", "Pa");
    declare_required(prm, "Pin Poisson ratio", P::Double(0, 0.5), "ν of the pin, 0 ≤ ν < 0.5.", "none");
    declare(prm,
            "Effective radius",
            "internal",
            P::Selection("internal|seed-printed"),
            "Relative radius R* in the stiffness K = 4/(3(σ1 + σ2)) √R* (seed eq. 10): "
            "'internal' R1 R2/(R1 − R2), correct for a pin inside a bore; "
            "'seed-printed' R1 R2/(R1 + R2) as printed in the seed (≈5× softer here), "
            "only for reproducing the paper.",
            "none");
    declare_required(prm,
                     "Normal force law",
                     P::Selection(normal_force_laws().pattern()),
                     "Normal contact force law." + normal_force_laws().documentation(),
                     "none");
    declare_required(prm,
                     "Friction law",
                     P::Selection(friction_law_pattern()),
                     "Tangential force law. 'none': no tangential force is computed." + friction_laws().documentation(),
                     "none");
    declare(prm,
            "Initial eccentricity",
            "0, 0",
            point_pattern(),
            "Pin centre − bore centre at assembly, in the bushing body's frame.",
            "m");
    declare(prm,
            "Bore profile file",
            "",
            P::Anything(),
            "CSV (angle_rad, radius_m) of a worn bore in the bushing's frame; empty: "
            "round. Relative paths are taken from the scene file's folder.",
            "none");
    declare(prm,
            "Pin profile file",
            "",
            P::Anything(),
            "CSV (angle_rad, radius_m) of a worn pin in the pin body's frame; empty: "
            "round.",
            "none");
    declare(prm,
            "Number of discrete areas",
            "360",
            P::Integer(8, max_discrete_areas),
            "Samples of each surface profile (discrete areas for wear), 8 … 100000: at 1e5 "
            "areas an area of a 10-mm bore is 0.6 µm wide, finer than its roughness and than "
            "any FE mesh of it; more would only exhaust memory.",
            "none");
    declare_persistent_contact(prm);
    declare_slices(prm);
    normal_force_laws().declare_all(prm);
    friction_laws().declare_all(prm);
  }

  ClearanceSize
  read_clearance_size(ParameterReader &r)
  {
    ClearanceSize s;
    s.bore_radius          = r.get_positive("Bore radius");
    s.radial_clearance     = r.get_double("Radial clearance");
    const double bore      = s.bore_radius;
    const double clearance = s.radial_clearance;
    if (!(clearance > 0))
      r.fail("Radial clearance",
             "it must be > 0 m",
             "A clearance joint needs a gap; use Model = ideal for a joint without one.");
    if (!(clearance < bore))
      r.fail("Radial clearance",
             "it must be smaller than the Bore radius (" + format_number(bore) +
               " m): the pin radius R1 − c would be ≤ 0 (pin larger than the bore)");
    if (!(clearance <= 0.5 * bore))
      r.fail("Radial clearance",
             "it must be at most half the Bore radius (" + format_number(0.5 * bore, 4) +
               " m): the pin would be less than half the bore's size, no clearance joint",
             "Radial clearances of pin joints are micrometres to a few tenths of a millimetre.");
    s.n_areas = static_cast<unsigned int>(r.get_integer("Number of discrete areas"));
    return s;
  }

  void
  read_clearance_materials(ParameterReader &r, ClearanceJointDescription &d)
  {
    d.geometry.axial_length                = r.get_positive("Axial length");
    d.geometry.bushing.youngs_modulus      = r.get_positive("Bushing elastic modulus");
    d.geometry.bushing.poisson_ratio       = r.get_double("Bushing Poisson ratio");
    d.geometry.pin_material.youngs_modulus = r.get_positive("Pin elastic modulus");
    d.geometry.pin_material.poisson_ratio  = r.get_double("Pin Poisson ratio");
    if (!(d.geometry.bushing.poisson_ratio < 0.5))
      r.fail("Bushing Poisson ratio", "it must be < 0.5 (incompressible is not allowed)");
    if (!(d.geometry.pin_material.poisson_ratio < 0.5))
      r.fail("Pin Poisson ratio", "it must be < 0.5 (incompressible is not allowed)");
    d.effective_radius =
      r.get("Effective radius") == "internal" ? EffectiveRadius::internal : EffectiveRadius::seed_printed;
    d.hold_persistent_contact = r.get("Persistent contact") == "held";
    d.hold_velocity           = r.get_double("Hold velocity");
    d.hold_acceleration       = r.get_double("Hold acceleration");
  }

  SliceLayout
  read_slice_layout(ParameterReader &r, const ClearanceJointDescription &d)
  {
    SliceLayout l;
    r.enter("Slices");
    l.count                     = static_cast<unsigned int>(r.get_integer("Axial slices"));
    l.misalignment              = r.get_double("Misalignment");
    l.tilt_direction            = r.get_double("Misalignment direction") * numbers::pi / 180;
    const std::string crown     = r.get("Pin crown");
    l.crown                     = crown == "circular"    ? PinCrown::circular :
                                  crown == "logarithmic" ? PinCrown::logarithmic :
                                                           PinCrown::none;
    l.crown_drop                = r.get_double("Crown drop");
    l.crown_load                = r.get_double("Crown design load");
    l.relief_depth              = r.get_double("Edge relief depth");
    l.relief_length             = r.get_double("Edge relief length");
    const std::string support   = r.get("Pin support");
    l.bending.support           = support == "pinned"     ? PinSupport::pinned :
                                  support == "clamped"    ? PinSupport::clamped :
                                  support == "cantilever" ? PinSupport::cantilever :
                                                            PinSupport::rigid;
    l.bending.bending_stiffness = r.get_double("Pin bending stiffness");
    l.bending.support_distance  = r.get_double("Support distance");
    const double length         = d.geometry.axial_length;
    const auto   needs_slices   = [&](const std::string &entry) {
      if (l.count < 2)
        r.fail(entry,
               "it acts along the pin, and the joint has one slice (Axial slices = 1)",
               "Set Axial slices ≥ 2 (10 resolve an edge load), or leave " + entry + " at its default.");
    };
    if (l.misalignment > 0)
      needs_slices("Misalignment");
    if (l.crown != PinCrown::none)
      needs_slices("Pin crown");
    if (l.relief_depth > 0)
      needs_slices("Edge relief depth");
    if (l.bending.support != PinSupport::rigid)
      needs_slices("Pin support");
    if (l.crown == PinCrown::circular && !(l.crown_drop > 0))
      r.fail("Crown drop", "it must be > 0 m with Pin crown = circular");
    if (l.crown == PinCrown::logarithmic && !(l.crown_load > 0))
      r.fail("Crown design load", "it must be > 0 N with Pin crown = logarithmic");
    if (l.relief_depth > 0 && !(l.relief_length > 0 && l.relief_length <= 0.5 * length))
      r.fail("Edge relief length",
             "it must be > 0 and at most half the Axial length (" + format_number(0.5 * length) +
               " m) with an Edge relief depth");
    if (l.count > 1 && d.hold_persistent_contact)
      r.fail("Axial slices",
             "a sliced joint is integrated with the compliant law (Persistent contact = held holds one contact)",
             "Set Persistent contact = compliant, or Axial slices = 1.");
    if (l.count > 1 && d.normal_force_law == "fe")
      r.fail("Axial slices",
             "the fe normal force law tabulates the whole joint's FE model; a slice has no table of its own",
             "Use a closed-form normal force law with slices (the fe pressure model acts per slice), or Axial "
             "slices = 1.");
    r.leave();
    return l;
  }

  void
  check_friction_coefficient(const std::string &joint, const double mu, ValidityWarnings &warnings)
  {
    warnings.check({"joint " + joint + ": Clearance friction coefficient",
                    mu,
                    1.0,
                    "",
                    "dry metal pairs 0.1 … 0.8, lubricated 0.05 … 0.15; above 1 only clean metals in vacuum and "
                    "elastomers",
                    "a friction force larger than the normal force; check the value"});
  }
} // namespace wearlink::contact
