// SPDX-License-Identifier: LGPL-2.1-or-later
// Archard's wear law on both surfaces of a clearance joint (REFERENCE.md §4):
//     dh = k_D p ds,   ds = |v_t| dt,
// accumulated per discrete area of each surface in its own body frame: the bore's areas
// are fixed in the bushing body, the pin's in the pin body, and the pressure model maps
// the contact pressure onto both (the pin turns relative to the bushing, so a pin area
// passes through the contact once per relative revolution while the bore's loaded area
// follows the load direction).
//
// Two volumes are kept per surface:
//   - the local volume  Σ_k h_k A_k (A_k = L R Δψ, the area's surface), which the
//     profile update removes, and which equals k_D ∫ (Σ_k p_k A_k) |v_t| dt exactly;
//   - the global Archard volume k_D ∫ F_n |v_t| dt. The two agree when the contact arc
//     is narrow (Σ p A = F_n); for wide conformal arcs Σ p A > F_n (the load is the
//     vector sum of pressures), which is why the local form is the one that matters.
#pragma once

#include "contact/pressure_model.h"

#include <vector>

namespace wearlink::wear
{
  /** Wear-rate of one joint state: dh/dt per area and the volume rates. */
  struct WearRate
  {
    std::vector<double> bore;            ///< dh/dt per bore area [m/s]
    std::vector<double> pin;             ///< dh/dt per pin area [m/s]
    double              bore_volume = 0; ///< Σ dh/dt A (local) [m³/s]
    double              pin_volume  = 0;
    double              bore_archard = 0; ///< k_D F_n |v_t| (global) [m³/s]
    double              pin_archard  = 0;
    double              sliding_speed = 0; ///< |v_t| [m/s]
    bool                active = false;    ///< in contact with a non-zero rate
  };

  class ArchardAccumulator
  {
  public:
    /**
     * @param bore_coefficient, pin_coefficient k_D of each surface [m³/(N m)].
     * @param model the joint's pressure model (geometry already set).
     */
    ArchardAccumulator(const contact::JointGeometry &geometry,
                       double                        bore_coefficient,
                       double                        pin_coefficient,
                       contact::PressureModel &      model);

    /** The wear rate at one state (evaluates the pressure model if loaded). */
    void
    rate(const contact::ContactLoad &load, double sliding_speed, WearRate &out);

    /** Accumulate @p weight × @p r (weight: a time span [s]). */
    void
    add(const WearRate &r, double weight);

    /** Forget the accumulated depths (start of a wear iteration). */
    void
    clear();

    /** Replace the geometry (after a profile update). */
    void
    set_geometry(const contact::JointGeometry &g);

    const std::vector<double> &
    bore_depth() const
    {
      return bore_depth_;
    }
    const std::vector<double> &
    pin_depth() const
    {
      return pin_depth_;
    }
    double bore_volume  = 0; ///< local [m³]
    double pin_volume   = 0;
    double bore_archard = 0; ///< global k_D ∫F|v|dt [m³]
    double pin_archard  = 0;
    double sliding_distance = 0; ///< ∫|v_t| dt while loaded [m]
    long   pressure_evaluations = 0;

    /** Surface area of one bore / pin area, L R Δψ [m²]. */
    double
    bore_area(unsigned int k) const;
    double
    pin_area(unsigned int k) const;

  private:
    contact::JointGeometry  geometry;
    const double            k_bore, k_pin;
    contact::PressureModel &model;
    contact::SurfacePressure pressure;
    std::vector<double>     bore_depth_, pin_depth_;
  };
} // namespace wearlink::wear
