#pragma once
// A benchmark's goals (targets, judged on measured numbers) and the two ways every
// bench report shows them: a JSON list and one "goal NAME MET|MISSED numbers" line each.
#include <cstdio>
#include <string>
#include <vector>

#include "app/json_text.h"

namespace bz::app {

struct Goal {
    std::string name;
    bool met = false;
    std::string detail;  // the measured numbers
};

// [{"goal": name, "met": bool, "measured": detail}, ...]
Json goals_json(const std::vector<Goal>& goals);

// One line a goal, the names left-aligned in `name_width` columns.
void print_goals(std::FILE* out, const std::vector<Goal>& goals, int name_width);

}  // namespace bz::app
