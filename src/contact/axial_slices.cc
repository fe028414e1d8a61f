// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/axial_slices.h"

#include "base/numbers.h"
#include "contact/clearance_joint.h"

#include <cmath>
#include <cstdio>

namespace wearlink::contact
{
  double
  slice_position(const unsigned int i, const unsigned int n, const double length)
  {
    // Antisymmetric to the last bit (slices i and n − 1 − i at ∓z): a symmetric crown's
    // pairs of slices get the same profiles and share their field.
    return (2.0 * i + 1.0 - n) * length / (2.0 * n);
  }

  mbs::Vec2
  bore_offset(const SliceLayout &layout, const double z)
  {
    const double shift = z * std::tan(layout.misalignment);
    return {shift * std::sin(layout.tilt_direction), -shift * std::cos(layout.tilt_direction)};
  }

  double
  crown_drop(const SliceLayout &layout,
             const double       z,
             const double       length,
             const Material    &bushing,
             const Material    &pin)
  {
    const double s = 2 * z / length; // −1 … 1 over the bushing
    switch (layout.crown)
      {
        case PinCrown::circular:
          return layout.crown_drop * s * s;
        case PinCrown::logarithmic:
          {
            const double e_prime = 1 / (bushing.compliance() + pin.compliance());
            return 2 * layout.crown_load / (numbers::pi * e_prime * length) * std::log(1 / (1 - s * s));
          }
        case PinCrown::none:
          break;
      }
    return 0;
  }

  double
  relief_gain(const SliceLayout &layout, const double z, const double length)
  {
    if (!(layout.relief_depth > 0 && layout.relief_length > 0))
      return 0;
    const double into = std::abs(z) - (0.5 * length - layout.relief_length);
    if (!(into > 0))
      return 0;
    const double s = into / layout.relief_length;
    return layout.relief_depth * s * s;
  }

  ClearanceJointDescription
  slice_of(const ClearanceJointDescription &joint, const SliceLayout &layout, const unsigned int i)
  {
    if (layout.count <= 1)
      return joint;
    ClearanceJointDescription d = joint;
    const double              L = joint.geometry.axial_length;
    auto                     &s = d.slice;
    s.joint                     = joint.name;
    s.index                     = i;
    s.count                     = layout.count;
    s.position                  = slice_position(i, layout.count, L);
    s.share                     = 1.0 / layout.count;
    s.bore_offset               = bore_offset(layout, s.position);
    s.nominal_bore_radius       = joint.geometry.bore.mean_radius();
    s.nominal_pin_radius        = joint.geometry.pin.mean_radius();
    d.name                      = slice_name(joint.name, i, layout.count);
    d.bushing_point             = joint.bushing_point + s.bore_offset;
    d.geometry.axial_length     = L / layout.count;
    const double crown  = crown_drop(layout, s.position, L, joint.geometry.bushing, joint.geometry.pin_material);
    const double relief = relief_gain(layout, s.position, L);
    for (auto &r : d.geometry.pin.samples())
      r -= crown;
    for (auto &r : d.geometry.bore.samples())
      r += relief;
    return d;
  }

  std::shared_ptr<ElasticPin>
  make_elastic_pin(const ClearanceJointDescription &joint, const SliceLayout &layout)
  {
    if (layout.count < 2 || layout.bending.support == PinSupport::rigid)
      return nullptr;
    PinBending   b = layout.bending;
    const double r = joint.geometry.pin.mean_radius();
    if (!(b.bending_stiffness > 0))
      b.bending_stiffness = joint.geometry.pin_material.youngs_modulus * numbers::pi * std::pow(r, 4) / 4;
    std::vector<double> z;
    for (unsigned int i = 0; i < layout.count; ++i)
      z.push_back(slice_position(i, layout.count, joint.geometry.axial_length));
    return std::make_shared<ElasticPin>(b, joint.geometry.axial_length, z);
  }

  std::string
  slice_number(const unsigned int i, const unsigned int n)
  {
    char number[16];
    std::snprintf(number, sizeof number, "%0*u", n >= 100 ? 3 : 2, i + 1);
    return number;
  }

  std::string
  slice_name(const std::string &joint, const unsigned int i, const unsigned int n)
  {
    return n <= 1 ? joint : joint + ".s" + slice_number(i, n);
  }
} // namespace wearlink::contact
