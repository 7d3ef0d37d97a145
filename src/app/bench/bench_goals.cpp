#include "app/bench/bench_goals.h"

namespace bz::app {

Json goals_json(const std::vector<Goal>& goals) {
    Json list = Json::array();
    for (const Goal& g : goals)
        list.push_back(Json{{"goal", g.name}, {"met", g.met}, {"measured", g.detail}});
    return list;
}

void print_goals(std::FILE* out, const std::vector<Goal>& goals, int name_width) {
    for (const Goal& g : goals) {
        std::fprintf(out, "goal %-*s %-6s %s\n", name_width, g.name.c_str(),
                     g.met ? "MET" : "MISSED", g.detail.c_str());
    }
}

}  // namespace bz::app
