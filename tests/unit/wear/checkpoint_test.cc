// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear checkpoint round-trips exactly (JSON, shortest round-trip doubles), and a damaged
// or missing checkpoint is an InputError naming the file: a changed byte (checksum), a
// cut file (length), an older format version (3: no warnings), entries of the wrong type,
// sizes that do not agree with each other, and (check_shape) sizes that do not fit the
// scene. The validity warnings round-trip too (format version 5), an infinite value as well.
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
    s.fingerprint      = "abc-12";
    s.scene            = {{"Title", "A scene"}, {"Joint A/Clearance/Radial clearance", "5e-4"}};
    s.ledger           = {{"calls", {{"wear iterations", 2}, {"rhs evaluations", 123456789012}}}};
    s.timings.dynamics = 1.0 / 3;
    s.timings.total    = 7.25;
    s.iterations_done  = 2;
    s.revolutions      = 1000.0 / 3;
    s.time             = std::sqrt(2.0);
    s.state            = Eigen::VectorXd::LinSpaced(7, -1.0 / 3, 5.0 / 7);
    s.factors          = {500, 1.0 / 7};
    s.modes            = {1, 0.123456789012345678, 0, 0};
    s.warnings.check({"joint A: largest penetration", 1.0 / 3e4, 1e-5 / 3, "m", "20 % of c", "check the moduli"});
    s.warnings.check({"energy balance relative error", HUGE_VAL, 0.01, "", "", ""});
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
    j.last_rate.depth_pin.assign(16, 1e-10 / 3);
    j.last_rate.depth_bore.assign(16, 2e-10 / 7);
    j.last_rate.volume_bore = 1.0 / 3e12;
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
  EXPECT_EQ(r.joints[0].last_rate.depth_bore, s.joints[0].last_rate.depth_bore);
  EXPECT_EQ(r.joints[0].last_rate.volume_bore, s.joints[0].last_rate.volume_bore);
  EXPECT_EQ(r.scene, s.scene);
  EXPECT_EQ(r.ledger, s.ledger);
  EXPECT_EQ(r.timings.dynamics, s.timings.dynamics);
  EXPECT_EQ(r.timings.total, s.timings.total);
  ASSERT_EQ(r.warnings.warnings().size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    {
      const auto &a = r.warnings.warnings()[k], &b = s.warnings.warnings()[k];
      EXPECT_EQ(a.quantity, b.quantity);
      EXPECT_EQ(a.value, b.value);
      EXPECT_EQ(a.limit, b.limit);
      EXPECT_EQ(a.text(), b.text());
    }
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
    {{"\"version\":7", "\"version\":8"}, "format version 8, this wearlink reads version 7"},
    {{"\"version\":7", "\"version\":6"}, "format version 6, this wearlink reads version 7"},
    {{"\"quantity\": \"joint A", "\"quantity\": 4, \"x\": \"joint A"}, "'warnings[0].quantity' is not text"},
    {{"\"warnings\": [", "\"warnings\": 3, \"w\": ["}, "'warnings' is not a list"},
    {{"\"value\": \"inf\"", "\"value\": 0.001"}, "'warnings[1].value' does not exceed its limit"},
    {{"\"name\": \"A\"", "\"name\": 7"}, "joints[0].name"},
    {{"\"iterations\": 2", "\"iterations\": -4"}, "'iterations' is not a count"},
    {{"\"fingerprint\"", "\"fingerprints\""}, "no entry 'fingerprint'"},
    {{"\"history\": [", "\"history\": [7, "}, "joints[0].history[0]"},
    {{"\"factors\": [", "\"factors\": [\"x\", "}, "'factors' holds something that is not a number"},
    {{"\"format\":\"wearlink wear checkpoint\"", "\"format\":\"other\""}, "not a wear checkpoint"},
    {{"\"factors\": [", "\"factors\": [3, "}, "'factors' has 3 entries for 2 iterations"},
    {{"\"iterations\": 2", "\"iterations\": 1"}, "'factors' has 2 entries for 1 iterations"},
    {{"\"relative_revolutions\": 0.0,\n     \"depth_pin\": [", "\"relative_revolutions\": 0.0, \"depth_pin\": [0, "},
     "joints[0].history[0]' has depths of another size"},
    {{"\"timings_s\"", "\"timing\""}, "no entry 'timings_s'"},
    {{"\"depth_pin\": [", "\"depth_pin\": [0, "}, "'joints[0].last_rate' has depths of another size"},
    {{"\"wear iterations\": 2", "\"wear iterations\": 2.5"}, "'ledger.calls.wear iterations' is not a count"},
  };
  for (const auto &[edit, expected] : cases)
    {
      const auto at = text.find(edit.first);
      ASSERT_NE(at, std::string::npos) << edit.first;
      std::string damaged = text;
      damaged.replace(at, edit.first.size(), edit.second);
      damaged                = wearlink::testing::reseal_checkpoint(damaged); // past the checksum
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

namespace
{
  std::string
  refusal(const std::string &path)
  {
    return wearlink::testing::input_error_message([&] { wear::WearState::read(path); });
  }
} // namespace

// Damage that the header catches before any entry is read: one changed byte anywhere in
// the payload, a file cut short (at every tenth of its length), a file of format
// version 2 (no header line).
TEST(Checkpoint, ChangedByteTruncationAndOldVersionAreRefused)
{
  const std::string dir  = wearlink::testing::fresh_directory("checkpoint_checksum");
  const std::string path = dir + "/checkpoint.json";
  sample_state().write(path);
  const std::string text    = wearlink::testing::file_content(path);
  const auto        payload = text.find("\"payload\": ") + 11;
  for (std::size_t at = payload + 1; at + 2 < text.size(); at += 97)
    {
      std::string flipped = text;
      flipped[at]         = static_cast<char>(flipped[at] ^ 0x01);
      std::ofstream(path, std::ios::binary) << flipped;
      const std::string m = refusal(path);
      EXPECT_NE(m.find("is damaged"), std::string::npos) << "byte " << at << ": " << m;
      EXPECT_NE(m.find("Resume is refused"), std::string::npos) << m;
    }
  for (int tenth = 1; tenth < 10; ++tenth)
    {
      std::ofstream(path, std::ios::binary) << text.substr(0, text.size() * tenth / 10);
      const std::string m = refusal(path);
      EXPECT_TRUE(m.find("truncated") != std::string::npos) << tenth << "/10: " << m;
      EXPECT_NE(m.find(path), std::string::npos) << m;
    }
  std::ofstream(path, std::ios::binary) << "{\n \"format\": \"wearlink wear checkpoint\",\n \"version\": 2\n}\n";
  EXPECT_NE(refusal(path).find("format version 2, this wearlink reads version 7"), std::string::npos) << refusal(path);
}

// check_shape: each size that differs from the scene's is named with both values.
TEST(Checkpoint, SizesThatDoNotFitTheSceneAreNamed)
{
  const auto       s = sample_state();
  wear::StateShape shape;
  shape.n_state = 7;
  shape.n_modes = 4;
  shape.joints  = {{"A", 16, 16}};
  EXPECT_NO_THROW(s.check_shape(shape, "cp.json"));
  const auto message = [&](const wear::StateShape &other) {
    return wearlink::testing::input_error_message([&] { s.check_shape(other, "cp.json"); });
  };
  auto other    = shape;
  other.n_state = 9;
  EXPECT_NE(message(other).find("its state has 7 entries, the mechanism of the scene needs 9"), std::string::npos)
    << message(other);
  other                 = shape;
  other.joints[0].n_pin = 32;
  EXPECT_NE(message(other).find("16 (pin) samples, the scene's 16 and 32"), std::string::npos) << message(other);
  other                = shape;
  other.joints[0].name = "B";
  EXPECT_NE(message(other).find("is 'A', the scene's is 'B'"), std::string::npos) << message(other);
  other         = shape;
  other.n_modes = 2;
  EXPECT_NE(message(other).find("contact modes of 2 clearance joints, the scene has 1"), std::string::npos)
    << message(other);
}
