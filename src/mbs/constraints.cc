// SPDX-License-Identifier: LGPL-2.1-or-later
// The constraint library. Derivations (B s = dA/dθ s = perp(A s)):
//
// Revolute, Φ = P_j − P_i − e0:
//   Φq:  body i [−I, −perp(A_i s_i)],  body j [I, perp(A_j s_j)]
//   γ  = θ̇_j² A_j s_j − θ̇_i² A_i s_i
//
// Translational, Φ1 = n·d with n = A_i perp(u_i), d = P_j − P_i:
//   ∂Φ1/∂r_i = −n, ∂Φ1/∂θ_i = perp(n)·d − n·perp(A_i s_i),
//   ∂Φ1/∂r_j =  n, ∂Φ1/∂θ_j = n·perp(A_j s_j),
//   γ1 = θ̇_i² n·d − 2 θ̇_i perp(n)·ḋ + n·(θ̇_j² A_j s_j − θ̇_i² A_i s_i)
//   (from Φ̈1 = n̈·d + 2ṅ·ḋ + n·d̈ with ṅ = θ̇_i perp(n), n̈ = θ̈_i perp(n) − θ̇_i² n).
// Relative-angle rows (translational Φ2, fixed-angle, driver) have constant Jacobians,
// γ = 0 and, for the driver, Φt = −ω.
// Unit tests compare every Φq and γ with finite differences.
#include "mbs/constraint.h"

namespace wearlink::mbs
{
  namespace
  {
    void
    set_angle_row(ConstraintRows &out, unsigned int row, int body_i, double phi)
    {
      out.phi[row]      = phi;
      out.jac_i[row][0] = 0;
      out.jac_i[row][1] = 0;
      out.jac_i[row][2] = body_i == ground ? 0.0 : -1.0;
      out.jac_j[row][0] = 0;
      out.jac_j[row][1] = 0;
      out.jac_j[row][2] = 1.0;
      out.phi_t[row]    = 0;
      out.gamma[row]    = 0;
    }

    class Revolute : public Constraint
    {
    public:
      Revolute(const std::string &name, int bi, const Vec2 &si, int bj, const Vec2 &sj, const Vec2 &e0)
        : Constraint(name, bi, bj)
        , s_i(si)
        , s_j(sj)
        , offset(e0)
      {
      }

      unsigned int
      n_equations() const override
      {
        return 2;
      }

      std::string
      type() const override
      {
        return "revolute";
      }

      std::array<bool, 3>
      constant_jacobian(unsigned int) const override
      {
        return {{true, true, false}};
      }

      void
      evaluate(double, const StateView &s, ConstraintRows &out) const override
      {
        out.n              = 2;
        const Vec2   a_i   = s.to_global(body_i, s_i);
        const Vec2   a_j   = s.to_global(body_j, s_j);
        const Vec2   p_i   = body_i == ground ? s_i : Vec2(s.position(body_i) + a_i);
        const Vec2   p_j   = s.position(body_j) + a_j;
        const Vec2   phi   = p_j - p_i - offset;
        const Vec2   b_i   = perp(a_i);
        const Vec2   b_j   = perp(a_j);
        const double wi    = s.angular_velocity(body_i);
        const double wj    = s.angular_velocity(body_j);
        const Vec2   gamma = wj * wj * a_j - (body_i == ground ? Vec2(0, 0) : Vec2(wi * wi * a_i));
        for (unsigned int d = 0; d < 2; ++d)
          {
            out.phi[d]      = phi[d];
            out.phi_t[d]    = 0;
            out.gamma[d]    = gamma[d];
            out.jac_i[d][0] = d == 0 ? -1.0 : 0.0;
            out.jac_i[d][1] = d == 1 ? -1.0 : 0.0;
            out.jac_i[d][2] = -b_i[d];
            out.jac_j[d][0] = d == 0 ? 1.0 : 0.0;
            out.jac_j[d][1] = d == 1 ? 1.0 : 0.0;
            out.jac_j[d][2] = b_j[d];
          }
      }

    private:
      const Vec2 s_i, s_j, offset;
    };

    class Translational : public Constraint
    {
    public:
      Translational(const std::string &name,
                    int                bi,
                    const Vec2        &si,
                    const Vec2        &ui,
                    int                bj,
                    const Vec2        &sj,
                    double             theta0)
        : Constraint(name, bi, bj)
        , s_i(si)
        , normal_i(perp(ui.normalized()))
        , s_j(sj)
        , theta0(theta0)
      {
      }

      unsigned int
      n_equations() const override
      {
        return 2;
      }

      std::string
      type() const override
      {
        return "translational";
      }

