// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear step: how an iteration's wear rate becomes its change of the profiles
// (Wear/Wear integration; doc/models.md, "The wear step").
//
// An iteration simulates a few cycles on the profiles of its start and stands for f
// times as many revolutions. Its rate r_n (depth per area and volumes, per unit factor)
// is therefore the rate at the start of the step, and applying f r_n is an explicit
// Euler step in revolutions: first order. Where the worn pocket draws the contact, the
// rate grows with the depth, and the deepest point lags by half a step's change of rate
// per step; a refinement study shows it as a largest depth that converges at order 1.
//
// The Adams–Bashforth step of order 2 extrapolates the rate to the middle of the step
// from the last two iterations, at no extra dynamics:
//     applied rate = (1 + ω/2) r_n − (ω/2) r_(n−1),   ω = f_n / f_(n−1),
// exact for a rate that changes linearly in revolutions. ω is taken at most 2 (a step
// that grows faster is extrapolated as if it had doubled), the first iteration is an
// Euler step, and a depth increment the extrapolation would make negative (an area the
// contact left) is cut to 0: wear never restores material. The change of rate is taken
// over the contact width (low-pass filtered there): the pocket's growth is at least
// that wide, while from one area to the next two iterations' rates differ by their
// chaotic samples. The chaotic part of the rates does not accumulate: summed over the
// iterations the combination telescopes to Σ r_n plus half a step's difference of the
// first and last rates.
#pragma once

#include "wear/wear_settings.h"
#include "wear/wear_state.h"

namespace wearlink::wear
{
  /** The largest ratio of consecutive factors the extrapolation uses [-]. */
  constexpr double max_step_ratio = 2;

  /**
   * The length over which the extrapolation's change of rate is taken (see step_rate):
   * the contact width [m] and the surfaces' mean radii [m]. A width of 0 takes it area
   * by area.
   */
  struct RateChangeScale
  {
    double contact_width = 0;
    double pin_radius    = 0;
    double bore_radius   = 0;
  };

  /**
   * The rate an iteration of factor @p f_now applies (the profiles change by @p f_now
   * times it): @p now for WearStep::euler, for the first iteration (@p before empty) or
   * after a step of factor 0; otherwise the Adams–Bashforth combination above with the
   * rate @p before of the previous iteration (factor @p f_before), every depth cut to
   * ≥ 0. The change of rate per area, (ω/2)(r_n − r_(n−1)), is low-pass filtered at
   * the contact width of @p scale (wear/wear_loop.h, low_pass; its sum is kept): the
   * rate's trend is the pocket's, at least a contact width wide, while from one area to
   * the next the two iterations' rates differ by their chaotic samples, which the
   * extrapolation would otherwise amplify by 1 + ω. The sizes of @p now and @p before
   * must agree.
   */
  WearRate
  step_rate(const WearRate        &now,
            const WearRate        &before,
            double                 f_now,
            double                 f_before,
            WearStep               scheme,
            const RateChangeScale &scale = {});
} // namespace wearlink::wear
