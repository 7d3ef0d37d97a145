#include "app/json_writer.h"

#include <gtest/gtest.h>

#include <limits>

namespace bz::app {
namespace {

TEST(JsonWriter, NestedValuesAndEscapes) {
    JsonWriter j;
    j.begin_object();
    j.field("name", "a \"quoted\"\\path\n");
    j.field("n", 3);
    j.field("x", 0.25);
    j.field("ok", true);
    j.key("list").begin_array().value(1).value("two").end_array();
    j.key("empty").begin_object().end_object();
    j.field("nan", std::numeric_limits<double>::quiet_NaN());
    j.end_object();
    EXPECT_EQ(j.str(),
              "{\n"
              "  \"name\": \"a \\\"quoted\\\"\\\\path\\u000a\",\n"
              "  \"n\": 3,\n"
              "  \"x\": 0.25,\n"
              "  \"ok\": true,\n"
              "  \"list\": [\n"
              "    1,\n"
              "    \"two\"\n"
              "  ],\n"
              "  \"empty\": {},\n"
              "  \"nan\": null\n"
              "}\n");
}

}  // namespace
}  // namespace bz::app
