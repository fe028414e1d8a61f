// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear checkpoint round-trips exactly (JSON, shortest round-trip doubles), and a damaged
// or missing checkpoint is an InputError naming the file.
#include "base/exceptions.h"
#include "support/test_support.h"
#include "wear/wear_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

using namespace wearlink;

namespace
{
  wear::WearState
  sample_state()
  {
    wear::WearState s;
    s.fingerprint     = "abc-12";
    s.iterations_done = 2;
    s.revolutions     = 1000.0 / 3;
    s.time            = std::sqrt(2.0);
    s.state           = Eigen::VectorXd::LinSpaced(7, -1.0 / 3, 5.0 / 7);
    s.factors         = {500, 1.0 / 7};
    s.modes           = {1, 0.123456789012345678, 0, 0};
    wear::JointWearState j;
    j.name = "A";
    std::vector<double> r(16);
    for (unsigned k = 0; k < 16; ++k)
      r[k] = 0.012 + 1e-7 * std::sin(k + 0.1);
    j.initial_bore = j.meshed_bore = Profile::round(0.012, 16);
    j.bore                         = Profile::from_samples(r);
    j.initial_pin = j.pin = j.meshed_pin = Profile::round(0.0115, 16);
    wear::IterationRecord rec;
    rec.volume_pin = 1.0 / 3e9;
    rec.depth_pin.assign(16, 1e-7 / 3);
    rec.depth_bore.assign(16, 2e-7 / 3);
    j.history = {rec, rec};
    s.joints.push_back(j);
    return s;
  }
} // namespace

TEST(Checkpoint, RoundTripIsExact)
{
  const std::string dir = wearlink::testing::fresh_directory("checkpoint_round_trip");
  const auto        s   = sample_state();
  s.write(dir + "/checkpoint.json");
  const auto r = wear::WearState::read(dir + "/checkpoint.json");
  EXPECT_EQ(r.fingerprint, s.fingerprint);
  EXPECT_EQ(r.iterations_done, s.iterations_done);
  EXPECT_EQ(r.revolutions, s.revolutions);
  EXPECT_EQ(r.time, s.time);
  ASSERT_EQ(r.state.size(), s.state.size());
  for (int i = 0; i < s.state.size(); ++i)
    EXPECT_EQ(r.state[i], s.state[i]);
  EXPECT_EQ(r.factors, s.factors);
  EXPECT_EQ(r.modes, s.modes);
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.joints[0].bore.samples(), s.joints[0].bore.samples());
  EXPECT_EQ(r.joints[0].history.size(), 2u);
  EXPECT_EQ(r.joints[0].history[1].volume_pin, s.joints[0].history[1].volume_pin);
  EXPECT_EQ(r.joints[0].history[1].depth_bore, s.joints[0].history[1].depth_bore);
}

TEST(Checkpoint, TruncatedOrMissingIsAnInputError)
{
  const std::string dir = wearlink::testing::fresh_directory("checkpoint_truncated");
  EXPECT_THROW(wear::WearState::read(dir + "/none.txt"), InputError);
  sample_state().write(dir + "/checkpoint.json");
  std::ifstream in(dir + "/checkpoint.json");
  std::string   text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir + "/cut.txt") << text.substr(0, text.size() / 2);
  try
    {
      wear::WearState::read(dir + "/cut.txt");
      FAIL() << "a truncated checkpoint was accepted";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(e.message().find("cut.txt"), std::string::npos) << e.message();
    }
}

TEST(Checkpoint, DamagedEntriesAreRefusedNamingTheEntry)
{
  const std::string dir = wearlink::testing::fresh_directory("checkpoint_damaged");
  sample_state().write(dir + "/checkpoint.json");
  std::ifstream in(dir + "/checkpoint.json");
  std::string   text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Each edit of the valid text, and the words the message must contain.
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
    {{"\"version\": 2", "\"version\": 3"}, "format version 3"},
    {{"\"name\": \"A\"", "\"name\": 7"}, "joints[0].name"},
    {{"\"iterations\": 2", "\"iterations\": -4"}, "'iterations' is not a count"},
    {{"\"fingerprint\"", "\"fingerprints\""}, "no entry 'fingerprint'"},
    {{"\"history\": [", "\"history\": [7, "}, "joints[0].history[0]"},
    {{"\"factors\": [", "\"factors\": [\"x\", "}, "'factors' holds something that is not a number"},
    {{"\"format\": \"wearlink wear checkpoint\"", "\"format\": \"other\""}, "not a wear checkpoint"},
  };
  for (const auto &[edit, expected] : cases)
    {
      const auto at = text.find(edit.first);
      ASSERT_NE(at, std::string::npos) << edit.first;
      std::string damaged = text;
      damaged.replace(at, edit.first.size(), edit.second);
      const std::string path = dir + "/damaged.json";
      std::ofstream(path) << damaged;
      try
        {
          wear::WearState::read(path);
          ADD_FAILURE() << "accepted: " << edit.second;
        }
      catch (const InputError &e)
        {
          EXPECT_NE(e.message().find(expected), std::string::npos) << e.message();
          EXPECT_NE(e.message().find(path), std::string::npos) << e.message();
        }
    }
}
