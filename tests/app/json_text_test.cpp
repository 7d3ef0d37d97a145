#include "app/json_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace bz::app {
namespace {

TEST(JsonText, KeepsKeyOrderEscapesAndNullsNonFiniteNumbers) {
    Json j = Json::object();
    j["name"] = "a \"quoted\"\\path\n";
    j["n"] = 3;
    j["x"] = 0.25;
    j["ok"] = true;
    j["list"] = Json::array({1, "two"});
    j["empty"] = Json::object();
    j["nan"] = std::numeric_limits<double>::quiet_NaN();
    j["inf"] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(json_text(j),
              "{\n"
              "  \"name\": \"a \\\"quoted\\\"\\\\path\\n\",\n"
              "  \"n\": 3,\n"
              "  \"x\": 0.25,\n"
              "  \"ok\": true,\n"
              "  \"list\": [\n"
              "    1,\n"
              "    \"two\"\n"
              "  ],\n"
              "  \"empty\": {},\n"
              "  \"nan\": null,\n"
              "  \"inf\": null\n"
              "}\n");
    // What it writes reads back.
    const Json back = Json::parse(json_text(j));
    EXPECT_EQ(back["name"], j["name"]);
    EXPECT_TRUE(back["nan"].is_null());
}

TEST(JsonText, InvalidUtf8IsReplacedNotThrown) {
    Json j = Json::object();
    j["level"] = std::string("bad \xff name");
    std::string text;
    ASSERT_NO_THROW(text = json_text(j));
    EXPECT_NE(text.find("bad \xEF\xBF\xBD name"), std::string::npos) << text;
}

}  // namespace
}  // namespace bz::app
