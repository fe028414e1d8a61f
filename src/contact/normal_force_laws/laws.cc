// SPDX-License-Identifier: LGPL-2.1-or-later
// The three normal force laws; see normal_force_law.h for the equations.
#include "base/parameters.h"
#include "contact/cylindrical_contact.h"
#include "contact/normal_force_law.h"
#include "contact/tabulated_normal_force_law.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace wearlink::contact
{
  namespace
  {
    void
    declare_exponent(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Exponent",
              "1.5",
              dealii::Patterns::Double(1.0, 3.0),
              "Exponent n of the elastic term K δⁿ (1.5 for Hertzian contact).",
              "none");
    }

    /** Restitution and the impact-velocity guard of the L-N hysteresis. */
    void
    declare_damping(dealii::ParameterHandler &prm)
    {
      declare_required(prm,
                       "Restitution coefficient",
                       dealii::Patterns::Double(0.0, 1.0),
                       "Coefficient of restitution c_e of the impact (seed: 0.9).",
                       "none");
      declare(prm,
              "Minimum impact velocity",
              "1e-4",
              dealii::Patterns::Double(1e-12),
              "Guard for contacts that begin with almost no impact velocity (continuous "
              "contact): the hysteresis term uses max(δ̇⁻, this value, |δ̇|) in place of "
              "the impact velocity δ̇⁻, so its factor 3(1 − c_e²)/(4 δ̇⁻) stays bounded "
              "and the damping force never exceeds 3(1 − c_e²)/4 of the elastic one once "
              "a contact is loaded faster than it began. Genuine impacts (|δ̇| ≤ δ̇⁻) are "
              "unaffected.",
              "m/s");
    }

    void
    declare_dissipative(dealii::ParameterHandler &prm)
    {
      declare_exponent(prm);
      declare_damping(prm);
    }

    /** δⁿ; Hertz's n = 1.5 as δ√δ (a third of pow's cost on the right-hand side's path). */
    double
    power_of(const double delta, const double n)
    {
      return n == 1.5 ? delta * std::sqrt(delta) : std::pow(delta, n);
    }

    /** Elastic part shared by all three laws. */
    void
    elastic(const NormalContactInput &in, double n, NormalContactOutput &out)
    {
      const double dn   = power_of(in.penetration, n);
      out.elastic_force = in.stiffness * dn;
      out.potential     = in.stiffness * dn * in.penetration / (n + 1);
    }

    class Hertz : public NormalForceLaw
    {
    public:
      explicit Hertz(ParameterReader &r)
        : n(r.get_double("Exponent"))
      {
      }
      void
      evaluate(const NormalContactInput &in, NormalContactOutput &out) const override
      {
        elastic(in, n, out);
        out.force = out.elastic_force;
      }
      double
      exponent() const override
      {
        return n;
      }

    private:
      const double n;
    };

    /** L-N and Flores differ only in the hysteresis factor χ: F = K δⁿ (1 + χ δ̇). */
    class HysteresisDamping : public NormalForceLaw
    {
    public:
      HysteresisDamping(ParameterReader &r, bool flores)
        : n(r.get_double("Exponent"))
        , restitution(r.get_double("Restitution coefficient"))
        , min_impact_velocity(r.get_positive("Minimum impact velocity"))
        , factor(flores ? 8 * (1 - restitution) / (5 * restitution) : 3 * (1 - restitution * restitution) / 4)
      {
        if (flores && !(restitution > 0))
          r.fail("Restitution coefficient", "the Flores law needs c_e > 0 (it divides by c_e)");
      }
      void
      evaluate(const NormalContactInput &in, NormalContactOutput &out) const override
      {
        elastic(in, n, out);
        out.force = lankarani_nikravesh_force(out.elastic_force, in, factor, min_impact_velocity);
      }
      Hysteresis
      hysteresis() const override
      {
        return {factor, min_impact_velocity};
      }
      double
      exponent() const override
      {
        return n;
      }

    private:
      const double n, restitution, min_impact_velocity, factor;
    };

    /**
     * A cylindrical closed form (contact/cylindrical_contact.h) with the L-N hysteresis:
     * tabulated from the joint's nominal radii, length and materials at every geometry
     * update (60 levels from 1 N to the law's valid maximum).
     */
    class Cylindrical : public TabulatedNormalForceLaw
    {
    public:
      Cylindrical(ParameterReader &r, const CylindricalLaw law)
        : TabulatedNormalForceLaw(r.get_double("Restitution coefficient"), r.get_positive("Minimum impact velocity"))
        , law(law)
      {
      }

    protected:
      ForceApproachTable
      build_table(const JointGeometry &g) override
      {
        return tabulate_cylindrical_law(law, CylinderPair::of(g), 1.0, 60);
      }

    private:
      const CylindricalLaw law;
    };
  } // namespace

  double
  NormalForceLaw::round_elastic_force(const double approach, const double stiffness) const
  {
    return approach > 0 ? stiffness * power_of(approach, exponent()) : 0.0;
  }

  double
  NormalForceLaw::potential(const NormalContactInput &in) const
  {
    const double n = exponent();
    return in.stiffness * std::pow(in.penetration, n + 1) / (n + 1);
  }

  Registry<NormalForceLaw> &
  normal_force_laws()
  {
    static Registry<NormalForceLaw> r("normal force law");
    return r;
  }

  void
  register_normal_force_laws()
  {
    auto &r = normal_force_laws();
    r.add("hertz", "F = K δⁿ, purely elastic (seed eq. 9 without damping).", declare_exponent, [](ParameterReader &p) {
      return std::make_unique<Hertz>(p);
    });
    r.add("lankarani-nikravesh",
          "F = K δⁿ (1 + 3(1 − c_e²) δ̇/(4 δ̇⁻)) (seed eqs 9–11).",
          declare_dissipative,
          [](ParameterReader &p) { return std::make_unique<HysteresisDamping>(p, false); });
    r.add("johnson",
          "F from Johnson's internal line contact δ = P/(π E*)[ln(4π E* ΔR/P) − 1], P = F/L (axial length "
          "included; contact/cylindrical_contact.h), with the L-N hysteresis.",
          declare_damping,
          [](ParameterReader &p) { return std::make_unique<Cylindrical>(p, CylindricalLaw::johnson); });
    r.add("esdu-78035",
          "F from ESDU-78035's internal line contact δ = P/(π E*)[ln(4π E* ΔR/P) + 1], P = F/L, with the L-N "
          "hysteresis.",
          declare_damping,
          [](ParameterReader &p) { return std::make_unique<Cylindrical>(p, CylindricalLaw::esdu_78035); });
    r.add("flores",
          "F = K δⁿ (1 + 8(1 − c_e) δ̇/(5 c_e δ̇⁻)) (Flores et al. 2011).",
          declare_dissipative,
          [](ParameterReader &p) { return std::make_unique<HysteresisDamping>(p, true); });
  }
} // namespace wearlink::contact
