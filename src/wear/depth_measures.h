// SPDX-License-Identifier: LGPL-2.1-or-later
// What a worn profile's depth says as a result:
//   - the raw largest depth: the deepest discrete area;
//   - the envelope depth: the largest running median of the depth over the contact
//     width — the depth a contact of that width meets. A feature narrower than the
//     contact (one area's spike) does not set it; a pocket wider than the contact does.
//     The life's depth and clearance criteria use it;
//   - the roughness: the largest deviation of the depth from its local least-squares
//     parabola over the contact width (Savitzky–Golay, degree 2), relative to the
//     largest depth. A parabola follows a smooth pocket's curvature exactly, so a smooth
//     profile reads ~0 whatever its shape, while a saw-tooth between neighbouring areas
//     reads its amplitude. Above 5 % the run warns (the profile is not resolved).
// The contact width: 2b of the Hertz line contact of the joint's unworn radii at a
// reference force (the largest normal force of the run's first iteration), at least
// three discrete areas; the window holds the odd number of areas nearest to it.
#pragma once

#include <vector>

namespace wearlink::wear
{
  /** Above this roughness the worn profile is flagged as not resolved [-]. */
  constexpr double roughness_limit = 0.05;

  /**
   * The window of a profile of @p n_areas areas around radius @p radius [m] for the
   * contact width @p width [m]: an odd number of areas, at least 3 and at most n_areas.
   */
  unsigned int
  window_areas(double width, double radius, unsigned int n_areas);

  /** Largest depth [m] (0 for an empty profile). */
  double
  largest_depth(const std::vector<double> &depth);

  /** Largest running median of the periodic @p depth over @p window areas (odd) [m]. */
  double
  envelope_depth(const std::vector<double> &depth, unsigned int window);

  /**
   * Largest |depth − its local parabola over @p window areas| / largest depth [-]
   * (0 for a profile without wear).
   */
  double
  roughness(const std::vector<double> &depth, unsigned int window);

  /**
   * 2b of the Hertz line contact [m] of a pin of radius @p pin_radius in a bore of
   * @p bore_radius, effective modulus @p effective_modulus [Pa], axial length
   * @p length [m], under @p force [N].
   */
  double
  hertz_contact_width(double force, double bore_radius, double pin_radius, double effective_modulus, double length);
} // namespace wearlink::wear
