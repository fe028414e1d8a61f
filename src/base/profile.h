// SPDX-License-Identifier: LGPL-2.1-or-later
// A discrete surface profile of a pin or a bore: the radius R*(ψ) measured from the
// body's joint centre, sampled at N uniformly spaced body-frame angles ψ_k = 2πk/N.
// Sample k is the centre of discrete area k (the wear layer accumulates depth per area).
// Between samples the radius is interpolated linearly and periodically.
// Round profiles are the special case R*(ψ) = R (doc/models.md §1.5, seed eqs 28–33).
#pragma once

#include <string>
#include <vector>

namespace wearlink
{
  class Profile
  {
  public:
    Profile() = default;

    /** A circle of radius @p radius [m] sampled at @p n_points angles. */
    static Profile
    round(double radius, unsigned int n_points);

    /** Uniform samples R(ψ_k), k = 0..N-1; checks validity (see check()). */
    static Profile
    from_samples(std::vector<double> radii, const std::string &what = "profile");

    /**
     * A profile from polar points (angle [rad], radius [m]) whose angles increase
     * strictly within one turn [a0, a0 + 2π): resampled linearly and periodically onto
     * @p n_points uniform angles (n_points = 0 keeps the count, which then must be
     * uniformly spaced). InputError (naming @p what) for fewer than 8 points, more than
     * one turn, or a non-uniform spacing with n_points = 0. Files: io/profile_file.h.
     */
    static Profile
    from_polar_points(const std::vector<double> &angles,
                      const std::vector<double> &radii,
                      unsigned int               n_points,
                      const std::string         &what);

    unsigned int
    n_points() const
    {
      return static_cast<unsigned int>(r.size());
    }
    /** Body-frame angle of sample @p k [rad]. */
    double
    angle(unsigned int k) const;
    /** Radius at sample @p k [m]. */
    double
    operator[](unsigned int k) const
    {
      return r[k];
    }
    const std::vector<double> &
    samples() const
    {
      return r;
    }
    /** Mutable samples, for the wear layer's profile update. Call check() after. */
    std::vector<double> &
    samples()
    {
      return r;
    }

    /** Radius at body-frame angle @p psi [rad] (any real; periodic). */
    double
    radius(double psi) const;
    /** dR/dψ at @p psi [m/rad] (of the linear interpolant: one-sided at samples). */
    double
    slope(double psi) const;

    double
    min_radius() const;
    double
    max_radius() const;
    double
    mean_radius() const;
    /** True if all samples are equal (to 1e-15 relative). */
    bool
    is_round() const;

    /** Area enclosed by the polar curve (linear in ψ between samples) [m²]. */
    double
    enclosed_area() const;

    /** InputError unless N ≥ 8 and all samples finite and > 0; @p what names the source. */
    void
    check(const std::string &what) const;

  private:
    std::vector<double> r;
  };
} // namespace wearlink
