// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/profile.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace wearlink
{
  namespace
  {
    using numbers::two_pi;
    constexpr unsigned int min_points = 8;

    /** Position of @p psi in sample units: index k and fraction f in [0, 1). */
    void
    locate(double psi, unsigned int n, unsigned int &k, double &f)
    {
      double s = psi / two_pi;
      s -= std::floor(s);
      double x = s * n;
      if (x >= n)
        x -= n;
      k = static_cast<unsigned int>(x);
      if (k >= n)
        k = n - 1;
      f = x - k;
    }
  } // namespace

  Profile
  Profile::round(double radius, unsigned int n_points)
  {
    Profile p;
    p.r.assign(n_points, radius);
    p.check("round profile");
    return p;
  }

  Profile
  Profile::from_samples(std::vector<double> radii, const std::string &what)
  {
    Profile p;
    p.r = std::move(radii);
    p.check(what);
    return p;
  }

  Profile
  Profile::from_polar_points(const std::vector<double> &angles,
                             const std::vector<double> &radii,
                             const unsigned int         n_points,
                             const std::string         &what)
  {
    if (angles.size() != radii.size())
      throw InputError("The " + what + " has " + std::to_string(angles.size()) + " angles but " +
                       std::to_string(radii.size()) + " radii.");
    for (std::size_t k = 1; k < angles.size(); ++k)
      if (!(angles[k] > angles[k - 1]))
        throw InputError("In the " + what + ", the angles must increase strictly (point " + std::to_string(k) +
                         " does not): a profile that turns back on itself is self-intersecting.");
    if (angles.size() < min_points)
      throw InputError("The " + what + " has " + std::to_string(angles.size()) + " points; at least " +
                       std::to_string(min_points) + " are needed.");
    if (!(angles.back() - angles.front() < two_pi))
      throw InputError("In the " + what +
                       ", the angles span more than one turn (2π rad): the profile would "
                       "overlap itself.");

    const unsigned int n = n_points == 0 ? static_cast<unsigned int>(angles.size()) : n_points;
    if (n_points == 0)
      {
        const double step = two_pi / n;
        for (unsigned int k = 0; k < n; ++k)
          if (std::abs(angles[k] - angles[0] - k * step) > 1e-6 * step)
            throw InputError("The " + what +
                             " is not uniformly spaced over 2π; give the number of "
                             "discrete areas so that it can be resampled.");
        // Already on the grid ψ_k = 2πk/N: keep the samples as they are. Otherwise
        // (grid shifted by a0) fall through to the resampling below.
        if (std::abs(angles[0]) <= 1e-12)
          return from_samples(radii, what);
      }
    // Periodic linear resampling onto ψ_k = 2πk/n.
    const std::size_t   m = angles.size();
    std::vector<double> out(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        double psi = two_pi * k / n;
        // bring psi into [angles[0], angles[0] + 2π)
        psi -= two_pi * std::floor((psi - angles[0]) / two_pi);
        std::size_t  j  = std::upper_bound(angles.begin(), angles.end(), psi) - angles.begin();
        const double a0 = angles[j - 1];
        const double r0 = radii[j - 1];
        const double a1 = j < m ? angles[j] : angles[0] + two_pi;
        const double r1 = j < m ? radii[j] : radii[0];
        out[k]          = r0 + (r1 - r0) * (psi - a0) / (a1 - a0);
      }
    return from_samples(out, what);
  }

  double
  Profile::angle(unsigned int k) const
  {
    return two_pi * k / r.size();
  }

  double
  Profile::radius(double psi) const
  {
    unsigned int k;
    double       f;
    const auto   n = n_points();
    locate(psi, n, k, f);
    const unsigned int k1 = k + 1 == n ? 0 : k + 1;
    return r[k] + f * (r[k1] - r[k]);
  }

  double
  Profile::slope(double psi) const
  {
    unsigned int k;
    double       f;
    const auto   n = n_points();
    locate(psi, n, k, f);
    const unsigned int k1 = k + 1 == n ? 0 : k + 1;
    return (r[k1] - r[k]) * n / two_pi;
  }

  double
  Profile::min_radius() const
  {
    return *std::min_element(r.begin(), r.end());
  }

  double
  Profile::max_radius() const
  {
    return *std::max_element(r.begin(), r.end());
  }

  double
  // The deviations from the first sample are summed, so that a round profile's mean is
  // its radius exactly whatever its sample count (a sum of N equal radii / N is not: the
  // clearance of a round joint would then differ in its last bit with the number of
  // discrete areas, and the chaotic dynamics would diverge from it).
  Profile::mean_radius() const
  {
    const double r0        = r.front();
    double       deviation = 0;
    for (const double x : r)
      deviation += x - r0;
    return r0 + deviation / r.size();
  }

  bool
  Profile::is_round() const
  {
    const double r0 = r.front();
    for (const double x : r)
      if (std::abs(x - r0) > 1e-15 * r0)
        return false;
    return true;
  }

  double
  Profile::enclosed_area() const
  {
    // ∫ ½ R(ψ)² dψ with R linear on each interval: ½ h (a² + ab + b²)/3.
    const auto   n = n_points();
    const double h = two_pi / n;
    double       a = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double r0 = r[k];
        const double r1 = r[k + 1 == n ? 0 : k + 1];
        a += (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
      }
    return 0.5 * h * a;
  }

  void
  Profile::check(const std::string &what) const
  {
    if (r.size() < min_points)
      throw InputError("The " + what + " has " + std::to_string(r.size()) + " points; at least " +
                       std::to_string(min_points) + " are needed.");
    for (std::size_t k = 0; k < r.size(); ++k)
      if (!std::isfinite(r[k]) || !(r[k] > 0))
        throw InputError("The " + what + " has radius " + std::to_string(r[k]) + " m at point " + std::to_string(k) +
                         "; every radius must be a finite number > 0.");
  }
} // namespace wearlink
