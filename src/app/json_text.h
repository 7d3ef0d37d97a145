#pragma once
// JSON reports (bench summary.json, sweep.json, scaling.json, the difficulty table) are built
// as nlohmann::ordered_json values, so keys keep the order they were written in, and turned
// into text here: two-space indentation, a final newline, NaN and infinities as null (JSON has
// neither), and any invalid UTF-8 in a name replaced rather than thrown on.
#include <nlohmann/json.hpp>
#include <string>

namespace bz::app {

using Json = nlohmann::ordered_json;

std::string json_text(const Json& value);

}  // namespace bz::app
