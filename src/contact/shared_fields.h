// SPDX-License-Identifier: LGPL-2.1-or-later
// The slices of a sliced joint (contact/axial_slices.h) whose geometry agrees share their
// conformal field: the slices of an aligned joint, or the pairs of a symmetric crown under
// an aligned load, wear alike and carry the same profiles, and a field evaluated for one
// of them at a pin centre serves every other at that pin centre.
//
// A FieldPool, one per sliced joint, hands out one field per distinct set of profiles and
// foundation; the field remembers its last evaluation, so that the mechanism's force
// elements, which evaluate the slices one after the other at the same state, compute it
// once. Where the slices' pin centres differ (a misaligned bore, a bent pin) the
// remembered evaluation does not match and each slice computes its own: sharing never
// changes a result, it only skips repeating one (the same inputs give the same bits).
#pragma once

#include "base/profile.h"
#include "contact/conformal_contact.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::contact
{
  /** What, besides the two profiles, makes a foundation field: equal keys build equal fields. */
  struct FieldKey
  {
    std::string  law;                                   ///< the normal force law's registry name
    double       stiffness = 0;                         ///< K [N/mⁿ]
    double       exponent  = 0;                         ///< n (infinite: a law tabulated as a curve)
    double       clearance = 0, radius = 0, length = 0; ///< the calibration's [m]
    unsigned int cells = 0;                             ///< cells per bore area

    bool
    operator==(const FieldKey &o) const;
  };

  class FieldPool
  {
  public:
    /**
     * The field of @p bore and @p pin with @p key: the one a slice already holds when its
     * profiles and key are the same bit for bit, else a new one built by @p make.
     */
    std::shared_ptr<const ConformalField>
    field(const Profile                                          &bore,
          const Profile                                          &pin,
          const FieldKey                                         &key,
          const std::function<std::unique_ptr<ConformalField>()> &make);

    /** Distinct fields in use (for tests and reports). */
    unsigned int
    n_fields() const;

  private:
    struct Entry
    {
      std::vector<double>                 bore, pin;
      FieldKey                            key;
      std::weak_ptr<const ConformalField> field;
    };
    std::vector<Entry> entries;
  };
} // namespace wearlink::contact
