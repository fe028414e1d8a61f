// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/cylindrical_contact.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <cmath>

namespace wearlink::contact
{
  namespace
  {
    using numbers::pi;

    /** The constant of the bracket: −1 (Johnson) or +1 (ESDU-78035). */
    double
    bracket_constant(const CylindricalLaw law)
    {
      return law == CylindricalLaw::johnson ? -1.0 : 1.0;
    }
  } // namespace

  CylinderPair
  CylinderPair::of(const JointGeometry &g)
  {
    CylinderPair p;
    p.bore_radius       = g.bore.mean_radius();
    p.pin_radius        = g.pin.mean_radius();
    p.axial_length      = g.axial_length;
    p.effective_modulus = contact::effective_modulus(g.bushing, g.pin_material);
    return p;
  }

  double
  cylindrical_approach(const CylindricalLaw law, const CylinderPair &p, const double force)
  {
    const double P = force / p.axial_length, E = p.effective_modulus, dR = p.bore_radius - p.pin_radius;
    return P / (pi * E) * (std::log(4 * pi * E * dR / P) + bracket_constant(law));
  }

  double
  cylindrical_valid_max_force(const CylindricalLaw law, const CylinderPair &p)
  {
    // dδ/dP ∝ ln(4π E* ΔR/P) + c − 1 > 0; with a margin of 1: ln(4π E* ΔR/P) = 2 − c.
    const double E = p.effective_modulus, dR = p.bore_radius - p.pin_radius;
    return 4 * pi * E * dR * std::exp(-(2 - bracket_constant(law))) * p.axial_length;
  }

  double
  cylindrical_force(const CylindricalLaw law, const CylinderPair &p, const double approach)
  {
    if (!(approach > 0))
      return 0;
    double lo = std::log(1e-12), hi = std::log(cylindrical_valid_max_force(law, p));
    if (cylindrical_approach(law, p, std::exp(hi)) < approach)
      return std::nan(""); // beyond the law's validity
    while (hi - lo > 1e-12)
      {
        const double mid                                                   = 0.5 * (lo + hi);
        (cylindrical_approach(law, p, std::exp(mid)) < approach ? lo : hi) = mid;
      }
    return std::exp(0.5 * (lo + hi));
  }

  double
  winkler_round_force(const JointGeometry &g, const double thickness, const double approach)
  {
    if (!(approach > 0))
      return 0;
    const double Ec = series_foundation_modulus(g.bushing, g.pin_material);
    const double R1 = g.bore.mean_radius(), c = R1 - g.pin.mean_radius(), e = c + approach;
    const double phi0 = std::acos(c / e);
    return Ec * g.axial_length * R1 / thickness *
           (e * (phi0 + std::sin(phi0) * std::cos(phi0)) - 2 * c * std::sin(phi0));
  }

  ForceApproachTable
  tabulate_cylindrical_law(const CylindricalLaw law,
                           const CylinderPair  &pair,
                           const double         min_force,
                           const unsigned int   n_levels)
  {
    const double max_force = cylindrical_valid_max_force(law, pair);
    if (!(max_force > min_force) || n_levels < 2)
      throw InputError("The cylindrical contact law needs a load range: its largest valid force (" +
                       std::to_string(max_force) + " N) is not above the smallest tabulated one (" +
                       std::to_string(min_force) + " N).");
    std::vector<double> forces(n_levels), approach(n_levels);
    for (unsigned int k = 0; k < n_levels; ++k)
      {
        forces[k]   = min_force * std::pow(max_force / min_force, double(k) / (n_levels - 1));
        approach[k] = cylindrical_approach(law, pair, forces[k]);
      }
    return ForceApproachTable(forces, 1, 1, approach);
  }
} // namespace wearlink::contact
