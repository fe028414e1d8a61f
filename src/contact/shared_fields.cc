// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/shared_fields.h"

#include <algorithm>

namespace wearlink::contact
{
  bool
  FieldKey::operator==(const FieldKey &o) const
  {
    return law == o.law && stiffness == o.stiffness && exponent == o.exponent && clearance == o.clearance &&
           radius == o.radius && length == o.length && cells == o.cells;
  }

  namespace
  {
    bool
    same_motion(const ConformalMotion *a, const ConformalMotion *b)
    {
      if (a == nullptr || b == nullptr)
        return a == b;
      return a->velocity == b->velocity && a->relative_rate == b->relative_rate && a->factor == b->factor &&
             a->impact_velocity == b->impact_velocity && a->min_velocity == b->min_velocity;
    }

    /** A field that answers a repeated question from its last answer. */
    class RememberingField : public ConformalField
    {
    public:
      explicit RememberingField(std::unique_ptr<ConformalField> f)
        : inner(std::move(f))
      {
      }

      double
      overlap(const mbs::Vec2 &e, const double relative_angle) const override
      {
        if (!(overlap_known && e == overlap_e && relative_angle == overlap_angle))
          {
            last_overlap  = inner->overlap(e, relative_angle);
            overlap_e     = e;
            overlap_angle = relative_angle;
            overlap_known = true;
          }
        return last_overlap;
      }

      void
      evaluate(const mbs::Vec2       &e,
               const double           relative_angle,
               const ConformalMotion *motion,
               const bool             with_potential,
               ConformalForce        &out) const override
      {
        const bool same = known && e == last_e && relative_angle == last_angle &&
                          same_motion(motion, has_motion ? &last_motion : nullptr) &&
                          (has_potential || !with_potential);
        if (!same)
          {
            inner->evaluate(e, relative_angle, motion, with_potential, last);
            known         = true;
            last_e        = e;
            last_angle    = relative_angle;
            has_motion    = motion != nullptr;
            last_motion   = has_motion ? *motion : ConformalMotion();
            has_potential = with_potential;
          }
        out = last;
        if (!with_potential)
          out.potential = 0;
      }

    private:
      std::unique_ptr<ConformalField> inner;
      mutable bool                    known = false, has_motion = false, has_potential = false;
      mutable mbs::Vec2               last_e{0, 0};
      mutable double                  last_angle = 0;
      mutable ConformalMotion         last_motion;
      mutable ConformalForce          last;
      mutable bool                    overlap_known = false;
      mutable mbs::Vec2               overlap_e{0, 0};
      mutable double                  overlap_angle = 0, last_overlap = 0;
    };
  } // namespace

  std::shared_ptr<const ConformalField>
  FieldPool::field(const Profile                                          &bore,
                   const Profile                                          &pin,
                   const FieldKey                                         &key,
                   const std::function<std::unique_ptr<ConformalField>()> &make)
  {
    entries.erase(std::remove_if(entries.begin(), entries.end(), [](const Entry &e) { return e.field.expired(); }),
                  entries.end());
    for (const auto &e : entries)
      if (e.key == key && e.bore == bore.samples() && e.pin == pin.samples())
        if (auto f = e.field.lock())
          return f;
    std::shared_ptr<const ConformalField> f = std::make_shared<RememberingField>(make());
    entries.push_back(Entry{bore.samples(), pin.samples(), key, f});
    return f;
  }

  unsigned int
  FieldPool::n_fields() const
  {
    return static_cast<unsigned int>(
      std::count_if(entries.begin(), entries.end(), [](const Entry &e) { return !e.field.expired(); }));
  }
} // namespace wearlink::contact