      std::array<bool, 3>
      constant_jacobian(const unsigned int row) const override
      {
        return {{row == 1, row == 1, row == 1}}; // row 1 is the relative angle
      }

      void
      evaluate(double, const StateView &s, ConstraintRows &out) const override
      {
        out.n             = 2;
        const double th_i = s.angle(body_i);
        const double wi   = s.angular_velocity(body_i);
        const double wj   = s.angular_velocity(body_j);
        const Vec2   a_i  = s.to_global(body_i, s_i);
        const Vec2   a_j  = s.to_global(body_j, s_j);
        const Vec2   n    = s.to_global(body_i, normal_i);
        const Vec2   p_i  = body_i == ground ? s_i : Vec2(s.position(body_i) + a_i);
        const Vec2   p_j  = s.position(body_j) + a_j;
        const Vec2   d    = p_j - p_i;
        const Vec2   v_i  = s.point_velocity(body_i, s_i);
        const Vec2   v_j  = s.point_velocity(body_j, s_j);
        const Vec2   dd   = v_j - v_i;

        out.phi[0]      = n.dot(d);
        out.phi_t[0]    = 0;
        out.jac_i[0][0] = -n.x();
        out.jac_i[0][1] = -n.y();
        out.jac_i[0][2] = perp(n).dot(d) - n.dot(perp(a_i));
        out.jac_j[0][0] = n.x();
        out.jac_j[0][1] = n.y();
        out.jac_j[0][2] = n.dot(perp(a_j));
        if (body_i == ground)
          out.gamma[0] = n.dot(wj * wj * a_j);
        else
          out.gamma[0] = wi * wi * n.dot(d) - 2 * wi * perp(n).dot(dd) + n.dot(wj * wj * a_j - wi * wi * a_i);

        set_angle_row(out, 1, body_i, s.angle(body_j) - th_i - theta0);
      }

    private:
      const Vec2   s_i, normal_i, s_j;
      const double theta0;
    };

    class FixedAngle : public Constraint
    {
    public:
      FixedAngle(const std::string &name, int bi, int bj, double theta0)
        : Constraint(name, bi, bj)
        , theta0(theta0)
      {
      }

      unsigned int
      n_equations() const override
      {
        return 1;
      }

      std::string
      type() const override
      {
        return "fixed-angle";
      }

      std::array<bool, 3>
      constant_jacobian(unsigned int) const override
      {
        return {{true, true, true}};
      }

      void
      evaluate(double, const StateView &s, ConstraintRows &out) const override
      {
        out.n = 1;
        set_angle_row(out, 0, body_i, s.angle(body_j) - s.angle(body_i) - theta0);
      }

    private:
      const double theta0;
    };

    class AngleDriver : public Constraint
    {
    public:
      AngleDriver(const std::string &name, int bi, int bj, double theta0, double omega)
        : Constraint(name, bi, bj)
        , theta0(theta0)
        , omega(omega)
      {
      }

      unsigned int
      n_equations() const override
      {
        return 1;
      }

      std::string
      type() const override
      {
        return "angle-driver";
      }

      double
      rate() const override
      {
        return omega;
      }

      std::array<bool, 3>
      constant_jacobian(unsigned int) const override
      {
        return {{true, true, true}};
      }

      void
      evaluate(double t, const StateView &s, ConstraintRows &out) const override
      {
        out.n = 1;
        set_angle_row(out, 0, body_i, s.angle(body_j) - s.angle(body_i) - theta0 - omega * t);
        out.phi_t[0] = -omega;
      }

    private:
      const double theta0, omega;
    };
  } // namespace

  std::unique_ptr<Constraint>
  make_revolute(const std::string &name, int body_i, const Vec2 &s_i, int body_j, const Vec2 &s_j, const Vec2 &offset)
  {
    return std::make_unique<Revolute>(name, body_i, s_i, body_j, s_j, offset);
  }

  std::unique_ptr<Constraint>
  make_translational(const std::string &name,
                     int                body_i,
                     const Vec2        &s_i,
                     const Vec2        &axis_i,
                     int                body_j,
                     const Vec2        &s_j,
                     double             angle_offset)
  {
    return std::make_unique<Translational>(name, body_i, s_i, axis_i, body_j, s_j, angle_offset);
  }

  std::unique_ptr<Constraint>
  make_fixed_angle(const std::string &name, int body_i, int body_j, double angle_offset)
  {
    return std::make_unique<FixedAngle>(name, body_i, body_j, angle_offset);
  }

  std::unique_ptr<Constraint>
  make_angle_driver(const std::string &name, int body_i, int body_j, double angle_offset, double angular_velocity)
  {
    return std::make_unique<AngleDriver>(name, body_i, body_j, angle_offset, angular_velocity);
  }
} // namespace wearlink::mbs
