// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/contact_kinematics.h"

#include "base/numbers.h"
#include "contact/gap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::fe
{
  using namespace dealii;
  using numbers::pi;
  using numbers::two_pi;

  namespace
  {

    /** Lagrange basis on p+1 equidistant points of [0, 1], evaluated at @p xi. */
    std::array<double, 3>
    lagrange_weights(const unsigned int n_points, const double xi)
    {
      std::array<double, 3> w{};
      const unsigned int    p = n_points - 1;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          double v = 1;
          for (unsigned int l = 0; l < n_points; ++l)
            if (l != k)
              v *= (xi - double(l) / p) / (double(k) - double(l)) * p;
          w[k] = v;
        }
      return w;
    }

    /** What one pin candidate's ray gives (one position of ContactKinematics). */
    struct Ray
    {
      double                      g0 = 0, bore_angle = 0;
      Tensor<1, 2>                normal;
      std::array<unsigned int, 3> masters{};
      std::array<double, 3>       weights{};
      unsigned char               n_masters = 0;
    };

    /**
     * The length of the ray from @p x along @p n to the bore profile; @p round_radius
     * is the radius of a round bore (every sample the same; < 0: not round).
     */
    double
    ray_length(const Profile &bore, const double round_radius, const Tensor<1, 2> &x, const Tensor<1, 2> &n)
    {
      const double radius = round_radius >= 0 ? round_radius : bore.radius(std::atan2(x[1], x[0]));
      const double b      = x * n;
      double       t      = -b + std::sqrt(std::max(b * b - x * x + radius * radius, 0.0));
      if (round_radius < 0)
        for (unsigned int it = 0; it < 20; ++it)
          {
            const Tensor<1, 2> y     = x + t * n;
            const double       rho   = y.norm();
            const double       alpha = std::atan2(y[1], y[0]);
            const double       f     = rho - bore.radius(alpha);
            if (std::abs(f) < 1e-14 * rho)
              break;
            const double df = (y * n) / rho - bore.slope(alpha) * (y[0] * n[1] - y[1] * n[0]) / (rho * rho);
            t -= f / df;
          }
      return t;
    }

    /** The bore face that the polar angle @p alpha falls in, and the position in it. */
    void
    locate_on_bore(const std::vector<SurfaceFace> &faces, const double alpha, Ray &ray)
    {
      // The last face that begins at or before alpha (the last one if none does): from
      // a guess by the mean face span, a walk (the faces are nearly uniform).
      const long n = faces.size();
      long       g = std::clamp(static_cast<long>((alpha - faces.front().begin) / two_pi * n), 0L, n - 1);
      while (g > 0 && faces[g].begin > alpha)
        --g;
      while (g + 1 < n && faces[g + 1].begin <= alpha)
        ++g;
      unsigned int f = faces.front().begin > alpha ? n - 1 : g;
      double       d = alpha - faces[f].begin;
      d -= two_pi * std::floor(d / two_pi);
      if (d > faces[f].span)
        {
          // Between the end of this face and the start of the next (round-off): take
          // the nearer one.
          const unsigned int g  = (f + 1) % faces.size();
          double             dg = alpha - faces[g].begin;
          dg -= two_pi * std::round(dg / two_pi);
          if (std::abs(dg) < d - faces[f].span)
            {
              f = g;
              d = 0;
            }
          else
            d = faces[f].span;
        }
      const double xi       = std::clamp(d / faces[f].span, 0.0, 1.0);
      const auto   n_points = static_cast<unsigned int>(faces[f].nodes.size());
      const auto   w        = lagrange_weights(n_points, xi);
      ray.n_masters         = n_points;
      for (unsigned int a = 0; a < n_points; ++a)
        {
          ray.masters[a] = faces[f].nodes[a];
          ray.weights[a] = w[a];
        }
    }

    /**
     * Casting the rays of one pose: the rotation by the relative angle and the radius of
     * a round bore, computed once (the same numbers rotate() and Profile::radius() give).
     */
    class RayCaster
    {
    public:
      RayCaster(const ElasticityProblem &problem, const PinPose &pose)
        : problem(problem)
        , pose(pose)
        , round_radius(pose.bore->is_round() ? pose.bore->radius(0.0) : -1.0)
        , c(std::cos(pose.relative_angle))
        , s(std::sin(pose.relative_angle))
      {
      }

      /** Candidate i's initial gap only. */
      double
      gap(const unsigned int i) const
      {
        return ray_length(*pose.bore, round_radius, point(i), normal(i));
      }

      /** Candidate i's ray: gap, normal, and where it meets the bore. */
      Ray
      cast(const unsigned int i) const
      {
        Ray                ray;
        const Tensor<1, 2> x = point(i);
        ray.normal           = normal(i);
        ray.g0               = ray_length(*pose.bore, round_radius, x, ray.normal);
        const Tensor<1, 2> y = x + ray.g0 * ray.normal;
        ray.bore_angle       = std::atan2(y[1], y[0]);
        locate_on_bore(problem.bore_faces, ray.bore_angle, ray);
        return ray;
      }

      /** Candidate i's initial gap along a given @p n (bushing frame). */
      double
      gap_along(const unsigned int i, const Tensor<1, 2> &n) const
      {
        return ray_length(*pose.bore, round_radius, point(i), n);
      }

    private:
      Tensor<1, 2>
      rotated(const Tensor<1, 2> &v) const
      {
        Tensor<1, 2> r;
        r[0] = c * v[0] - s * v[1];
        r[1] = s * v[0] + c * v[1];
        return r;
      }

      /** The candidate in the bushing frame (its radial offset applied, see PinPose). */
      Tensor<1, 2>
      point(const unsigned int i) const
      {
        Tensor<1, 2> p = problem.pin_nodes[i].point;
        if (pose.pin_offsets != nullptr)
          p *= 1 + (*pose.pin_offsets)[i] / p.norm();
        return pose.eccentricity + rotated(p);
      }

      Tensor<1, 2>
      normal(const unsigned int i) const
      {
        return rotated(problem.pin_nodes[i].normal);
      }

      const ElasticityProblem &problem;
      const PinPose           &pose;
      const double             round_radius; ///< < 0: not round
      const double             c, s;         ///< cos, sin of the relative angle
    };

    void
    append(ContactKinematics &k, const unsigned int i, const Ray &ray)
    {
      k.candidates.push_back(i);
      k.g0.push_back(ray.g0);
      k.normal.push_back(ray.normal);
      k.bore_angle.push_back(ray.bore_angle);
      k.masters.push_back(ray.masters);
      k.weights.push_back(ray.weights);
      k.n_masters.push_back(ray.n_masters);
    }

    ContactKinematics
    empty_kinematics(const PinPose &pose)
    {
      ContactKinematics k;
      k.relative_angle = pose.relative_angle;
      k.eccentricity   = pose.eccentricity;
      // Round-off of the gap formula: lengths of the size of the bore radius.
      k.tolerance = 1e-13 * pose.bore->max_radius();
      return k;
    }

    /** max |dR/dψ| of the linear interpolant of @p p [m/rad]. */
    double
    max_slope(const Profile &p)
    {
      const unsigned int n = p.n_points();
      double             s = 0;
      for (unsigned int k = 0; k < n; ++k)
        s = std::max(s, std::abs(p[(k + 1) % n] - p[k]));
      return s * n / two_pi;
    }

    /** max |dR/dψ| of the pin as its candidates sample it (offsets included) [m/rad]. */
    double
    pin_max_slope(const ElasticityProblem &problem, const PinPose &pose)
    {
      const auto        &nodes = problem.pin_nodes;
      const unsigned int m     = nodes.size();
      if (pose.pin_offsets == nullptr)
        return problem.pin_surface_slope;
      auto r = [&](unsigned int i) {
        return nodes[i].point.norm() + (*pose.pin_offsets)[i];
      };
      double s = 0;
      for (unsigned int i = 0; i < m; ++i)
        {
          const unsigned int j  = (i + 1) % m;
          double             da = nodes[j].angle - nodes[i].angle;
          da -= two_pi * std::floor(da / two_pi);
          if (da > 0)
            s = std::max(s, std::abs(r(j) - r(i)) / da);
        }
      return s;
    }
  } // namespace


  ContactKinematics
  compute_kinematics(const ElasticityProblem &problem, const PinPose &pose)
  {
    ContactKinematics  k = empty_kinematics(pose);
    const RayCaster    rays(problem, pose);
    const unsigned int m = problem.pin_nodes.size();
    for (unsigned int i = 0; i < m; ++i)
      append(k, i, rays.cast(i));
    return k;
  }


  void
  refresh_gaps(const ElasticityProblem &problem, const PinPose &pose, ContactKinematics &k)
  {
    const RayCaster rays(problem, pose);
    k.eccentricity = pose.eccentricity;
    for (unsigned int p = 0; p < k.candidates.size(); ++p)
      k.g0[p] = rays.gap_along(k.candidates[p], k.normal[p]);
  }


  // Blocks of B candidates between sampled ones: a block whose bound (mean of its two
  // end gaps − L Δψ/2) exceeds the threshold cannot hold a candidate below it.
  ContactKinematics
  compute_window_kinematics(const ElasticityProblem &problem,
                            const PinPose           &pose,
                            const WindowThreshold   &rule,
                            double                  *threshold_used)
  {
    constexpr unsigned int B     = 8;
    const auto            &nodes = problem.pin_nodes;
    const unsigned int     m     = nodes.size();
    const RayCaster        rays(problem, pose);
    const double           L = 2 * (pose.eccentricity.norm() + max_slope(*pose.bore) + pin_max_slope(problem, pose));
    const unsigned int     n_blocks = (m + B - 1) / B;
    std::vector<double>    sampled(n_blocks);
    double                 g_min = std::numeric_limits<double>::max();
    for (unsigned int j = 0; j < n_blocks; ++j)
      {
        sampled[j] = rays.gap(j * B);
        g_min      = std::min(g_min, sampled[j]);
      }
    const double threshold = std::max({rule.at_least, g_min + rule.above_smallest, -rule.overlap_factor * g_min});
    if (threshold_used != nullptr)
      *threshold_used = threshold;

    // The candidates below the threshold, with their rays, in increasing order.
    std::vector<std::pair<unsigned int, Ray>> below;
    for (unsigned int j = 0; j < n_blocks; ++j)
      {
        const unsigned int a  = j * B;
        const unsigned int b  = std::min(a + B, m); // b = m: the block ends at candidate 0
        double             da = nodes[b % m].angle - nodes[a].angle;
        da -= two_pi * std::floor(da / two_pi);
        const double lower = 0.5 * (sampled[j] + sampled[(j + 1) % n_blocks]) - 0.5 * L * da;
        if (sampled[j] <= threshold)
          below.emplace_back(a, rays.cast(a));
        if (lower <= threshold)
          for (unsigned int i = a + 1; i < b; ++i)
            if (Ray ray = rays.cast(i); ray.g0 <= threshold)
              below.emplace_back(i, ray);
      }
    // Padded by one candidate on either side, so that every contact node's neighbours
    // (the ends of its tributary arc) are in the window.
    std::vector<char> in(m, 0);
    for (const auto &b : below)
      in[b.first] = 1;
    ContactKinematics k    = empty_kinematics(pose);
    std::size_t       next = 0;
    for (unsigned int i = 0; i < m; ++i)
      {
        const bool listed = next < below.size() && below[next].first == i;
        if (listed)
          append(k, i, below[next++].second);
        else if (in[(i + 1) % m] || in[(i + m - 1) % m])
          append(k, i, rays.cast(i));
      }
    return k;
  }

  namespace
  {
    /** The sample directions of both profiles in the bushing frame, sorted, in [0, 2π). */
    std::vector<double>
    sample_directions(const Profile &bore, const Profile &pin, const double relative_angle)
    {
      std::vector<double> phi;
      phi.reserve(bore.n_points() + pin.n_points());
      for (unsigned int i = 0; i < bore.n_points(); ++i)
        phi.push_back(bore.angle(i));
      for (unsigned int j = 0; j < pin.n_points(); ++j)
        phi.push_back(pin.angle(j) + relative_angle);
      for (auto &a : phi)
        a -= two_pi * std::floor(a / two_pi);
      std::sort(phi.begin(), phi.end());
      phi.erase(std::unique(phi.begin(), phi.end(), [](double a, double b) { return b - a < 1e-12; }), phi.end());
      return phi;
    }

    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }
  } // namespace


  Tensor<1, 2>
  rigid_rest_position(const Profile &bore, const Profile &pin, const double relative_angle, const Tensor<1, 2> &d)
  {
    const double phi_d     = std::atan2(d[1], d[0]);
    const auto   clearance = [&](const double phi) {
      return bore.radius(phi) - pin.radius(phi - relative_angle);
    };
    if (bore.is_round() && pin.is_round())
      return clearance(phi_d) * d;
    // Polar points p_k = u(φ_k)/c(φ_k), in angular order; the hull's vertices by a
    // cyclic scan from the farthest point (a hull vertex), keeping left turns only.
    const auto                phi = sample_directions(bore, pin, relative_angle);
    const std::size_t         n   = phi.size();
    std::vector<Tensor<1, 2>> p(n);
    std::size_t               far = 0;
    for (std::size_t k = 0; k < n; ++k)
      {
        const double c = clearance(phi[k]);
        p[k][0]        = std::cos(phi[k]) / c;
        p[k][1]        = std::sin(phi[k]) / c;
        if (p[k].norm_square() > p[far].norm_square())
          far = k;
      }
    std::vector<std::size_t> hull = {far};
    for (std::size_t i = 1; i <= n; ++i)
      {
        const std::size_t k = (far + i) % n;
        while (hull.size() >= 2 && cross(p[hull.back()] - p[hull[hull.size() - 2]], p[k] - p[hull.back()]) <= 0)
          hull.pop_back();
        if (i < n)
          hull.push_back(k);
      }
    // The hull edge (a, b) whose directions bracket φ_d (counter-clockwise from a).
    const auto ccw_from = [](const double from, const double to) {
      return to - from - two_pi * std::floor((to - from) / two_pi);
    };
    std::size_t a = hull.back(), b = hull.front();
    for (std::size_t h = 0; h < hull.size(); ++h)
      {
        const std::size_t a_h = hull[h], b_h = hull[(h + 1) % hull.size()];
        if (ccw_from(phi[a_h], phi_d) <= ccw_from(phi[a_h], phi[b_h]))
          {
            a = a_h;
            b = b_h;
            break;
          }
      }
    // The vertex of the constraint polygon: e·u_a = c_a, e·u_b = c_b.
    Tensor<1, 2> e;
    const double ca = clearance(phi[a]), cb = clearance(phi[b]);
    const double det = std::sin(phi[b] - phi[a]);
    if (std::abs(det) < 1e-12)
      e = ca * d;
    else
      {
        e[0] = (ca * std::sin(phi[b]) - cb * std::sin(phi[a])) / det;
        e[1] = (cb * std::cos(phi[a]) - ca * std::cos(phi[b])) / det;
      }
    // Between the sample directions the gap is not the polygon's: onto the exact radial
    // gap along d (a few sub-µm steps; the contact solver refines the rest).
    const contact::Gap gap(bore, pin);
    for (int it = 0; it < 3; ++it)
      {
        const double overlap = gap.evaluate(mbs::Vec2(e[0], e[1]), 0.0, relative_angle).penetration;
        if (!std::isfinite(overlap))
          break;
        e -= overlap * d;
      }
    return e;
  }
} // namespace wearlink::fe
