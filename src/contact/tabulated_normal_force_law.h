// SPDX-License-Identifier: LGPL-2.1-or-later
// A normal force law whose elastic part is a force–approach table built from the joint's
// geometry (contact/force_approach_table.h), with the Lankarani–Nikravesh hysteresis on
// top (the same factor 3(1 − c_e²)/4 and impact-velocity guard as `lankarani-nikravesh`).
// The derived law says how the table is built — `johnson` and `esdu-78035` from their
// closed forms (contact/cylindrical_contact.h), `fe` from the FE model
// (fe/fe_normal_force_law.h); this class evaluates it, rebuilds it at every geometry
// update, and counts the evaluations beyond the table for the run summary.
#pragma once

#include "contact/force_approach_table.h"
#include "contact/normal_force_law.h"

namespace wearlink::contact
{
  class TabulatedNormalForceLaw : public NormalForceLaw
  {
  public:
    TabulatedNormalForceLaw(double restitution, double min_impact_velocity);

    void
    evaluate(const NormalContactInput &in, NormalContactOutput &out) const override;
    double
    potential(const NormalContactInput &in) const override;
    /** The L-N hysteresis. */
    Hysteresis
    hysteresis() const override
    {
      return {damping_factor, min_impact_velocity};
    }
    /** The table's force in its first direction (a round pair's table has one). */
    double
    round_elastic_force(double approach, double stiffness) const override;
    /** No single exponent: potential() integrates the table. NaN. */
    double
    exponent() const override;
    /** Rebuilds the table (build_table()). */
    void
    update_geometry(const JointGeometry &geometry) override;
    /** True if the table has more than one direction. */
    bool
    uses_direction() const override;
    /** The table's size and range, evaluations and extrapolations above and below it. */
    Json
    report() const override;

  protected:
    /** The table for @p geometry. */
    virtual ForceApproachTable
    build_table(const JointGeometry &geometry) = 0;

    /**
     * Drop the table (a derived law that carries the geometry another way, e.g. the fe
     * law's conformal field): evaluate() is then an error until the next update_geometry().
     */
    void
    clear_table()
    {
      table = ForceApproachTable();
    }

  private:
    const double       damping_factor, min_impact_velocity;
    ForceApproachTable table;
    mutable long       evaluations = 0, above = 0, below = 0;
  };
} // namespace wearlink::contact
