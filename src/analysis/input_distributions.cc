// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/input_distributions.h"

#include "base/exceptions.h"

namespace wearlink::analysis
{
  namespace
  {
    std::vector<InputDistribution>
    distributions_of(const UncertaintySettings &settings)
    {
      if (settings.inputs.empty())
        throw InputError("Sampling uncertain inputs needs at least one input.");
      std::vector<InputDistribution> d;
      for (const auto &i : settings.inputs)
        d.push_back(i.distribution);
      return d;
    }
  } // namespace

  SaltelliDesign
  member_design(const UncertaintySettings &settings, const std::uint64_t n_members)
  {
    const auto          d     = distributions_of(settings);
    const std::uint64_t width = d.size() + 2;
    if (n_members < width || n_members % width != 0)
      throw InputError("A Saltelli design of " + std::to_string(d.size()) + " uncertain inputs needs a multiple of " +
                       std::to_string(width) + " members (n base rows × (inputs + 2)), not " +
                       std::to_string(n_members) + ". Choose --ensemble " + std::to_string(width) + " × n, e.g. " +
                       std::to_string(width * 8) + " for 8 base rows.");
    return SaltelliDesign(d, n_members / width, 0, settings.seed);
  }

  std::vector<double>
  member_inputs(const UncertaintySettings &settings,
                const InputSampling        sampling,
                const std::uint64_t        n_members,
                const std::uint64_t        k)
  {
    if (sampling == InputSampling::saltelli)
      return member_design(settings, n_members).point(k);
    const auto          d = distributions_of(settings);
    const SobolSequence sequence(static_cast<unsigned int>(d.size()), 0, settings.seed);
    auto                x = sequence.point(k);
    for (std::size_t i = 0; i < d.size(); ++i)
      x[i] = d[i].quantile(x[i]);
    return x;
  }
} // namespace wearlink::analysis
