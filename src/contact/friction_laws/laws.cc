// SPDX-License-Identifier: LGPL-2.1-or-later
// Coulomb and Ambrósio's modified Coulomb friction; see friction_law.h.
#include "base/parameters.h"
#include "contact/friction_law.h"

#include <cmath>

namespace wearlink::contact
{
  namespace
  {
    void
    declare_coefficient(dealii::ParameterHandler &prm)
    {
      declare_required(prm,
                       "Friction coefficient",
                       dealii::Patterns::Double(0.0),
                       "Coulomb friction coefficient μ (seed: 0.15).",
                       "none");
    }

    class Coulomb : public FrictionLaw
    {
    public:
      explicit Coulomb(ParameterReader &r)
        : mu(r.get_double("Friction coefficient"))
      {
      }
      double
      force(double normal_force, double v) const override
      {
        return v > 0 ? -mu * normal_force : (v < 0 ? mu * normal_force : 0.0);
      }
      double
      coefficient() const override
      {
        return mu;
      }

    private:
      const double mu;
    };

    class ModifiedCoulomb : public FrictionLaw
    {
    public:
      explicit ModifiedCoulomb(ParameterReader &r)
        : mu(r.get_double("Friction coefficient"))
        , v0(r.get_positive("Static velocity limit"))
        , v1(r.get_positive("Dynamic velocity limit"))
      {
        if (!(v1 > v0))
          r.fail("Dynamic velocity limit",
                 "it must be larger than 'Static velocity limit' (" + format_number(v0) + " m/s)");
      }
      double
      force(double normal_force, double v) const override
      {
        const double s = std::abs(v);
        if (s <= v0)
          return 0.0;
        const double cd = s >= v1 ? 1.0 : (s - v0) / (v1 - v0);
        return -mu * cd * normal_force * (v > 0 ? 1.0 : -1.0);
      }
      double
      coefficient() const override
      {
        return mu;
      }

    private:
      const double mu, v0, v1;
    };
  } // namespace

  Registry<FrictionLaw> &
  friction_laws()
  {
    static Registry<FrictionLaw> r("friction law");
    return r;
  }

  std::string
  friction_law_pattern()
  {
    return "none|" + friction_laws().pattern();
  }

  void
  register_friction_laws()
  {
    auto &r = friction_laws();
    r.add("coulomb", "F_t = −μ F_n sign(v_t).", declare_coefficient, [](ParameterReader &p) {
      return std::make_unique<Coulomb>(p);
    });
    r.add(
      "modified-coulomb",
      "Ambrósio: F_t = −μ c_d F_n v_t/|v_t|, c_d ramps 0→1 between the static and "
      "dynamic velocity limits (seed eqs 12–13).",
      [](dealii::ParameterHandler &prm) {
        declare_coefficient(prm);
        declare(prm,
                "Static velocity limit",
                "1e-4",
                dealii::Patterns::Double(0.0),
                "v0: below this sliding speed the friction force is zero.",
                "m/s");
        declare(prm,
                "Dynamic velocity limit",
                "2e-4",
                dealii::Patterns::Double(0.0),
                "v1: above this sliding speed the full Coulomb force acts.",
                "m/s");
      },
      [](ParameterReader &p) { return std::make_unique<ModifiedCoulomb>(p); });
  }
} // namespace wearlink::contact
