// SPDX-License-Identifier: LGPL-2.1-or-later
// JSON for summaries, ledgers and checkpoint metadata (nlohmann-json's ordered_json,
// base/json.h): a round trip through writing and reading keeps structure, key order,
// full double precision and any text (non-ASCII and control characters included); NaN
// is written as null and read back as NaN; malformed text and files are refused with a
// message naming the file.
#include "base/exceptions.h"
#include "base/json.h"
#include "io/json_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using wearlink::Json;
using wearlink::json_number;

TEST(Json, RoundTripKeepsOrderAndPrecision)
{
  Json j   = Json::object();
  j["b"]   = 1.0 / 3.0;
  j["a"]   = "text \"quoted\"";
  Json arr = Json::array();
  arr.push_back(1);
  arr.push_back(true);
  arr.push_back(Json());
  j["list"]        = arr;
  j["nested"]["x"] = -2.5e-12;

  const Json back = Json::parse(j.dump(2));
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back.begin().key(), "b");              // insertion order, not alphabetical
  EXPECT_EQ(json_number(back.at("b")), 1.0 / 3.0); // bit-exact: round-trip precision
  EXPECT_EQ(back.at("a").get<std::string>(), "text \"quoted\"");
  EXPECT_EQ(back.at("list").size(), 3u);
  EXPECT_TRUE(back.at("list")[1].get<bool>());
  EXPECT_EQ(json_number(back.at("nested").at("x")), -2.5e-12);
}

TEST(Json, TextWithNonAsciiAndControlCharactersRoundTrips)
{
  // UTF-8 of several widths (2, 3 and 4 bytes), every ASCII control character, a
  // quote, a backslash and a solidus.
  std::string text = "µm, Δθ = 2π, ≤ 90°, 𝜎 ";
  for (char c = 1; c < 0x20; ++c)
    text += c;
  text += "\x7f\"\\/";
  Json j       = Json::object();
  j[text]      = text; // as a key and as a value
  j["escaped"] = Json::parse(R"("\u00b5\u0394\ud835\udf0e\n\t")").get<std::string>();

  for (const int indent : {-1, 2})
    {
      const std::string written = j.dump(indent);
      const Json        back    = Json::parse(written);
      EXPECT_EQ(back.at(text).get<std::string>(), text);
      EXPECT_EQ(back.begin().key(), text);
      // \u escapes (with a surrogate pair) decode to UTF-8, not to one byte each.
      EXPECT_EQ(back.at("escaped").get<std::string>(), "µΔ𝜎\n\t");
      if (indent < 0) // control characters are escaped: one line stays one line
        {
          EXPECT_EQ(written.find('\n'), std::string::npos);
        }
    }
}

TEST(Json, NonFiniteNumbersAreWrittenAsNullAndReadBackAsNaN)
{
  Json j          = Json::object();
  j["x"]          = std::nan("");
  j["y"]          = HUGE_VAL;
  const Json back = Json::parse(j.dump(-1));
  EXPECT_TRUE(back.at("x").is_null());
  EXPECT_TRUE(back.at("y").is_null());
  EXPECT_TRUE(std::isnan(json_number(back.at("x"))));
  EXPECT_THROW(json_number(Json("text")), Json::type_error);
}

TEST(Json, MalformedTextThrowsParseErrors)
{
  for (const char *bad : {"{\"a\": }", "[1, 2", R"("\u12G4")", R"("\ud835")", "{\"a\": 1} x", "\"\x01\""})
    EXPECT_THROW(Json::parse(bad), Json::parse_error) << bad;
}

TEST(Json, ReadingAFileNamesItWhenMissingOrMalformed)
{
  const std::string dir = wearlink::testing::fresh_directory("json_file");
  const std::string bad = dir + "/bad.json";
  std::ofstream(bad) << "{\"a\": \"\\u12G4\"}";
  try
    {
      wearlink::io::read_json_file(bad);
      FAIL() << "a malformed file was accepted";
    }
  catch (const wearlink::InputError &e)
    {
      EXPECT_NE(e.message().find(bad), std::string::npos) << e.message();
    }
  EXPECT_THROW(wearlink::io::read_json_file(dir + "/missing.json"), wearlink::InputError);
  const std::string good = dir + "/good.json";
  std::ofstream(good) << "{\"v\": 2.5, \"s\": \"Δ\"}";
  const Json j = wearlink::io::read_json_file(good);
  EXPECT_EQ(json_number(j.at("v")), 2.5);
  EXPECT_EQ(j.at("s").get<std::string>(), "Δ");
}
