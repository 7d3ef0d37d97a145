#pragma once
// Small, strict parsers for command-line values. Each throws UsageError with a message that
// names the option and what was expected.
#include <glm/glm.hpp>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/text/printable.h"
#include "render/settings.h"
#include "scene/style.h"

namespace bz::app {

using Args = std::span<char* const>;  // arguments after the subcommand name

class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

double parse_number(std::string_view option, std::string_view text);
int parse_int(std::string_view option, std::string_view text, int min_value, int max_value);
glm::dvec3 parse_vec3(std::string_view option, std::string_view text);     // "x,y,z"
glm::ivec2 parse_size(std::string_view option, std::string_view text);     // "WxH"
scene::Style parse_style(std::string_view option, std::string_view text);  // a style name

// One of an option's named values: parse_choice("--clears", text, {{"auto", A}, {"pipeline",
// P}}) returns A for "auto" and throws UsageError("--clears: expected auto or pipeline, not
// 'x'") for anything else.
template <typename T>
struct Choice {
    std::string_view name;
    T value;
};
std::string choice_list(std::span<const std::string_view> names);  // "a, b or c"
template <typename T>
T parse_choice(std::string_view option, std::string_view text,
               std::initializer_list<Choice<T>> choices);

// The renderer's switches that `render` and `bench` share: --clears auto|pipeline|compute,
// --prepass-raster auto|pipeline|compute, --edge-prefilter auto|gpu|cpu and
// --bloom-chain auto|pipeline|compute.
render::ColourClears parse_colour_clears(std::string_view option, std::string_view text);
render::BloomChain parse_bloom_chain(std::string_view option, std::string_view text);
render::PrepassRaster parse_prepass_raster(std::string_view option, std::string_view text);
render::EdgePrefilter parse_edge_prefilter(std::string_view option, std::string_view text);

// Whether a command-line word is an option name ("--out", "-h") rather than a value; a
// negative number ("-2", "-0.5,1,0") is a value.
bool looks_like_option(std::string_view word);

// Walks argv: `value()` takes the value of the current option or throws UsageError. A value
// that is missing, empty or another option is refused, so `--mask --out x` cannot write a
// file named "--out".
class ArgCursor {
  public:
    ArgCursor(int count, char* const* args) : count_(count), args_(args) {}
    bool done() const { return index_ >= count_; }
    std::string_view next() { return args_[index_++]; }
    std::string_view value(std::string_view option);

  private:
    int count_;
    char* const* args_;
    int index_ = 0;
};

template <typename T>
T parse_choice(std::string_view option, std::string_view text,
               std::initializer_list<Choice<T>> choices) {
    std::vector<std::string_view> names;
    for (const Choice<T>& c : choices) {
        if (c.name == text) return c.value;
        names.push_back(c.name);
    }
    throw UsageError(std::string(option) + ": expected " + choice_list(names) + ", not '" +
                     printable(text) + "'");
}

}  // namespace bz::app
