// SPDX-License-Identifier: LGPL-2.1-or-later
// The contact kinematics of one load state: where the normal ray of each pin contact
// candidate meets the bore (contact_solver.h explains the discretization). The ray from
// the pin candidate x_i along its normal n_i meets the bore profile r = R1*(ψ) where
// |x + t n| = R1*(atan2(x + t n)): for a round bore the circle formula is exact,
// otherwise a few Newton steps on t follow. The initial gap g0_i is the ray's length,
// the contact point on the bore is interpolated onto the nodes of the bore face it
// falls in (the FE shape functions along that face).
#pragma once

#include "base/profile.h"
#include "fe/elasticity_problem.h"

#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>
#include <vector>

namespace wearlink::fe
{
  /** @p v rotated by @p angle [rad] (counter-clockwise). */
  inline dealii::Tensor<1, 2>
  rotate(const dealii::Tensor<1, 2> &v, const double angle)
  {
    const double         c = std::cos(angle), s = std::sin(angle);
    dealii::Tensor<1, 2> r;
    r[0] = c * v[0] - s * v[1];
    r[1] = s * v[0] + c * v[1];
    return r;
  }

  /**
   * Geometry of one load state: where the pin candidates meet the bore. The arrays are
   * indexed by position p in @p candidates, the pin candidates they describe (increasing
   * indices into ElasticityProblem::pin_nodes): every candidate for compute_kinematics(),
   * the contact window for compute_window_kinematics().
   */
  struct ContactKinematics
  {
    double                                   relative_angle = 0; ///< θ_pin − θ_bushing [rad]
    dealii::Tensor<1, 2>                     eccentricity;       ///< reference pin position, bushing frame [m]
    std::vector<unsigned int>                candidates;         ///< pin candidate of each position
    std::vector<double>                      g0;                 ///< initial gap [m]
    std::vector<dealii::Tensor<1, 2>>        normal;             ///< pin normal, bushing frame
    std::vector<double>                      bore_angle; ///< bushing-frame angle of the contact point on the bore
    std::vector<std::array<unsigned int, 3>> masters;    ///< bore nodes of the face met
    std::vector<std::array<double, 3>>       weights;    ///< their interpolation weights
    std::vector<unsigned char>               n_masters;
    double                                   tolerance = 0; ///< a gap this small [m] counts as closed (round-off)
  };

  /** Where the pin is for a load state: what its kinematics depend on. */
  struct PinPose
  {
    const Profile       *bore           = nullptr; ///< the bore profile the rays meet
    double               relative_angle = 0;       ///< θ_pin − θ_bushing [rad]
    dealii::Tensor<1, 2> eccentricity;             ///< pin centre − bore centre, bushing frame [m]
    /**
     * If given (one per pin candidate), each candidate is moved radially by that much
     * [m] before its ray is cast: the difference between the pin's current profile and
     * the meshed one, so that a mesh kept across small wear updates still sees the
     * current gaps (the normals and the compliance stay those of the mesh).
     */
    const std::vector<double> *pin_offsets = nullptr;
  };

  /**
   * Re-linearize @p kinematics about @p pose: the gaps of its candidates become the
   * exact ray lengths at the new pin position, while the pairing (the bore points and
   * nodes that each candidate's force acts on, and the normals) stays that of the pose
   * it was computed at. The contact solvers linearize the gap in the pin translation U
   * and refresh the gaps until U vanishes; keeping the pairing keeps the compliance
   * (and its factorization) of the first pose. The bore points move by less than U
   * tangentially (a few µm at 100 kN on the nine-bar joint, < 1/10 of a 25 µm element):
   * a choice of the discretization, the same in both solvers.
   */
  void
  refresh_gaps(const ElasticityProblem &problem, const PinPose &pose, ContactKinematics &kinematics);

  /** Cast every pin candidate's normal ray onto the bore (see PinPose). */
  ContactKinematics
  compute_kinematics(const ElasticityProblem &problem, const PinPose &pose);

  /**
   * Which candidates make the contact window (compute_window_kinematics): those whose
   * initial gap is at most T = max(at_least, g_min + above_smallest,
   * −overlap_factor × g_min), with g_min the smallest gap of the pose [m].
   */
  struct WindowThreshold
  {
    double at_least       = 0; ///< [m]
    double above_smallest = 0; ///< [m]
    double overlap_factor = 0; ///< [-]
  };

  /**
   * The kinematics of the contact window (see WindowThreshold). Every 8th candidate's
   * ray is cast (g_min is their smallest gap); between two of them the gap cannot fall
   * below their mean by more than L Δψ/2, with L = 2(|e| + max|R1*'| + max|R2*'|)
   * (twice a bound of |dg0/dψ|), so only the blocks that this bound cannot exclude are
   * cast candidate by candidate. @p threshold receives T [m].
   */
  ContactKinematics
  compute_window_kinematics(const ElasticityProblem &problem,
                            const PinPose           &pose,
                            const WindowThreshold   &rule,
                            double                  *threshold = nullptr);

  /**
   * Where a rigid pin pushed along the unit direction @p d (bushing frame) comes to rest
   * in the bore: the eccentricity e that maximizes d·e while the radial gap
   * c(φ) − e·u(φ), c(φ) = R1*(φ) − R2*(φ − θ), stays ≥ 0 (θ the pin's angle relative to
   * the bushing). The constraints e·u(φ_k) ≤ c(φ_k) at the profiles' sample directions
   * make a convex polygon; its vertex that d selects is found as the edge of the hull of
   * the polar points u(φ_k)/c(φ_k) that the ray along d leaves through (O(N)), then
   * moved along d onto the exact radial gap (contact::Gap). On a worn, nearly conformal
   * pocket the rest point lies off the load's line: the pin slides along the pocket
   * until the contact normal faces the load (the tangential part of e is the slope
   * c'(φ) of the clearance there). Round profiles: c(φ_d) d exactly.
   */
  dealii::Tensor<1, 2>
  rigid_rest_position(const Profile &bore, const Profile &pin, double relative_angle, const dealii::Tensor<1, 2> &d);

} // namespace wearlink::fe
