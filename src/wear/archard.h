// SPDX-License-Identifier: LGPL-2.1-or-later
// Archard's wear law on both surfaces of a clearance joint (doc/models.md §4):
//     dh = k_D p ds,   ds = |v_t| dt,
// accumulated per discrete area of each surface in its own body frame: the bore's areas
// are fixed in the bushing body, the pin's in the pin body, and the pressure model maps
// the contact pressure onto both (the pin turns relative to the bushing, so a pin area
// passes through the contact once per relative revolution while the bore's loaded area
// follows the load direction).
//
// A load history is a list of samples (state of the joint + quadrature weight in time);
// add() evaluates the pressure model for one sample and adds weight × dh/dt. Two volumes
// are kept per surface:
//   - the local volume  Σ_k h_k A_k (A_k = L R_k Δψ, the area's surface), which the
//     profile update removes;
//   - the global Archard volume k_D ∫ F_n |v_t| dt. Every pressure model carries the
//     load as the resultant of its pressure, Σ_k p_k A_k u_k = F_n u(φ*)
//     (contact/pressure_model.h), so Σ_k p_k A_k = F_n / ⟨cos⟩ ≥ F_n, ⟨cos⟩ the
//     pressure-weighted mean cosine of the contact arc: the two volumes agree for a
//     narrow contact (a Hertz strip of half-angle ε: 1 + ε²/8) and the local one exceeds
//     the global one on a wide conformal arc (3.5 % for a ±30° strip). That is local
//     Archard on a curved conformal contact, not an error, and the local form is the
//     one that is removed from the profiles.
//
// Two ways to apply an iteration's wear (Wear/Wear update):
//   - simultaneous: every state of the history is evaluated on the iteration's start
//     geometry and the sum is extrapolated by f at the end (the seed's route). Where a
//     load dwells, one explicit step × f digs far deeper than the contact's elastic
//     approach (tens of µm against ~0.1 µm): the next iteration's contact sits on the
//     trench's edges, and the profile grows saw-tooth spikes between neighbouring areas.
//   - sequential: the states are taken in time order and each state's wear, × f, is
//     removed from the pressure model's surfaces at once (PressureModel::remove_material),
//     so that the next state meets the worn surfaces, as the wear of f repetitions of the
//     history would. Each state is a step of the wear–pressure feedback with the wear
//     compliance c = f k_D |v_t| Δt [m/Pa]: implicit models (winkler, fe) take it in one
//     step; an explicit one (hertz-strip) splits a state whose c exceeds its
//     stable_compliance() into equal parts evaluated one after the other. The depths
//     kept here are still per factor 1 (the update applies f × them), so the volumes
//     and the records are as in the simultaneous update.
#pragma once

#include "contact/pressure_model.h"

#include <vector>

namespace wearlink::wear
{
  /** One state of a joint in a load history, with its weight in the time quadrature. */
  struct LoadSample
  {
    contact::ContactLoad load;
    double               sliding_speed = 0; ///< |v_t| [m/s]
    double               weight        = 0; ///< quadrature weight [s]
    double               time          = 0; ///< [s]
  };

  /**
   * Whether two load histories are the same bit for bit (the slices of an aligned joint
   * record the same loads; wear/wear_loop.h shares their wear).
   */
  bool
  identical_histories(const std::vector<LoadSample> &a, const std::vector<LoadSample> &b);

  class ArchardAccumulator
  {
  public:
    /**
     * @param geometry the joint's current geometry (sizes the depth buffers).
     * @param bore_coefficient, pin_coefficient k_D of each surface [m³/(N m)].
     * @param model the joint's pressure model (geometry already set).
     */
    ArchardAccumulator(const contact::JointGeometry &geometry,
                       double                        bore_coefficient,
                       double                        pin_coefficient,
                       contact::PressureModel       &model);

    /**
     * Apply the wear sequentially with extrapolation factor @p factor (> 0; see the file
     * comment), or simultaneously (0, the default). Set before adding samples.
     */
    void
    set_sequential_factor(double factor)
    {
      sequential_factor = factor;
    }

