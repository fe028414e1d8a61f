// SPDX-License-Identifier: LGPL-2.1-or-later
// Files of a wear run (each written atomically; PNGs through gnuplot, io/plot.h):
//   wear_history.csv           per iteration: revolutions, factor, per joint worn volume
//                              [mm³], mass loss [mg] and largest depth [µm] per surface
//   wear_depth_<J>.csv/.png    cumulative wear depth vs body-frame angle on pin and
//                              bushing after each iteration (seed Fig 5)
//   profile_<J>_bore.png, profile_<J>_pin.png
//                              reconstructed surfaces, wear magnified by a stated factor
//                              (seed Figs 6–7); profiles_<J>.csv the radii (true scale)
//   profiles_<J>.msh           the worn bore and pin as closed gmsh curves (MSH 2.2,
//                              true scale, physical curves "bore" and "pin")
//   response_before.csv, response_after.csv, response.png
//                              acceleration of the response body before and after wear
//                              from the same initial state (seed Fig 8)
//   wear_volume.png            cumulative worn volume vs revolutions
#pragma once

#include "io/scene.h"
#include "mbs/simulation.h"
#include "wear/wear_state.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** Samples one body's position and acceleration on the dense output. */
  class ResponseRecorder : public mbs::StepObserver
  {
  public:
    ResponseRecorder(const mbs::Mechanism &mechanism, int body, double interval, double duration);
    void
    on_start(const mbs::StepContext &c) override;
    void
    on_step(const mbs::StepContext &c) override;

    void
    write_csv(const std::string &path) const;

    std::string         body_name;
    std::vector<double> t, x, y, ax, ay; ///< time from the start [s], [m], [m/s²]

  private:
    const int       body;
    const unsigned  n;
    const double    interval, duration;
    double          t_start = 0;
    Eigen::VectorXd ys, fs;
  };

  /** Index of Wear/Response body (default: the last body); InputError if unknown. */
  int
  response_body(const Scene &scene);

  void
  write_wear_history(const std::string &path, const Scene &scene, const wear::WearState &state);

  /** Every file of the list above except wear_history.csv and response_before.csv. */
  void
  write_wear_outputs(const std::string      &dir,
                     const Scene            &scene,
                     const wear::WearState  &state,
                     const ResponseRecorder &after);

  /** Write the two closed curves as a gmsh MSH 2.2 ASCII file (true scale) [m]. */
  void
  write_profiles_msh(const std::string &path, const Profile &bore, const Profile &pin);
} // namespace wearlink::io
