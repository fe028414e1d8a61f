// SPDX-License-Identifier: LGPL-2.1-or-later
// The JSON writer/reader used for summaries and checkpoints: a round trip keeps
// structure, order and full double precision; NaN becomes null (JSON has no NaN).
#include "base/json.h"

#include <gtest/gtest.h>

#include <cmath>

using wearlink::Json;

TEST(Json, RoundTripKeepsOrderAndPrecision)
{
  Json j = Json::object();
  j["b"] = 1.0 / 3.0;
  j["a"] = "text \"quoted\"";
  Json arr = Json::array();
  arr.push_back(1);
  arr.push_back(true);
  arr.push_back(Json());
  j["list"] = arr;
  j["nested"]["x"] = -2.5e-12;

  const Json back = Json::parse(j.dump());
  ASSERT_EQ(back.members().size(), 4u);
  EXPECT_EQ(back.members()[0].first, "b");
  EXPECT_EQ(back.at("b").as_number(), 1.0 / 3.0); // bit-exact with %.17g
  EXPECT_EQ(back.at("a").as_string(), "text \"quoted\"");
  EXPECT_EQ(back.at("list").size(), 3u);
  EXPECT_TRUE(back.at("list")[1].as_bool());
  EXPECT_EQ(back.at("nested").at("x").as_number(), -2.5e-12);
}

TEST(Json, NonFiniteNumbersAreWrittenAsNull)
{
  Json j  = Json::object();
  j["x"]  = std::nan("");
  const Json back = Json::parse(j.dump(-1));
  EXPECT_EQ(back.at("x").type(), Json::Type::null);
  EXPECT_TRUE(std::isnan(back.at("x").as_number()));
}

TEST(Json, MalformedTextThrows)
{
  EXPECT_THROW(Json::parse("{\"a\": }"), std::runtime_error);
  EXPECT_THROW(Json::parse("[1, 2"), std::runtime_error);
}