    /** Add the wear of one sample: weight × k_D p |v_t| on every area. */
    void
    add(const LoadSample &sample);

    /**
     * Add the wear of @p sample with the pressure shape the model computed for
     * @p key (@p key_pressure): scaled by F_n/F_n,key and turned, on each surface, by
     * the change of the contact direction in that surface's frame (fractional shift by
     * linear interpolation, which conserves Σ p on a periodic grid). No model call;
     * the sequential update wears the surfaces after the whole window (add_history).
     */
    void
    add_shaped(const LoadSample &sample, const LoadSample &key, const contact::SurfacePressure &key_pressure);

    /**
     * Add a whole history. every_step: add() per sample. samples: the history is cut
     * into windows of @p window seconds from @p t0; the model is evaluated once per
     * window, at its sample of largest F_n, and every sample of the window uses that
     * shape (add_shaped). This is the "N load samples per cycle" knob: N model calls per
     * cycle, while the load magnitude, sliding and contact direction still follow every
     * integrator step.
     */
    void
    add_history(const std::vector<LoadSample> &history, bool every_step, double window, double t0);

    /** Forget the accumulated depths and volumes. */
    void
    clear();

    /** Replace the geometry (after a profile update); clears. */
    void
    set_geometry(const contact::JointGeometry &g);

    /** Depth per bore area [m] (bushing frame, area k at ψ_k = 2πk/N). */
    const std::vector<double> &
    bore_depth() const
    {
      return bore_depth_;
    }
    /** Depth per pin area [m] (pin frame). */
    const std::vector<double> &
    pin_depth() const
    {
      return pin_depth_;
    }

    /** Surface of one bore / pin area, L R_k Δψ [m²]. */
    double
    bore_area(unsigned int k) const;
    double
    pin_area(unsigned int k) const;

    double bore_volume          = 0; ///< Σ_k h_k A_k of the bore, accumulated [m³]
    double pin_volume           = 0; ///< Σ_k h_k A_k of the pin [m³]
    double bore_archard         = 0; ///< k_D ∫ F_n |v_t| dt with the bore's k_D [m³]
    double pin_archard          = 0; ///< the same with the pin's k_D [m³]
    double sliding_distance     = 0; ///< ∫ |v_t| dt over the loaded samples [m]
    long   pressure_evaluations = 0;
    /** Sequential update: load states split because their wear compliance exceeded the model's stable one. */
    long split_states = 0;

  private:
    void
    deposit(const LoadSample &s, const std::vector<double> &bore, const std::vector<double> &pin);

    /** The wear compliance of @p s scaled by @p scale, for the sequential factor. */
    contact::WearCompliance
    compliance(const LoadSample &s, double scale) const;

    /** Sequential update: remove factor × the pending depths from the model's surfaces. */
    void
    flush();

    /** Into how many parts a state of wear compliance @p c is split (sequential update). */
    unsigned int
    parts(const contact::ContactLoad &load, const contact::WearCompliance &c);

    /** One window of the history (samples update): its key's shape on every sample. */
    void
    add_window(const std::vector<LoadSample> &h, std::size_t begin, std::size_t end, std::size_t key);

    /** Depth added since the last flush, per area, and the areas it touched. */
    struct Pending
    {
      std::vector<double>       depth;
      std::vector<unsigned int> areas;
      void
      add(unsigned int k, double dh)
      {
        if (depth[k] == 0)
          areas.push_back(k);
        depth[k] += dh;
      }
    };

    contact::JointGeometry   geometry;
    const double             k_bore, k_pin;
    contact::PressureModel  &model;
    contact::SurfacePressure pressure;
    std::vector<double>      bore_depth_, pin_depth_, shifted_bore, shifted_pin;
    double                   sequential_factor = 0;
    Pending                  pending_bore, pending_pin;
    contact::SurfaceWear     removed; ///< scratch of flush()
  };
} // namespace wearlink::wear
