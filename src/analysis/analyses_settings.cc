// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/analyses_settings.h"

namespace wearlink::analysis
{
  std::vector<std::string>
  AnalysesSettings::names() const
  {
    std::vector<std::string> out;
    if (phase_portrait)
      out.emplace_back("phase-portrait");
    if (poincare)
      out.emplace_back("poincare");
    if (lyapunov)
      out.emplace_back("lyapunov");
    return out;
  }
} // namespace wearlink::analysis
