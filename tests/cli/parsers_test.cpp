// Every command's parser on argument strings, without a window, a model or GL: the same code
// `beamzone` runs (and the fuzz target feeds). Each row gives the words and either a piece of
// the usage error or "" for a command line that parses.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/bench_args.h"
#include "cli/check_args.h"
#include "cli/compare_args.h"
#include "cli/difficulty_args.h"
#include "cli/play_args.h"
#include "cli/reference_args.h"
#include "cli/render_args.h"
#include "cli/replay_args.h"

namespace bz::app {
namespace {

const std::map<std::string, std::function<void(Args)>>& parsers() {
    static const std::map<std::string, std::function<void(Args)>> table = {
        {"render", [](Args a) { parse_render_args(a); }},
        {"reference", [](Args a) { parse_reference_args(a); }},
        {"bench", [](Args a) { parse_bench_args(a); }},
        {"difficulty", [](Args a) { parse_difficulty_args(a); }},
        {"replay", [](Args a) { parse_replay_args(a); }},
        {"play", [](Args a) { parse_play_options(static_cast<int>(a.size()), a.data()); }},
        {"compare", [](Args a) { parse_compare_args(a); }},
        {"check", [](Args a) { parse_check_args(a); }},
    };
    return table;
}

// The usage error of `command` on the words, or "" when it parses.
std::string error_of(const std::string& command, const std::string& words) {
    std::vector<std::string> storage;
    std::istringstream in(words);
    for (std::string w; in >> w;) storage.push_back(w == "''" ? "" : w);
    std::vector<char*> argv;
    for (std::string& w : storage) argv.push_back(w.data());
    try {
        parsers().at(command)(Args(argv.data(), argv.size()));
    } catch (const UsageError& e) {
        return e.what();
    }
    return {};
}

TEST(Parsers, EveryCommandAcceptsAndRefusesWhatItsUsageSays) {
    struct Case {
        const char* command;
        const char* words;
        const char* error;  // a piece of the message; "" parses
    };
    const Case cases[] = {
        {"render", "builtin:cube --size 64x48 --style halo --beam classic", ""},
        {"render", "builtin:cube --material-lines --svg l.svg", ""},
        {"render", "builtin:cube --intersection-lines --copies 4", ""},
        {"render", "builtin:cube --copies 4 --copy-step 0.6", ""},
        {"render", "builtin:cube --copies 4 --copy-step 0.01", "--copy-step"},
        {"render", "builtin:cube --preset turbo", "turbo"},
        {"render", "builtin:cube --beam neon", "neon"},
        {"render", "builtin:cube --line-method magic", "magic"},
        {"render", "builtin:cube --eye 0,5,0 --target 0,0,0", "cannot make a picture"},
        {"render", "builtin:cube --out a.png --mask a.png", "same file"},
        {"render", "builtin:cube --copies 10001", "--copies"},
        {"render", "", "no INPUT"},
        {"render", "builtin:cube --clears compute --prepass-raster pipeline --edge-prefilter cpu",
         ""},
        {"render", "builtin:cube --clears fast",
         "--clears: expected auto, pipeline or compute, not 'fast'"},
        {"render", "builtin:cube --edge-prefilter x",
         "--edge-prefilter: expected auto, gpu or cpu"},
        {"render", "builtin:cube --prepass-raster x", "--prepass-raster: expected auto, pipeline"},
        {"render", "builtin:cube --bloom-chain compute", ""},
        {"render", "builtin:cube --bloom-chain gpu",
         "--bloom-chain: expected auto, pipeline or compute, not 'gpu'"},
        {"reference", "--level l.toml --time 3", ""},
        {"reference", "--level l.toml --time 3 --eye 1,2,3", "only --size applies"},
        {"reference", "m.obj --crease 0", "--crease"},
        {"reference", "m.obj --material-lines", ""},
        {"reference", "m.obj --intersection-lines", ""},
        {"bench", "levels/classic.toml --sweep", ""},
        {"bench", "levels/classic.toml --sweep --preset fast", "exclude each other"},
        {"bench", "levels/classic.toml --preset turbo", "turbo"},
        {"bench", "levels/classic.toml --beam neon", "neon"},
        {"bench", "--accuracy --model x.obj", ""},
        {"bench", "levels/classic.toml --clears pipeline", ""},
        {"bench", "levels/classic.toml --clears gpu", "--clears: expected"},
        {"bench", "levels/classic.toml --sweep --clears compute", "exclude --sweep"},
        {"bench", "--accuracy --clears compute", "exclude --accuracy"},
        {"bench", "l.toml --prepass-raster compute --edge-prefilter gpu", ""},
        {"bench", "l.toml --edge-prefilter both", "--edge-prefilter: expected auto, gpu or cpu"},
        {"bench", "l.toml --sweep --prepass-raster compute", "exclude --sweep"},
        {"bench", "l.toml --bloom-chain pipeline", ""},
        {"bench", "l.toml --sweep --bloom-chain compute", "exclude --sweep"},
        {"bench", "--accuracy --bloom-chain compute", "exclude --accuracy"},
        {"bench", "--model x.obj l.toml", "--model needs --accuracy"},
        {"difficulty", "a.toml --seeds 3 --difficulty arcade --json d.json", ""},
        {"difficulty", "--difficulty hard", "hard"},
        {"difficulty", "--seconds 0", "--seconds"},
        {"replay", "r.replay --verify --inputs-only", ""},
        {"replay", "r.replay --inputs-only", "needs --verify"},
        {"replay", "--verify", "no replay FILE"},
        {"play", "levels/maze.toml --style sketch --press 2:Down,3:Return", ""},
        {"play", "--record a --replay b", "cannot be used together"},
        {"play", "--press 2:NoSuchKey", "--press"},
        {"play", "--line-method \x1b[31m", "not '\\e[31m'"},  // escaped, never raw
        {"compare", "a.png b.png --tol 2 --ink", ""},
        {"compare", "a.png", "need TEST.png and REF.png"},
        {"check", "-q a.toml -- --not-an-option.toml", ""},
        {"check", "--frobnicate a.toml", "unknown option '--frobnicate'"},
        {"check", "", "no level files given"},
    };
    for (const Case& c : cases) {
        const std::string got = error_of(c.command, c.words);
        if (std::string(c.error).empty()) {
            EXPECT_EQ(got, "") << c.command << " " << c.words;
        } else {
            EXPECT_NE(got.find(c.error), std::string::npos)
                << c.command << " " << c.words << ": " << got;
        }
    }
}

}  // namespace
}  // namespace bz::app
