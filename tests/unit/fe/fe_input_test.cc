// SPDX-License-Identifier: LGPL-2.1-or-later
// Bad input to the FE layer is a clear InputError (exit status 2 from the program), and
// nothing is meshed for it: self-intersecting or non-finite profiles, fewer than 8
// profile points, a profile in millimetres, a pin that does not fit in the bore, negative
// sizes, a --set of the load list that the chosen control does not read.
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "fe/pin_bushing_mesher.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

namespace
{

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }
} // namespace


TEST(FeInput, PinNotInsideBoreIsRejectedBeforeMeshing)
{
  auto g              = steel_pair();
  g.pin               = Profile::round(0.0121, 360);
  const long sessions = EffectLedger::instance().resources("gmsh sessions");
  const auto msg      = wearlink::testing::input_error_message(
    [&] { PinBushingModel m(g, settings_about_minus_y(1e-4, 180), mesh_file("bad_pin")); });
  EXPECT_TRUE(contains(msg, "not inside the bore")) << msg;
  EXPECT_EQ(EffectLedger::instance().resources("gmsh sessions"), sessions);
}


TEST(FeInput, NegativeOrNonFiniteSizesAreRejected)
{
  const auto g           = steel_pair();
  auto       s           = settings_about_minus_y(1e-4, 180);
  s.surface_element_size = -1e-5;
  auto msg = wearlink::testing::input_error_message([&] { PinBushingModel m(g, s, mesh_file("bad_size")); });
  EXPECT_TRUE(contains(msg, "Surface element size")) << msg;

  MeshSpecification spec;
  spec.core_radius          = 0.004;
  spec.outer_radius         = -0.024;
  spec.surface_element_size = 1e-4;
  spec.max_element_size     = 1e-3;
  spec.size_growth          = 0.3;
  msg = wearlink::testing::input_error_message([&] { check_pin_bushing_geometry(g.bore, g.pin, spec); });
  EXPECT_TRUE(contains(msg, "outer radius")) << msg;

  spec.outer_radius         = 0.024;
  spec.surface_element_size = std::numeric_limits<double>::quiet_NaN();
  msg = wearlink::testing::input_error_message([&] { check_pin_bushing_geometry(g.bore, g.pin, spec); });
  EXPECT_TRUE(contains(msg, "finite and > 0")) << msg;

  auto g2         = steel_pair();
  g2.axial_length = -0.01;
  msg             = wearlink::testing::input_error_message(
    [&] { PinBushingModel m(g2, settings_about_minus_y(1e-4, 180), mesh_file("bad_length")); });
  EXPECT_TRUE(contains(msg, "axial length")) << msg;
}


TEST(FeInput, ProfilesNeedEightFinitePositivePoints)
{
  auto msg =
    wearlink::testing::input_error_message([] { Profile::from_samples(std::vector<double>(7, 0.012), "bore"); });
  EXPECT_TRUE(contains(msg, "at least 8")) << msg;
  std::vector<double> r(16, 0.012);
  r[3] = std::numeric_limits<double>::quiet_NaN();
  msg  = wearlink::testing::input_error_message([&] { Profile::from_samples(r, "bore"); });
  EXPECT_TRUE(contains(msg, "finite")) << msg;
}


TEST(FeInput, ContactCommandRejectsBadCasesWithoutPartialOutput)
{
  const std::string dir = wearlink::testing::fresh_directory("fe_contact_invalid");
  // A bore profile whose angles turn back on themselves: self-intersecting.
  {
    std::ofstream f(dir + "/twisted.csv");
    f << "angle_rad,radius_m\n";
    for (int k = 0; k < 12; ++k)
      f << (k == 6 ? 0.5 : k * 0.5) << ",0.012\n";
  }
  // The round 12 mm bore written in millimetres.
  {
    std::ofstream f(dir + "/millimetres.csv");
    f << "angle_rad,radius_m\n";
    for (int k = 0; k < 12; ++k)
      f << k * 0.5 << ",12.0\n";
  }
  const std::string prm = wearlink::testing::source_path("params/pin_bushing.prm");
  struct Case
  {
    std::vector<std::string> set;
    std::string              expected;
  };
  const std::vector<Case> cases = {
    {{"Geometry/Bore profile file=" + dir + "/twisted.csv"}, "self-intersecting"},
    {{"Geometry/Pin radius=0.0125"}, "Pin radius"},
    {{"Geometry/Number of profile points=4"}, "Number of profile points"},
    {{"FE model/Surface element size=-1e-5"}, "Surface element size"},
    {{"Geometry/Bore profile file=" + dir + "/millimetres.csv"},
     "the profile's mean radius is 12 m, but the joint's Bore radius is 0.012 m"},
    // A list the chosen control does not read: the run used the other list (the default
    // eccentricity, the clearance itself: 0 N) and said nothing.
    {{"Loads/Control=displacement", "Loads/Load magnitudes=1"},
     "--set \"Loads/Load magnitudes=1\" has no effect: under Loads/Control = displacement the load states are "
     "Loads/Eccentricities"},
    {{"Loads/Eccentricities=1e-3"}, "under Loads/Control = force the load states are Loads/Load magnitudes"},
  };
  for (const auto &c : cases)
    {
      const std::string        out  = dir + "/out";
      std::vector<std::string> args = {"contact", prm, "--output", out};
      for (const auto &s : c.set)
        {
          args.push_back("--set");
          args.push_back(s);
        }
      const auto r = wearlink::testing::run_wearlink(args);
      EXPECT_EQ(r.exit_status, 2) << r.output;
      EXPECT_TRUE(contains(r.output, c.expected)) << r.output;
      EXPECT_TRUE(wearlink::testing::files_in(out).empty()) << "no partial output for " << c.expected;
    }
}
