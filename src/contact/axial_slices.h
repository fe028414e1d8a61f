// SPDX-License-Identifier: LGPL-2.1-or-later
// A clearance joint cut into slices along the pin (doc/models.md §1.8). The joint's
// axial length L is divided into n slices of length L/n centred at
//     z_i = (i + 1/2) L/n − L/2,   i = 0 … n−1,
// measured from the bushing's mid-plane along the pin. Each slice is a clearance joint
// of its own (contact/clearance_joint.h: own profiles, own gap, own wear) whose stiffness
// is the share 1/n of the joint's: n aligned slices carry what the joint carries. What
// makes the slices differ is where they sit along the pin:
//   - misalignment: the bore's axis is tilted by γ against the pin's about an in-plane
//     axis at angle ψ in the bushing's frame, so the bore centre at height z lies at
//         z tan γ (sin ψ, −cos ψ)
//     from the nominal one (a straight pin in a bore machined askew: the offset is fixed
//     in the bushing's frame);
//   - pin crown: the pin radius falls by c(z) towards its ends:
//         circular     c(z) = c_e (2z/L)²               (c_e the drop at the ends)
//         logarithmic  c(z) = 2Q/(π E' L) ln(1/(1 − (2z/L)²))   (Lundberg's profile for
//                      the design load Q, 1/E' = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂)
//   - edge relief: the bore radius grows by r_d ((|z| − (L/2 − ℓ))/ℓ)² within ℓ of each
//     end of the bushing.
// The joint's planar force is the sum of its slices' (the mechanism adds them as force
// elements); the moment Σ z_i F_i about the in-plane axes — the edge load — and the
// axial position of the resultant are what the planar model cannot carry and reports.
#pragma once

#include "contact/elastic_pin.h"
#include "contact/pressure_model.h"
#include "contact/shared_fields.h"
#include "mbs/types.h"

#include <memory>
#include <string>
#include <vector>

namespace wearlink::contact
{
  enum class PinCrown
  {
    none,
    circular,
    logarithmic
  };

  /** How a clearance joint is sliced along its pin (the scene's entries). */
  struct SliceLayout
  {
    unsigned int count          = 1; ///< n ≥ 1 (1: the two-dimensional joint)
    double       misalignment   = 0; ///< γ [rad]
    double       tilt_direction = 0; ///< ψ, the tilt's axis in the bushing's frame [rad]
    PinCrown     crown          = PinCrown::none;
    double       crown_drop     = 0; ///< circular: c_e [m]
    double       crown_load     = 0; ///< logarithmic: Q [N]
    double       relief_depth   = 0; ///< r_d [m]
    double       relief_length  = 0; ///< ℓ [m]
    PinBending   bending;            ///< rigid, or how the pin bends (contact/elastic_pin.h)
  };

  /** z_i of slice @p i of @p n over the length @p length [m]. */
  double
  slice_position(unsigned int i, unsigned int n, double length);

  /** The bore centre at height @p z from the nominal one, bushing frame [m]. */
  mbs::Vec2
  bore_offset(const SliceLayout &layout, double z);

  /** The pin's radius loss c(z) of the crown at height @p z [m] (≥ 0). */
  double
  crown_drop(const SliceLayout &layout, double z, double length, const Material &bushing, const Material &pin);

  /** The bore's radius gain of the edge relief at height @p z [m] (≥ 0). */
  double
  relief_gain(const SliceLayout &layout, double z, double length);

  /** What a slice of a sliced joint knows about its place (ClearanceJointDescription::slice). */
  struct AxialSlice
  {
    std::string  joint;             ///< the sliced joint's name
    unsigned int index    = 0;      ///< i
    unsigned int count    = 1;      ///< n
    double       position = 0;      ///< z_i [m]
    double       share    = 1;      ///< 1/n: of the joint's length and stiffness
    mbs::Vec2    bore_offset{0, 0}; ///< bore centre − nominal bore centre, bushing frame [m]
    /**
     * The mean radii of the slice's bore and pin before its crown and relief [m]: its K
     * and its conformal foundation are the joint's, computed from them.
     */
    double nominal_bore_radius = 0, nominal_pin_radius = 0;
    /** The joint's bending pin, shared by its slices (nullptr: rigid). */
    std::shared_ptr<const ElasticPin> elastic_pin;
    /** Where the joint's slices find the conformal field of a slice whose geometry is theirs (contact/shared_fields.h). */
    std::shared_ptr<FieldPool> field_pool;
  };

  struct ClearanceJointDescription;

  /**
   * The bending pin of @p joint sliced as @p layout says (its EI, when not given, of a
   * solid pin of the joint's pin radius and modulus: E π r⁴/4), or nullptr for a rigid
   * pin. Its slices get it in their AxialSlice and attach to it once built.
   */
  std::shared_ptr<ElasticPin>
  make_elastic_pin(const ClearanceJointDescription &joint, const SliceLayout &layout);

  /** The number of slice @p i of @p n as names and files carry it ("03": two digits, three from 100 slices). */
  std::string
  slice_number(unsigned int i, unsigned int n);

  /** The name of slice @p i of @p n of joint @p joint ("B.s03"; the joint's own for n = 1). */
  std::string
  slice_name(const std::string &joint, unsigned int i, unsigned int n);
} // namespace wearlink::contact
